#pragma once
/// A run's load collective from the vehicle itself, on the current wheel profiles: the scene's
/// vehicle solved quasi-statically in the route's constant curves and simulated in time, with
/// the track's irregularities, through its tangents and transitions; each wheelset's states
/// become states of the collective (position, yaw, rates, spin, loads and friction), weighted by
/// the share of the route they stand for. Manual: docs/vehicle.md, "In the run".
///
/// Quasi-statically, the route is reduced to its running conditions: every constant curve as it
/// is (and, without the time domain, every tangent, and every transition at its midpoint's
/// curvature and cant); conditions that coincide (the same radius, cant, speed and friction) are
/// solved once with their shares summed. In the time domain each tangent is represented by a
/// stretch at its middle and each transition by itself (DynamicPiece), run from the quasi-static
/// state of the track where the simulation starts.

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle.hpp"
#include "wheelwear/vehicle/vehicle_motion.hpp"

namespace wheelwear::pipeline {

/// One running condition of the route, solved quasi-statically.
struct RouteCase {
  std::string label;           ///< the first section's name (or kind and radius)
  vehicle::SteadyCurve curve;  ///< radius, cant, speed, rail-top and gauge-face friction
  /// Of the route's length [-]; 0 for a condition that only starts a time-domain piece, whose
  /// states are not worn.
  double share = 0.0;
  bool reversed = false;  ///< met running the route backwards (RunningDirection)
};

/// A stretch of a tangent or transition the vehicle is simulated through.
struct DynamicPiece {
  std::string label;           ///< the section's name (or number and kind)
  std::size_t section = 0;     ///< index into the route's sections
  double start_m = 0.0;        ///< where the stretch starts along the route [m]
  double length_m = 0.0;       ///< of the stretch [m], > 0
  double share = 0.0;          ///< of the route's length its samples stand for: its section's
  double speed = 0.0;          ///< its section's speed [m/s]
  std::size_t start_case = 0;  ///< the RouteCase whose solution starts the simulation
  std::uint64_t seed = 0;      ///< of its generated irregularities (seed_for_section)
  bool tangent = false;        ///< a tangent's stretch, else a whole transition
  /// Run backwards: `section` and the distances are along vehicle::reversed(route).
  bool reversed = false;
  /// The car body's centre runs from sim_start_m (every body at rest in the start case's
  /// state) over sim_length_m (samples after the first run_in of it), so that each wheelset
  /// runs through the whole stretch after at least the run-in; sim_start_m < 0 for a piece at
  /// the route's start (the track before it is the first section's).
  double sim_start_m = 0.0;
  double sim_length_m = 0.0;
};

/// What a route's wear step solves: its quasi-static cases and its time-domain pieces.
struct RoutePlan {
  std::vector<RouteCase> cases;
  std::vector<DynamicPiece> pieces;
};

/// The running conditions of `route` in order of first appearance, every section solved
/// quasi-statically; their shares sum to 1.
std::vector<RouteCase> route_cases(const vehicle::Route& route);

/// The plan of `route` for `vehicle` (its wheelsets' places set where the pieces' simulations
/// start): without the time domain route_cases(route) and no pieces; with it the curves' cases
/// (shares > 0), one piece per tangent and transition, and the cases that start the pieces
/// (share 0 unless they coincide with a curve's). The shares of the worn cases and the pieces
/// sum to 1. Throws InputError for time-domain keys out of range.
RoutePlan route_plan(const vehicle::Route& route, const TimeDomainKeys& time_domain,
                     const vehicle::Vehicle& vehicle);

/// The plan of `run` in its direction(s): route_plan of its route (forward), of
/// vehicle::reversed(route) (reverse; every case and piece marked reversed, labels prefixed
/// "backwards, ", generated irregularities seeded seed_for_section(seed, sections + i) so that
/// they differ from the forward ones), or both, each with half its shares.
RoutePlan route_plan(const VehicleRun& run);

/// The route, time-domain keys and vehicle of one direction: `run`'s, or reversed
/// (vehicle::reversed, a measured irregularity record reversed along the route, the powered
/// axles in the reversed order of travel).
struct RunningWay {
  vehicle::Route route;
  TimeDomainKeys time_domain;
  vehicle::Vehicle vehicle;
};
RunningWay running_way(const VehicleRun& run, bool reversed);

/// A piece's irregularities: the measured record, none, or generated over the stretch the
/// wheelsets run through with the piece's seed, faded in over the run-in from where the leading
/// wheelset starts (IrregularitySpec::run_in), in route distance. Throws InputError naming the
/// file when a measured record does not cover where the piece's wheelsets run.
vehicle::TrackIrregularities piece_irregularities(const DynamicPiece& piece,
                                                  const TimeDomainKeys& time_domain,
                                                  const vehicle::Vehicle& vehicle);

/// What a piece's simulation gave, per wheelset in order of travel where it applies.
struct PieceRun {
  bool completed = false;  ///< false: it stopped early (message), its samples up to there
  std::string message;     ///< why it stopped early
  double time_step = 0.0;  ///< [s]
  long steps = 0;          ///< integration steps
  std::array<int, vehicle::kWheelsets> samples{};      ///< taken in the stretch
  std::array<double, vehicle::kWheelsets> dy_rms{};    ///< about zero [m]
  std::array<double, vehicle::kWheelsets> dy_max{};    ///< largest |dy| [m]
  std::array<double, vehicle::kWheelsets> yaw_rms{};   ///< angle of attack [rad]
  std::array<double, vehicle::kWheelsets> y_over_q{};  ///< largest Y/Q of its wheels [-]
  /// Samples whose contact kept a side of a jump of Q (vehicle::WheelsetForces::load_jump).
  std::array<int, vehicle::kWheelsets> load_jumps{};
};

/// The states of the wheelsets `worn` (in order of travel) where each runs through `piece`,
/// every one weighted share / (its samples) / (worn wheelsets), and the piece's summary (its
/// rms and extremes NaN for a wheelset without samples). A simulation that stopped early
/// weights each sample it reached as a completed one would (share / samples planned / worn
/// wheelsets), and the wheelset's state in the start case (where the car body started) stands
/// for the part of the stretch it did not reach, with the rest of its part of the share (all of
/// it for a wheelset never sampled there); the weights always sum to the share.
std::vector<WheelsetStateSpec> piece_states(const DynamicPiece& piece,
                                            const vehicle::VehicleMotion& motion,
                                            const RouteCase& start_case,
                                            const vehicle::VehicleCurving& start,
                                            const std::vector<int>& worn, PieceRun& summary);

/// The contact model of one wheelset for the vehicle: `left` and `right` wheel profiles on the
/// kernel's rail and track, with its normal-problem options, tangential method, material and
/// lateral arm (the forces only: no cell fields).
vehicle::WheelsetModel wheelset_model(const StateKernel& kernel, const profiles::Profile& left,
                                      const profiles::Profile& right);

/// The vehicle solved in every case of the route and simulated through every piece, and the
/// collective its states make.
struct VehicleCollective {
  std::vector<RouteCase> cases;
  std::vector<DynamicPiece> pieces;
  std::vector<PieceRun> piece_runs;              ///< per piece
  std::vector<vehicle::VehicleCurving> curving;  ///< per case
  /// Per worn case (share > 0), per wheelset the run wears (VehicleRun::wheelsets), in that
  /// order; then per piece the states of piece_states.
  std::vector<WheelsetStateSpec> states;
  int unconverged = 0;  ///< cases whose solve did not converge (their last iterate is used)
  /// Cases whose solve on the current profiles did not converge from the last converged one,
  /// which they keep (its states on the earlier profiles).
  int kept = 0;
  /// Pieces whose simulation stopped early.
  int incomplete() const;
  /// The linear critical speed on tangent track on the solve's profiles [m/s] (VehicleRun::
  /// critical_speed); NaN where not computed or not found (critical_speed_note says which).
  double critical_speed = std::numeric_limits<double>::quiet_NaN();
  std::string critical_speed_note = "not computed";
  /// The contact tables the vehicle ran on (VehicleRun::contact_table), per pair of the solve's
  /// wheel profiles: the step's states are evaluated on them while those profiles are current
  /// (VehicleRun::wear_from_table). Neither stored nor sent between processes.
  ContactTables contact_tables;
};

/// The states of the four wheelsets (in order of travel) in a solved case, each weighted 1
/// (wheelset_state): where a time-domain piece starts, they stand in for the part of its stretch
/// a simulation that stopped early did not reach.
using StartStates = std::array<WheelsetStateSpec, vehicle::kWheelsets>;
StartStates start_states(const RouteCase& route_case, const vehicle::VehicleCurving& curving);

/// piece_states with the start case's states given as they are (start_states).
std::vector<WheelsetStateSpec> piece_states(const DynamicPiece& piece,
                                            const vehicle::VehicleMotion& motion,
                                            const StartStates& start, const std::vector<int>& worn,
                                            PieceRun& summary);

/// One running condition to solve: its index in the plan's cases, and where its bodies start:
/// the same condition's solution on the profiles before (then at most 20 Newton iterations and
/// no fresh start: a warm start that fails keeps the earlier solution), or, unset, centred and
/// radial with the curve reached by continuation.
struct CaseTask {
  std::size_t index = 0;
  std::optional<vehicle::VehiclePlacement> start;
  double cost = 1.0;  ///< expected, relative to the others (for sharing the tasks out)
};

/// One piece to simulate: its index in the plan's pieces, where every body starts (its start
/// case's solution) and its wheelsets' states there.
struct PieceTask {
  std::size_t piece = 0;
  vehicle::VehiclePlacement start;
  StartStates start_states;
  double cost = 1.0;  ///< expected, relative to the others (for sharing the tasks out)
};

/// What a piece's simulation gives: its summary and its states (piece_states).
struct PieceOutcome {
  PieceRun run;
  std::vector<WheelsetStateSpec> states;
};

/// What a vehicle solve needs besides each case's and piece's start: the plan of `run` (for
/// draw `draw`), its running ways, and the contact models of its wheelsets on `wheels`. Built
/// from the same inputs, it solves a case and simulates a piece to the same bits in any
/// process.
class RouteSolver {
 public:
  /// The contact models of the four wheelsets in order of travel: the physical wheelset k, or
  /// 3 - k running backwards with its sides swapped.
  using Models = std::array<vehicle::WheelsetModel, vehicle::kWheelsets>;

  RouteSolver(const VehicleRun& run, const StateKernel& kernel,
              const std::vector<const profiles::Profile*>& wheels, std::uint64_t draw);

  const RoutePlan& plan() const { return plan_; }
  const Models& models(bool reversed) const { return models_[reversed ? 1 : 0]; }
  const RunningWay& way(bool reversed) const;
  /// The wheelsets the run wears (VehicleRun::worn_wheelsets).
  const std::vector<int>& worn_wheelsets() const { return worn_; }
  /// Solves the vehicle quasi-statically in the case of `task`.
  vehicle::VehicleCurving solve(const CaseTask& task) const;
  /// Simulates the piece of `task` from its start.
  PieceOutcome simulate(const PieceTask& task) const;
  /// The models' contact tables (VehicleRun::contact_table), per pair of profiles, keyed as
  /// the evaluation of the states on the same wheels numbers them (ContactTables).
  const ContactTables& contact_tables() const { return tables_; }

 private:
  RoutePlan plan_;
  std::vector<int> worn_;
  std::array<Models, 2> models_;
  std::array<std::optional<RunningWay>, 2> ways_;
  ContactTables tables_;
};

/// Where a vehicle solve's cases and pieces are worked out, results in the tasks' order: in
/// this process, TBB-parallel (the default), or spread over the processes of a job
/// (StepDistributor).
class RouteExecutor {
 public:
  virtual ~RouteExecutor() = default;
  virtual std::vector<vehicle::VehicleCurving> cases(const RouteSolver& solver,
                                                     const std::vector<CaseTask>& tasks);
  virtual std::vector<PieceOutcome> pieces(const RouteSolver& solver,
                                           const std::vector<PieceTask>& tasks);
};

/// Solves `run`'s vehicle in every case of its route on `wheels` (one profile for both wheels
/// of every wheelset, left and right, or left and right of each physical wheelset in the forward
/// order of travel: ProfileLayout), then simulates it through every piece from its start
/// case's solution, TBB-parallel over the cases and over the pieces (or with `executor`), and
/// finds its linear critical speed (searched from the previous solution's where there is one).
/// With `previous` (the same route's solution on earlier profiles) each case starts where it
/// was, and is not solved afresh where that fails: a case that converged then keeps that
/// solution (counted in `kept`), one that did not goes on from its last iterate. `draw`: the wear
/// step the vehicle is solved at; with TimeDomainKeys::redraw the pieces' generated
/// irregularities are that step's (redraw_pieces). Deterministic for any number of threads or
/// processes. Throws InputError on bad input.
VehicleCollective solve_vehicle_collective(const VehicleRun& run, const StateKernel& kernel,
                                           const std::vector<const profiles::Profile*>& wheels,
                                           const VehicleCollective* previous = nullptr,
                                           std::uint64_t draw = 0,
                                           RouteExecutor* executor = nullptr);

/// The pieces' seeds of draw `draw` (TimeDomainKeys::redraw): each piece's section in its
/// direction (sections + i running backwards), 2 sections further on per draw, so that no two
/// draws or directions share a track; draw 0 is route_plan's.
void redraw_pieces(std::vector<DynamicPiece>& pieces, const VehicleRun& run, std::uint64_t draw);

/// Throws InputError naming the condition where one of the conditions `run` solves (route_plan:
/// curves, transitions, the pieces' starting states, both ways) would unload a wheel of the
/// centred vehicle or ask a powered axle for more traction or braking than its adhesion
/// (vehicle::require_upright, require_adhesion): checked before a run creates its results file
/// or resumes one. `lateral_arm` as the scene's.
void require_upright_route(const VehicleRun& run, double lateral_arm);

/// Where a vehicle file disagrees with the scene it runs in, one warning each naming the key,
/// both values and which one is used (a difference was silent): its wheel radius (the contact
/// rolls on the scene's wheel) and lateral arm, and every key of its [contact] table it states
/// (a pairing it proposes; the scene's profiles and track are used). `vehicle_name` names the
/// file in the warnings; `wheel_radius` is the scene's wheel's nominal radius [m]; `friction`
/// the friction of a single curve (`curving`), unset on a route, whose sections give their own.
std::vector<std::string> vehicle_scene_differences(const vehicle::Vehicle& v,
                                                   const std::string& vehicle_name,
                                                   const Scene& scene, double wheel_radius,
                                                   std::optional<double> friction);

/// The contact look-up table of `model` the run interpolates from (VehicleRun::contact_table):
/// the default grid (contactgeom::WheelsetTableOptions), its loads from a quarter to three times
/// `vehicle`'s static wheel load.
std::shared_ptr<const contactgeom::WheelsetContactTable> contact_table(
    const vehicle::WheelsetModel& model, const vehicle::Vehicle& vehicle);

/// The collective's state of wheelset `k` (in order of travel) in a solved curve: its dy, yaw,
/// spin and the vertical forces its contact was solved for (so that the kernel meets the same
/// contact), the case's speed, radius and friction, its physical wheelset and direction
/// (mark_wheelset); weight `weight`.
WheelsetStateSpec wheelset_state(const RouteCase& route_case,
                                 const vehicle::VehicleCurving& curving, int k, double weight);

/// Sets `state`'s physical wheelset and direction: travel position `k` (0..3) is the physical
/// wheelset k, or 3 - k running backwards.
void mark_wheelset(WheelsetStateSpec& state, int k, bool reversed);

/// The collective's state of a wheelset in motion: its dy, yaw, rates and spin as `state`, the
/// vertical forces its contact was solved for (so that the kernel meets the same contact), the
/// speed, radius and friction of `running`; weight `weight`.
WheelsetStateSpec motion_state(const vehicle::WheelsetMotionState& state,
                               const vehicle::WheelsetForces& forces,
                               const vehicle::RunningConditions& running, std::string label,
                               double weight);

/// `states` as a load-collective CSV file (docs/scenes.md, "Load collective formats"): a label
/// column and every column a run records under collective/, 17 significant digits so that the
/// file reads back to the same numbers, unset optional values left empty. Labels are quoted
/// where RFC 4180 needs it (core::csv_field), so they read back as written.
std::string collective_csv(const std::vector<WheelsetStateSpec>& states);

}  // namespace wheelwear::pipeline
