#pragma once
/// A run's load collective from the vehicle itself: the scene's vehicle solved quasi-statically
/// on the current wheel profiles in every running condition of its route, each wheelset's
/// steady state becoming a state of the collective (position, yaw, spin, loads and friction),
/// weighted by the share of the route it stands for.
///
/// The route is reduced to its running conditions: every constant curve and tangent as it is,
/// every transition at its midpoint's curvature and cant (the quasi-static state there; its
/// twist and the curvature's rate of change are left out); conditions that coincide (the same
/// radius, cant, speed and friction) are solved once with their shares summed. Tangent track
/// without irregularities gives the centred wheelset: the time-domain simulation with track
/// irregularities is not part of the run (docs/vehicle.md, "In the run").

#include <memory>
#include <string>
#include <vector>

#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle.hpp"

namespace wheelwear::pipeline {

/// One running condition of the route.
struct RouteCase {
  std::string label;           ///< the first section's name (or kind and radius)
  vehicle::SteadyCurve curve;  ///< radius, cant, speed, rail-top and gauge-face friction
  double share = 0.0;          ///< of the route's length [-]
};

/// The running conditions of `route` in order of first appearance; their shares sum to 1.
std::vector<RouteCase> route_cases(const vehicle::Route& route);

/// The contact model of one wheelset for the vehicle: `left` and `right` wheel profiles on the
/// kernel's rail and track, with its normal-problem options, tangential method, material and
/// lateral arm (the forces only: no cell fields).
vehicle::WheelsetModel wheelset_model(const StateKernel& kernel, const profiles::Profile& left,
                                      const profiles::Profile& right);

/// The vehicle solved in every case of the route, and the collective its states make.
struct VehicleCollective {
  std::vector<RouteCase> cases;
  std::vector<vehicle::VehicleCurving> curving;  ///< per case
  /// Per case, per wheelset the run wears (VehicleRun::wheelsets), in that order.
  std::vector<WheelsetStateSpec> states;
  int unconverged = 0;  ///< cases whose solve did not converge (their last iterate is used)
  /// Cases whose solve on the current profiles did not converge from the last converged one,
  /// which they keep (its states on the earlier profiles).
  int kept = 0;
};

/// Solves `run`'s vehicle in every case of its route on `wheels` (one profile for both wheels
/// of every wheelset, or left and right), TBB-parallel over the cases. With `previous` (the
/// same route's solution on earlier profiles) each case starts where it was, and is not solved
/// afresh where that fails: a case that converged then keeps that solution (counted in `kept`),
/// one that did not goes on from its last iterate. Deterministic for any number of threads.
/// Throws InputError on bad input.
VehicleCollective solve_vehicle_collective(const VehicleRun& run, const StateKernel& kernel,
                                           const std::vector<const profiles::Profile*>& wheels,
                                           const VehicleCollective* previous = nullptr);

/// The contact look-up table of `model` the run interpolates from (VehicleRun::contact_table):
/// the default grid (contactgeom::WheelsetTableOptions), its loads from a quarter to three times
/// `vehicle`'s static wheel load.
std::shared_ptr<const contactgeom::WheelsetContactTable> contact_table(
    const vehicle::WheelsetModel& model, const vehicle::Vehicle& vehicle);

/// The collective's state of wheelset `k` in a solved curve: its dy, yaw, spin and the
/// vertical forces its contact was solved for (so that the kernel meets the same contact), the
/// case's speed, radius and friction; weight `weight`.
WheelsetStateSpec wheelset_state(const RouteCase& route_case,
                                 const vehicle::VehicleCurving& curving, int k, double weight);

/// `states` as a load-collective CSV file (docs/scenes.md, "Load collective formats"): a label
/// column and every column a run records under collective/, 17 significant digits so that the
/// file reads back to the same numbers, unset optional values left empty. Labels are made one
/// cell that reads back: commas and line breaks become ';', edge spaces go, and a leading '#'
/// (a comment row to the reader) becomes "no. #".
std::string collective_csv(const std::vector<WheelsetStateSpec>& states);

}  // namespace wheelwear::pipeline
