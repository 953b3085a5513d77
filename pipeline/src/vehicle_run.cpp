#include "wheelwear/pipeline/vehicle_run.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {

namespace {

// What makes two running conditions the same.
using CaseKey = std::tuple<double, double, double, double, double>;

CaseKey case_key(const vehicle::SteadyCurve& c) {
  return {c.running.curve_radius, c.cant, c.running.speed, c.running.friction,
          c.running.friction_flange.value_or(c.running.friction)};
}

std::string case_label(const vehicle::RouteSection& section, std::size_t index,
                       const vehicle::TrackPoint& point) {
  if (!section.name.empty()) return section.name;
  char text[96];
  std::snprintf(text, sizeof text, "section %zu, %s, R %.0f m", index + 1,
                std::string(vehicle::section_kind_name(section.kind)).c_str(), point.radius_m);
  return text;
}

}  // namespace

std::vector<int> VehicleRun::worn_wheelsets() const {
  if (wheelsets == WheelsetSelection::leading) return {0, 2};
  return {0, 1, 2, 3};
}

std::vector<RouteCase> route_cases(const vehicle::Route& route) {
  const std::vector<double> starts = route.section_starts();
  const double total = route.total_length();
  std::vector<RouteCase> cases;
  std::vector<CaseKey> keys;
  for (std::size_t i = 0; i < route.sections.size(); ++i) {
    const vehicle::RouteSection& section = route.sections[i];
    // A constant section is the same everywhere; a transition is taken at its midpoint.
    const vehicle::TrackPoint point = vehicle::track_at(route, starts[i] + 0.5 * section.length_m);
    RouteCase c;
    c.curve.running.speed = point.speed_m_s;
    c.curve.running.curve_radius = point.radius_m;
    c.curve.running.friction = point.friction_top;
    c.curve.running.friction_flange = point.friction_flange;
    c.curve.cant = point.cant_m;
    c.share = section.length_m / total;
    const CaseKey key = case_key(c.curve);
    std::size_t k = 0;
    while (k < keys.size() && keys[k] != key) ++k;
    if (k < keys.size()) {
      cases[k].share += c.share;
      continue;
    }
    c.label = case_label(section, i, point);
    keys.push_back(key);
    cases.push_back(std::move(c));
  }
  return cases;
}

vehicle::WheelsetModel wheelset_model(const StateKernel& kernel, const profiles::Profile& left,
                                      const profiles::Profile& right) {
  vehicle::WheelsetModel model{{kernel.pair(left), kernel.pair(right)}};
  model.contact = kernel.contact_options();
  model.method = kernel.method();
  model.solve = kernel.solve_options();
  model.solve.fastsim.cell_fields = false;  // the vehicle needs the forces only
  model.material = kernel.material();
  model.lateral_arm = kernel.scene().lateral_arm;
  return model;
}

std::shared_ptr<const contactgeom::WheelsetContactTable> contact_table(
    const vehicle::WheelsetModel& model, const vehicle::Vehicle& vehicle) {
  // Loads from a quarter of the static wheel load to three times it: beyond the quasi-static
  // range of every curve (Y/Q and the unloading of the inner wheel) without wasting levels.
  const double static_load = vehicle.mass() * vehicle::kGravity / (2.0 * vehicle::kWheelsets);
  contactgeom::WheelsetTableOptions grid;
  grid.load_min = 0.25 * static_load;
  grid.load_max = 3.0 * static_load;
  return std::make_shared<const contactgeom::WheelsetContactTable>(model.track, model.contact,
                                                                   grid);
}

WheelsetStateSpec wheelset_state(const RouteCase& route_case,
                                 const vehicle::VehicleCurving& curving, int k, double weight) {
  const vehicle::CurvingWheelset& w = curving.wheelsets[static_cast<std::size_t>(k)];
  const vehicle::RunningConditions& running = route_case.curve.running;
  WheelsetStateSpec s;
  s.label = route_case.label + ", wheelset " + std::to_string(k + 1);
  s.dy = w.state.dy;
  s.yaw = w.state.yaw;
  // The vertical forces the contact was solved for (Q less the creep forces' vertical part):
  // the kernel then meets the very contact the vehicle's balance used.
  s.load_left = w.forces.contact.left.vertical_force;
  s.load_right = w.forces.contact.right.vertical_force;
  s.speed = running.speed;
  s.curve_radius = running.curve_radius;
  s.angular_velocity = w.state.spin;
  s.yaw_rate = w.state.yaw_rate;
  s.lateral_velocity = w.state.lateral_velocity;
  s.roll = w.forces.contact.roll;
  s.friction = running.friction;
  s.friction_flange = running.rail_friction().flange;
  s.weight = weight;
  return s;
}

VehicleCollective solve_vehicle_collective(const VehicleRun& run, const StateKernel& kernel,
                                           const std::vector<const profiles::Profile*>& wheels,
                                           const VehicleCollective* previous) {
  require(wheels.size() == 1 || wheels.size() == 2, "worn wheel profiles",
          static_cast<double>(wheels.size()), "give one (shared) or two (left, right)");
  VehicleCollective out;
  out.cases = route_cases(run.route);
  if (previous)
    require(previous->curving.size() == out.cases.size(), "previous solution's cases",
            static_cast<double>(previous->curving.size()), "must be the route's");
  vehicle::WheelsetModel model = wheelset_model(kernel, *wheels.front(), *wheels.back());
  if (run.contact_table) model.table = contact_table(model, run.vehicle);
  const std::array<vehicle::WheelsetModel, vehicle::kWheelsets> models{model, model, model, model};
  out.curving.resize(out.cases.size());
  std::vector<int> kept(out.cases.size(), 0);
  tbb::parallel_for(std::size_t{0}, out.cases.size(), [&](std::size_t i) {
    vehicle::CurvingOptions options;
    if (previous) {
      options.start = vehicle::placement_of(previous->curving[i]);
      // A fresh solve (continuation from tangent track) costs the most and rarely succeeds
      // where the warm start fails on the slightly worn profiles.
      options.restart_on_failure = false;
    }
    out.curving[i] =
        vehicle::solve_vehicle_curving(run.vehicle, models, out.cases[i].curve, options);
    if (previous && !out.curving[i].converged && previous->curving[i].converged) {
      out.curving[i] = previous->curving[i];
      kept[i] = 1;
    }
  });
  const std::vector<int> worn = run.worn_wheelsets();
  for (std::size_t i = 0; i < out.cases.size(); ++i) {
    if (!out.curving[i].converged) ++out.unconverged;
    out.kept += kept[i];
    const double weight = out.cases[i].share / static_cast<double>(worn.size());
    for (int k : worn)
      out.states.push_back(wheelset_state(out.cases[i], out.curving[i], k, weight));
  }
  return out;
}

}  // namespace wheelwear::pipeline
