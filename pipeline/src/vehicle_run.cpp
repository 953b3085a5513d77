#include "wheelwear/pipeline/vehicle_run.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/vehicle/vehicle_stability.hpp"

namespace wheelwear::pipeline {

namespace {

using Models = RouteSolver::Models;

// The linear critical speed of `way`'s vehicle with `models`, the contacts its dynamics uses,
// into out.critical_speed and out.critical_speed_note; searched from the previous solve's where
// it was found (the profiles change little between solves: the crossing nearest it), to 0.1 %
// (the table's interpolation moves it by more, docs/vehicle.md). A search that fails (no steady
// state on tangent track at some speed) leaves NaN and says why, and does not stop the run.
void find_critical_speed(const RunningWay& way, const Models& models,
                         const VehicleCollective* previous, VehicleCollective& out) {
  vehicle::VehicleStabilityOptions options;
  options.speed_step = 5.0;
  options.tolerance = 1e-3;
  if (previous && std::isfinite(previous->critical_speed)) {
    options.start_speed = previous->critical_speed;
    options.speed_step = 2.0;
  }
  try {
    const vehicle::CriticalSpeed c = vehicle::vehicle_critical_speed(way.vehicle, models, options);
    if (c.found) {
      out.critical_speed = c.speed;
      out.critical_speed_note = options.start_speed > 0.0 ? "the crossing nearest the last solve's"
                                                          : "the lowest crossing from 5 m/s";
    } else {
      out.critical_speed_note = "none found between " + core::format_number(options.speed_step) +
                                " and 100 m/s (stable up to 100 m/s, or unstable at the lowest)";
    }
  } catch (const InputError& e) {
    out.critical_speed_note = std::string("not found: ") + e.what();
  }
}

// The index of physical wheelset j's wheel on `side` (0 left, 1 right) among `count` worn
// profiles (ProfileLayout's order).
std::size_t profile_index(std::size_t count, std::size_t j, std::size_t side) {
  if (count == 1) return 0;
  if (count == 2) return side;
  return 2 * j + side;
}

// The profiles (left, right in travel) of the wheelset k in order of travel, running forwards
// or backwards (the physical wheelset 3 - k, its sides swapped).
std::array<std::size_t, 2> travel_profiles(std::size_t count, std::size_t k, bool reversed) {
  const std::size_t j = reversed ? vehicle::kWheelsets - 1 - k : k;
  return {profile_index(count, j, reversed ? 1 : 0), profile_index(count, j, reversed ? 0 : 1)};
}

// The models of both directions (a direction the run does not take gets the other's); each
// distinct pair of profiles gets one contact table, built in parallel.
std::array<Models, 2> direction_models(const VehicleRun& run, const StateKernel& kernel,
                                       const std::vector<const profiles::Profile*>& wheels) {
  constexpr auto kSets = static_cast<std::size_t>(vehicle::kWheelsets);
  std::vector<std::array<std::size_t, 2>> pairs;
  std::array<std::array<std::size_t, kSets>, 2> pair_of{};
  const std::array<bool, 2> taken{run.direction != RunningDirection::reverse,
                                  run.direction != RunningDirection::forward};
  for (std::size_t d = 0; d < 2; ++d) {
    if (!taken[d]) continue;
    for (std::size_t k = 0; k < kSets; ++k) {
      const std::array<std::size_t, 2> pair = travel_profiles(wheels.size(), k, d == 1);
      const auto it = std::find(pairs.begin(), pairs.end(), pair);
      pair_of[d][k] = static_cast<std::size_t>(it - pairs.begin());
      if (it == pairs.end()) pairs.push_back(pair);
    }
  }
  std::vector<std::optional<vehicle::WheelsetModel>> distinct(pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    vehicle::WheelsetModel model =
        wheelset_model(kernel, *wheels[pairs[i][0]], *wheels[pairs[i][1]]);
    if (run.contact_table) model.table = contact_table(model, run.vehicle);
    distinct[i] = std::move(model);
  });
  const auto models = [&](std::size_t d) {
    const auto& p = pair_of[taken[d] ? d : 1 - d];
    return Models{*distinct[p[0]], *distinct[p[1]], *distinct[p[2]], *distinct[p[3]]};
  };
  return {models(0), models(1)};
}

// Solves every case of `out` (from `previous`'s solutions where given) into out.curving, and adds
// the worn cases' states to out.states.
void solve_cases(const RouteSolver& solver, const VehicleCollective* previous,
                 RouteExecutor& execute, VehicleCollective& out) {
  std::vector<CaseTask> tasks;
  for (std::size_t i = 0; i < out.cases.size(); ++i) {
    tasks.push_back({i, std::nullopt});
    if (previous) {
      tasks.back().start = vehicle::placement_of(previous->curving[i]);
      // A condition that took many iterations on the earlier profiles likely does again.
      tasks.back().cost = 1.0 + previous->curving[i].iterations;
    }
  }
  out.curving = execute.cases(solver, tasks);
  require(out.curving.size() == out.cases.size(), "solved cases",
          static_cast<double>(out.curving.size()), "one per case");
  const std::vector<int> worn = solver.worn_wheelsets();
  for (std::size_t i = 0; i < out.cases.size(); ++i) {
    // A warm start that fails keeps the converged solution it started from.
    if (previous && !out.curving[i].converged && previous->curving[i].converged) {
      out.curving[i] = previous->curving[i];
      ++out.kept;
    }
    if (!out.curving[i].converged) ++out.unconverged;
    if (out.cases[i].share == 0.0) continue;  // only starts a piece
    const double weight = out.cases[i].share / static_cast<double>(worn.size());
    for (int k : worn)
      out.states.push_back(wheelset_state(out.cases[i], out.curving[i], k, weight));
  }
}

// Simulates every piece of `out` from its start case's solution, and appends their states to
// out.states in the pieces' order.
void simulate_pieces(const RouteSolver& solver, RouteExecutor& execute, VehicleCollective& out) {
  std::vector<PieceTask> tasks;
  for (std::size_t p = 0; p < out.pieces.size(); ++p) {
    const std::size_t c = out.pieces[p].start_case;
    // Its cost: the time simulated.
    tasks.push_back({p, vehicle::placement_of(out.curving[c]),
                     start_states(out.cases[c], out.curving[c]),
                     out.pieces[p].sim_length_m / out.pieces[p].speed});
  }
  std::vector<PieceOutcome> simulated = execute.pieces(solver, tasks);
  require(simulated.size() == tasks.size(), "simulated pieces",
          static_cast<double>(simulated.size()), "one per piece");
  out.piece_runs.resize(out.pieces.size());
  for (std::size_t p = 0; p < simulated.size(); ++p) {
    out.piece_runs[p] = std::move(simulated[p].run);
    for (WheelsetStateSpec& s : simulated[p].states) out.states.push_back(std::move(s));
  }
}

// `wheels` where a vehicle can wear them; InputError otherwise.
const std::vector<const profiles::Profile*>& checked_wheels(
    const std::vector<const profiles::Profile*>& wheels) {
  require(wheels.size() == 1 || wheels.size() == 2 || wheels.size() == 2 * vehicle::kWheelsets,
          "worn wheel profiles", static_cast<double>(wheels.size()),
          "give one (shared), two (left, right) or eight (left and right of each wheelset)");
  return wheels;
}

}  // namespace

int VehicleCollective::incomplete() const {
  return static_cast<int>(std::count_if(piece_runs.begin(), piece_runs.end(),
                                        [](const PieceRun& r) { return !r.completed; }));
}

std::vector<int> VehicleRun::worn_wheelsets() const {
  if (wheelsets == WheelsetSelection::leading) return {0, 2};
  return {0, 1, 2, 3};
}

void mark_wheelset(WheelsetStateSpec& state, int k, bool reversed) {
  state.wheelset = reversed ? vehicle::kWheelsets - 1 - k : k;
  state.reversed = reversed;
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
  model.slip_point = kernel.scene().slip_point;
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

WheelsetStateSpec motion_state(const vehicle::WheelsetMotionState& state,
                               const vehicle::WheelsetForces& forces,
                               const vehicle::RunningConditions& running, std::string label,
                               double weight) {
  WheelsetStateSpec s;
  s.label = std::move(label);
  s.dy = state.dy;
  s.yaw = state.yaw;
  // The vertical forces the contact was solved for (Q less the creep forces' vertical part):
  // the kernel then meets the very contact the vehicle's balance used.
  s.load_left = forces.contact.left.vertical_force;
  s.load_right = forces.contact.right.vertical_force;
  s.speed = running.speed;
  s.curve_radius = running.curve_radius;
  s.angular_velocity = state.spin;
  s.yaw_rate = state.yaw_rate;
  s.lateral_velocity = state.lateral_velocity;
  s.roll = forces.contact.roll;
  s.friction = running.friction;
  s.friction_flange = running.rail_friction().flange;
  s.weight = weight;
  return s;
}

WheelsetStateSpec wheelset_state(const RouteCase& route_case,
                                 const vehicle::VehicleCurving& curving, int k, double weight) {
  const vehicle::CurvingWheelset& w = curving.wheelsets[static_cast<std::size_t>(k)];
  WheelsetStateSpec s =
      motion_state(w.state, w.forces, route_case.curve.running,
                   route_case.label + ", wheelset " + std::to_string(k + 1), weight);
  mark_wheelset(s, k, route_case.reversed);
  return s;
}

RouteSolver::RouteSolver(const VehicleRun& run, const StateKernel& kernel,
                         const std::vector<const profiles::Profile*>& wheels, std::uint64_t draw)
    : plan_(route_plan(run)),
      worn_(run.worn_wheelsets()),
      models_(direction_models(run, kernel, checked_wheels(wheels))) {
  if (run.time_domain.redraw) redraw_pieces(plan_.pieces, run, draw);
  ways_[0] = running_way(run, false);
  if (run.direction != RunningDirection::forward) ways_[1] = running_way(run, true);
  // A direction the run does not take holds the other's models: no tables of its own.
  const std::array<bool, 2> taken{run.direction != RunningDirection::reverse,
                                  run.direction != RunningDirection::forward};
  for (std::size_t d = 0; d < 2; ++d)
    for (std::size_t k = 0; taken[d] && k < models_[d].size(); ++k)
      if (models_[d][k].table)
        tables_.emplace(travel_profiles(wheels.size(), k, d == 1), models_[d][k].table);
}

const RunningWay& RouteSolver::way(bool reversed) const {
  return reversed && ways_[1] ? *ways_[1] : *ways_[0];
}

PieceOutcome RouteSolver::simulate(const PieceTask& task) const {
  const DynamicPiece& piece = plan_.pieces.at(task.piece);
  const RunningWay& way = this->way(piece.reversed);
  vehicle::VehicleMotionOptions options;
  options.run_in = way.time_domain.run_in;
  options.sample_distance = way.time_domain.sample_distance;
  options.speed = piece.speed;
  const vehicle::VehicleMotion motion = vehicle::simulate_vehicle(
      way.vehicle, models(piece.reversed), way.route, piece.sim_start_m, piece.sim_length_m,
      piece_irregularities(piece, way.time_domain, way.vehicle), task.start, options);
  PieceOutcome out;
  out.states = piece_states(piece, motion, task.start_states, worn_, out.run);
  return out;
}

vehicle::VehicleCurving RouteSolver::solve(const CaseTask& task) const {
  const RouteCase& route_case = plan_.cases.at(task.index);
  vehicle::CurvingOptions options;
  if (task.start) {
    options.start = task.start;
    // A fresh solve (continuation from tangent track) costs the most and rarely succeeds
    // where the warm start fails on the slightly worn profiles.
    options.restart_on_failure = false;
    // A warm start that converges takes 2-16 iterations (once 39 over a 10^5 km run); a stall
    // spent all 60, 40 % of the run's time, before it kept the earlier balance anyway.
    options.max_iterations = 20;
  }
  try {
    return vehicle::solve_vehicle_curving(way(route_case.reversed).vehicle,
                                          models(route_case.reversed), route_case.curve, options);
  } catch (const InputError& e) {
    throw InputError("route condition \"" + route_case.label + "\": " + e.what());
  }
}

std::vector<vehicle::VehicleCurving> RouteExecutor::cases(const RouteSolver& solver,
                                                          const std::vector<CaseTask>& tasks) {
  std::vector<vehicle::VehicleCurving> out(tasks.size());
  tbb::parallel_for(std::size_t{0}, tasks.size(),
                    [&](std::size_t t) { out[t] = solver.solve(tasks[t]); });
  return out;
}

std::vector<PieceOutcome> RouteExecutor::pieces(const RouteSolver& solver,
                                                const std::vector<PieceTask>& tasks) {
  std::vector<PieceOutcome> out(tasks.size());
  tbb::parallel_for(std::size_t{0}, tasks.size(),
                    [&](std::size_t t) { out[t] = solver.simulate(tasks[t]); });
  return out;
}

VehicleCollective solve_vehicle_collective(const VehicleRun& run, const StateKernel& kernel,
                                           const std::vector<const profiles::Profile*>& wheels,
                                           const VehicleCollective* previous, std::uint64_t draw,
                                           RouteExecutor* executor) {
  RouteExecutor here;
  RouteExecutor& execute = executor ? *executor : here;
  const RouteSolver solver(run, kernel, wheels, draw);
  VehicleCollective out;
  out.cases = solver.plan().cases;
  out.pieces = solver.plan().pieces;
  if (previous)
    require(previous->curving.size() == out.cases.size(), "previous solution's cases",
            static_cast<double>(previous->curving.size()), "must be the route's");
  // The critical speed's search (serial) beside the cases and the pieces (parallel), which stay
  // on this thread: an executor spreading them over processes talks to them from here.
  tbb::task_group critical_speed;
  critical_speed.run([&] {
    // The vehicle as it runs: backwards only, the physical wheelset 4 leads.
    const bool reversed = run.direction == RunningDirection::reverse;
    if (run.critical_speed)
      find_critical_speed(solver.way(reversed), solver.models(reversed), previous, out);
  });
  try {
    solve_cases(solver, previous, execute, out);
    simulate_pieces(solver, execute, out);
  } catch (...) {
    critical_speed.wait();
    throw;
  }
  critical_speed.wait();
  out.contact_tables = solver.contact_tables();
  return out;
}

}  // namespace wheelwear::pipeline
