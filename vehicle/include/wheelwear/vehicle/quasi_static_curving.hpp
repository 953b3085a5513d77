#pragma once
/// Quasi-static curving of the whole vehicle: the steady state of the car body, both bogies and
/// all four wheelsets in a constant curve without irregularities. Newton's method on the balance
/// of every body (lateral force and yaw moment in the track plane) and the free rolling of every
/// axle (zero axle torque, the spin moments included), with the wheels' loads from the vertical
/// balance: the rails' forces from the project's own contact chain on the current profiles
/// (wheelset_forces), gravity from the cant, the centrifugal force and the suspension.
///
/// The model, in the track plane (it turns with the cant):
/// - Each body has a lateral shift y from the track centre line at its own position and a yaw
///   relative to the track's tangent there (for a wheelset: its angle of attack). Suspension
///   joints see the relative displacement of the child body against the parent's attachment
///   point in the parent's frame: for a child at distance d ahead of its parent,
///   dy = y_child - d^2 / (2 R) - y_parent - yaw_parent d, and dyaw = yaw_child - d / R -
///   yaw_parent (small angles; R signed, > 0 right-hand).
/// - Primary joint: both axleboxes of a wheelset (lateral 2 ky, yaw 2 (kx b^2 + kpsi), b half
///   their spacing); secondary joint: both sides of a bogie, plus the lateral stop.
/// - Every body needs the in-plane force m (V^2/|R| cos(phi) - g sin(phi)) towards the curve
///   centre (phi the cant angle) and no yaw moment.
/// - Wheel loads: each wheelset carries its own mass, half its bogie's and a quarter of the car
///   body's; their weight (g cos(phi) + V^2/|R| sin(phi) per unit mass) is shared by the two
///   wheels so that the moment about the track centre line at rail level balances: the bodies'
///   in-plane forces at their centres of gravity and their weights at their lateral positions,
///   the car body's where the bogie's secondary suspension carries it: its shift over the
///   bogie's pivot, against the track there (in a curve the body's centre lies inside the
///   track by the versine, kappa d^2 / 2 at R 500 m and 9.5 m from the pivots 90 mm, where the
///   pivots follow the bogies).
///   The bodies' roll in their suspension is not modelled (its shift of the car body's centre of
///   gravity is left out).
/// - The longitudinal balance is not solved: the stiff longitudinal springs carry the small
///   longitudinal force an axle's creep leaves.

#include <array>
#include <optional>
#include <string>

#include "wheelwear/vehicle/free_wheelset.hpp"
#include "wheelwear/vehicle/vehicle.hpp"
#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle {

/// A body's place in the track plane.
struct BodyPlacement {
  double y = 0.0;    ///< lateral shift from the track centre line at the body [m], + left
  double yaw = 0.0;  ///< relative to the track's tangent at the body [rad], + heads left
};

/// What is left of a body's balance [N], [N m]: the in-plane forces on it minus the force the
/// curve requires, and the yaw moment about its centre.
struct BodyBalance {
  double lateral = 0.0;
  double yaw_moment = 0.0;
};

/// One wheelset in the solved curve.
struct CurvingWheelset {
  double x = 0.0;                   ///< ahead of the car body's centre [m]
  WheelsetMotionState state;        ///< dy, yaw (angle of attack), spin; rates zero
  double load_left = 0.0;           ///< Q the left wheel carries [N]
  double load_right = 0.0;          ///< Q the right wheel carries [N]
  WheelsetForces forces;            ///< the rails' forces at `state`
  BodyBalance balance;              ///< residual of the wheelset's balance
  double suspension_lateral = 0.0;  ///< the primary joint's lateral force on the wheelset [N]
  double suspension_yaw = 0.0;      ///< the primary joint's yaw moment on the wheelset [N m]
};

/// Where every body is: the unknowns of the curving problem.
struct VehiclePlacement {
  BodyPlacement car_body;
  std::array<BodyPlacement, kBogies> bogies;
  std::array<WheelsetMotionState, kWheelsets> wheelsets;  ///< dy, yaw, spin; rates unused
};

/// How to solve.
struct CurvingOptions {
  int max_iterations = 60;  ///< Newton iterations per attempt
  /// Converged when every body's lateral residual is within `force_tolerance` m g, its yaw
  /// moment within `force_tolerance` m g times 1 m, and every axle torque within 1e-7 of the
  /// sum of |Fx| r of its patches (at least 1e-9 of its wheel load times its radius).
  double force_tolerance = 1e-7;
  /// Where Newton starts, e.g. the same curve's solution on the profiles before a wear step;
  /// unset, or where Newton fails from there: every body centred and radial, the curve reached
  /// by continuation. The solution converged from either meets the same tolerances.
  std::optional<VehiclePlacement> start;
  /// Where Newton fails from `start`: start afresh (true) or give up at once (false: a start
  /// that did not converge before rarely converges afresh, and a fresh solve costs the most).
  /// A start that cannot be used (not finite, an axle without spin, beyond the profiles) is
  /// no attempt: the solve starts afresh either way.
  bool restart_on_failure = true;
};

/// The solved steady state.
struct VehicleCurving {
  bool converged = false;
  int iterations = 0;          ///< Newton iterations, over all continuation steps
  int continuation_steps = 1;  ///< the curve reached in this many steps of curvature
  bool from_start = false;     ///< converged from CurvingOptions::start
  /// Converged with the contacts evaluated directly: the attempts on the tabulated contacts
  /// (WheelsetModel::table) failed (Newton can stall at a kink of their interpolation), and the
  /// solve went on with direct contacts, from the nearest attempt or afresh; the balance is then
  /// with the direct contacts' forces.
  bool finished_directly = false;
  int wheelset_evaluations = 0;  ///< calls of wheelset_forces
  std::string message;           ///< why, when not converged
  double cant_deficiency = 0.0;  ///< [m]
  BodyPlacement car_body;
  std::array<BodyPlacement, kBogies> bogies;
  std::array<BodyBalance, kBogies + 1> body_balances;  ///< car body, bogie 0, bogie 1
  std::array<CurvingWheelset, kWheelsets> wheelsets;   ///< in order of travel
};

/// The placement of every body in a solved (or attempted) curve, to start another solve from.
VehiclePlacement placement_of(const VehicleCurving& curving);

/// Solves the quasi-static curving of `vehicle` in `curve`, its wheelsets' contacts given by
/// `wheelsets` (in order of travel; each with its own profiles, as a run that wears them
/// separately has). Throws InputError on bad input; a numerical failure is reported in the
/// result (converged false, with the message).
VehicleCurving solve_vehicle_curving(const Vehicle& vehicle,
                                     const std::array<WheelsetModel, kWheelsets>& wheelsets,
                                     const SteadyCurve& curve, const CurvingOptions& options = {});

/// The wheels' loads (left, right) [N] of a wheelset for the bodies at the given lateral shifts
/// against the track (the car body's over the wheelset's bogie pivot, the bogie's, the
/// wheelset's) in `curve` (model above).
std::array<double, 2> wheel_loads(const Vehicle& vehicle, const SteadyCurve& curve,
                                  double lateral_arm, double car_body_y, double bogie_y,
                                  double wheelset_y);

/// Throws InputError where `curve`'s unbalanced lateral acceleration unloads a wheel of the
/// centred vehicle (wheel_loads with every body centred, `lateral_arm` as WheelsetModel's): the
/// vehicle overturns there and no balance exists. The message names the curve, the cant
/// deficiency and the fix.
void require_upright(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm);

/// Throws InputError where `curve`'s traction or braking (SteadyCurve::traction, per powered
/// axle) reaches the adhesion of a powered axle of the centred vehicle, friction times its wheel
/// loads: its wheels would slip or slide and no balance exists.
void require_adhesion(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm);

}  // namespace wheelwear::vehicle
