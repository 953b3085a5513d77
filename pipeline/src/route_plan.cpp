// The route as a wear step solves it: its running conditions (curves, transitions at their
// midpoints, the pieces' starting states), its time-domain pieces, both ways, and the checks
// that every condition has a balance to solve.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"

namespace wheelwear::pipeline {

namespace {

// What makes two running conditions the same.
using CaseKey = std::tuple<double, double, double, double, double, double, bool>;

CaseKey case_key(const RouteCase& c) {
  const vehicle::SteadyCurve& curve = c.curve;
  return {curve.running.curve_radius,
          curve.cant,
          curve.running.speed,
          curve.running.friction,
          curve.running.friction_flange.value_or(curve.running.friction),
          curve.traction,
          c.reversed};
}

std::string case_label(const vehicle::RouteSection& section, std::size_t index,
                       const vehicle::TrackPoint& point) {
  if (!section.name.empty()) return section.name;
  char text[96];
  std::snprintf(text, sizeof text, "section %zu, %s, R %.0f m", index + 1,
                std::string(vehicle::section_kind_name(section.kind)).c_str(), point.radius_m);
  return text;
}

// The running condition of the track at `point`, at `speed`.
vehicle::SteadyCurve condition_at(const vehicle::TrackPoint& point, double speed) {
  vehicle::SteadyCurve curve;
  curve.running.speed = speed;
  curve.running.curve_radius = point.radius_m;
  curve.running.friction = point.friction_top;
  curve.running.friction_flange = point.friction_flange;
  curve.cant = point.cant_m;
  curve.traction = point.traction_N;
  return curve;
}

// Adds `c` to `cases`, or its share to the case of the same condition already there (which takes
// its label if it was only a piece's start). Returns the case's index.
std::size_t add_case(std::vector<RouteCase>& cases, RouteCase c) {
  const CaseKey key = case_key(c);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (case_key(cases[k]) != key) continue;
    if (cases[k].share == 0.0 && c.share > 0.0) cases[k].label = std::move(c.label);
    cases[k].share += c.share;
    return k;
  }
  cases.push_back(std::move(c));
  return cases.size() - 1;
}

// The quasi-static case of section `i`: a constant section is the same everywhere, a
// transition is taken at its midpoint.
RouteCase section_case(const vehicle::Route& route, std::size_t i, double start, double total) {
  const vehicle::RouteSection& section = route.sections[i];
  const vehicle::TrackPoint point = vehicle::track_at(route, start + 0.5 * section.length_m);
  return {case_label(section, i, point), condition_at(point, point.speed_m_s),
          section.length_m / total};
}

}  // namespace

std::vector<RouteCase> route_cases(const vehicle::Route& route) {
  const std::vector<double> starts = route.section_starts();
  const double total = route.total_length();
  std::vector<RouteCase> cases;
  for (std::size_t i = 0; i < route.sections.size(); ++i)
    add_case(cases, section_case(route, i, starts[i], total));
  return cases;
}

RoutePlan route_plan(const vehicle::Route& route, const TimeDomainKeys& time_domain,
                     const vehicle::Vehicle& vehicle) {
  if (!time_domain.enabled) return {route_cases(route), {}};
  require(std::isfinite(time_domain.tangent_length) && time_domain.tangent_length > 0.0,
          "[time_domain] tangent_length_m", time_domain.tangent_length, "must be positive (m)");
  require(std::isfinite(time_domain.run_in) && time_domain.run_in >= 0.0, "[time_domain] run_in_m",
          time_domain.run_in, "must not be negative (m)");
  require(std::isfinite(time_domain.sample_distance) && time_domain.sample_distance > 0.0,
          "[time_domain] sample_distance_m", time_domain.sample_distance, "must be positive (m)");
  const std::vector<double> starts = route.section_starts();
  const double total = route.total_length();
  // The leading and the trailing wheelset's places ahead of the car body's centre.
  const double lead = vehicle.wheelset_x(0), trail = vehicle.wheelset_x(vehicle::kWheelsets - 1);
  RoutePlan plan;
  for (std::size_t i = 0; i < route.sections.size(); ++i) {
    const vehicle::RouteSection& section = route.sections[i];
    if (section.kind == vehicle::SectionKind::curve ||
        (section.kind == vehicle::SectionKind::transition && !time_domain.simulate_transitions)) {
      add_case(plan.cases, section_case(route, i, starts[i], total));
      continue;
    }
    DynamicPiece piece;
    piece.section = i;
    // A tangent is a stationary random track: a stretch at its middle, away from the
    // transitions (simulated themselves), stands for all of it.
    piece.length_m = section.kind == vehicle::SectionKind::tangent
                         ? std::min(section.length_m, time_domain.tangent_length)
                         : section.length_m;
    piece.start_m = starts[i] + 0.5 * (section.length_m - piece.length_m);
    piece.share = section.length_m / total;
    piece.speed = section.speed_m_s;
    piece.seed = vehicle::seed_for_section(time_domain.seed, i);
    // Before the route's start (a piece at its very start) the track is its first section's.
    piece.sim_start_m = piece.start_m - lead;
    piece.sim_length_m = piece.length_m + lead - trail;
    const vehicle::TrackPoint start_point =
        vehicle::track_at(route, std::max(0.0, piece.sim_start_m - time_domain.run_in));
    piece.tangent = section.kind == vehicle::SectionKind::tangent;
    piece.label =
        case_label(section, i, vehicle::track_at(route, piece.start_m + 0.5 * piece.length_m));
    piece.start_case = add_case(
        plan.cases, {"start of " + piece.label, condition_at(start_point, piece.speed), 0.0});
    plan.pieces.push_back(std::move(piece));
  }
  return plan;
}
RunningWay running_way(const VehicleRun& run, bool reversed) {
  if (!reversed) return {run.route, run.time_domain, run.vehicle};
  RunningWay way{vehicle::reversed(run.route), run.time_domain, run.vehicle};
  std::reverse(way.vehicle.powered.begin(), way.vehicle.powered.end());
  if (run.time_domain.irregularities == IrregularitySource::file)
    way.time_domain.measured =
        vehicle::reversed(run.time_domain.measured, run.route.total_length());
  return way;
}

RoutePlan route_plan(const VehicleRun& run) {
  const bool forward = run.direction != RunningDirection::reverse;
  const bool backward = run.direction != RunningDirection::forward;
  const double part = forward && backward ? 0.5 : 1.0;
  RoutePlan plan;
  if (forward) plan = route_plan(run.route, run.time_domain, run.vehicle);
  if (!backward) return plan;
  const RunningWay way = running_way(run, true);
  RoutePlan back = route_plan(way.route, way.time_domain, way.vehicle);
  for (RouteCase& c : plan.cases) c.share *= part;
  for (DynamicPiece& p : plan.pieces) p.share *= part;
  const std::size_t first_case = plan.cases.size();
  for (RouteCase& c : back.cases) {
    c.share *= part;
    c.reversed = true;
    // Its name is the route's, written for the forward way: say which hand the curve is now.
    const double radius = c.curve.running.curve_radius;
    c.label = "backwards, " + c.label +
              (radius > 0.0   ? " (right-hand this way)"
               : radius < 0.0 ? " (left-hand this way)"
                              : "");
    plan.cases.push_back(std::move(c));
  }
  const std::size_t sections = run.route.sections.size();
  for (DynamicPiece& p : back.pieces) {
    p.share *= part;
    p.reversed = true;
    p.label = "backwards, " + p.label;
    p.start_case += first_case;
    p.seed = vehicle::seed_for_section(run.time_domain.seed, sections + p.section);
    plan.pieces.push_back(std::move(p));
  }
  return plan;
}

void redraw_pieces(std::vector<DynamicPiece>& pieces, const VehicleRun& run, std::uint64_t draw) {
  const std::uint64_t sections = run.route.sections.size();
  for (DynamicPiece& p : pieces)
    p.seed = vehicle::seed_for_section(
        run.time_domain.seed, draw * 2 * sections + (p.reversed ? sections : 0) + p.section);
}

void require_upright_route(const VehicleRun& run, double lateral_arm) {
  // Every condition the run solves (curves, transitions, the pieces' starting states; both
  // ways), each at its own speed and traction.
  // (The wheel loads of the centred vehicle are alike for every wheelset, so either way's
  // order of the wheelsets gives the same.)
  for (const RouteCase& c : route_plan(run).cases) {
    try {
      vehicle::require_upright(run.vehicle, c.curve, lateral_arm);
      vehicle::require_adhesion(run.vehicle, c.curve, lateral_arm);
    } catch (const InputError& e) {
      throw InputError("route condition \"" + c.label + "\": " + e.what());
    }
  }
}

}  // namespace wheelwear::pipeline
