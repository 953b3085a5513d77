#pragma once
/// The forces of the rails on one wheelset in a given motion, from the project's own chain:
/// both wheels' contacts with the roll their geometry gives (contactgeom::solve_wheelset), each
/// patch's creepages from the motion at its own contact point, its tangential problem with the
/// chosen method, and the sums in the track plane that a vehicle model balances.
///
/// Track frame: x forward along the track, y to the left, z up; yaw + counter-clockwise seen
/// from above (the wheelset heads left). Each wheel's own frame is that of WheelsetPose (the
/// right wheel the mirror image of a left one); its contact plane's lateral axis runs towards
/// the gauge side, the track centre.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/contactgeom/rail_friction.hpp"
#include "wheelwear/contactgeom/wheelset.hpp"
#include "wheelwear/contactgeom/wheelset_table.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::vehicle {

/// Where the wheelset is and how it moves relative to the track.
struct WheelsetMotionState {
  double dy = 0.0;  ///< lateral shift of the centre from the track centre line [m], + left
  /// Yaw relative to the track's local tangent [rad], + heads left: the angle of attack.
  double yaw = 0.0;
  double spin = 0.0;              ///< axle angular velocity [rad/s], > 0 rolling forward
  double lateral_velocity = 0.0;  ///< d(dy)/dt [m/s], + left
  double yaw_rate = 0.0;          ///< d(yaw)/dt relative to the track [rad/s]
};

/// The running conditions of the track at the wheelset.
struct RunningConditions {
  double speed = 0.0;         ///< forward speed of the wheelset centre [m/s], > 0
  double curve_radius = 0.0;  ///< [m]; 0 tangent track, > 0 right-hand (left rail outer)
  double friction = 0.3;      ///< on the rail top [-], > 0
  /// On the gauge face, for patches at contact angles from contactgeom::kFlangeContactAngle
  /// [-], > 0; unset: the rail top's.
  std::optional<double> friction_flange;

  /// Both coefficients, the flange's defaulting to the rail top's.
  contactgeom::RailFriction rail_friction() const {
    return {friction, friction_flange.value_or(friction)};
  }
};

/// What the contact model of the wheelset is made of.
struct WheelsetModel {
  contactgeom::WheelsetOnTrack track;  ///< both wheels' profiles, rails and track geometry
  contactgeom::WheelRailOptions contact;
  tangential::Method method = tangential::Method::fastsim_sdec;
  /// Solve on the equivalent ellipse (the SDEC's a and b, psi = 0) centred at O instead of the
  /// SDEC. With linear_sdec this is Kalker's classic linear creep, the textbook's: a symmetric
  /// patch couples no spin into Fx.
  bool ellipse_at_O = false;
  tangential::SolveOptions solve;
  tangential::Material material{80e9, 0.25};  ///< combined shear modulus and Poisson's ratio
  /// Distance from the wheelset centre to each wheel's contact [m]: the arm of the yaw rate in
  /// each wheel's forward speed and of the longitudinal forces in the yaw moment.
  double lateral_arm = 0.75;
  /// Where each patch's lateral creepage is the wheel's rigid slip (contactgeom::SlipPoint).
  contactgeom::SlipPoint slip_point = contactgeom::SlipPoint::axle_plane;
  /// A contact look-up table of `track` with `contact` (contactgeom::WheelsetContactTable): the
  /// wheels' contacts are interpolated from it where it answers and solved directly elsewhere.
  /// Unset: always solved directly (the reference).
  std::shared_ptr<const contactgeom::WheelsetContactTable> table;
  /// Relative tolerance to which each wheel's Q meets its load, in (0, 0.01].
  double load_tolerance = 1e-9;
};

/// One patch's share, in its wheel's frame.
struct PatchForces {
  double normal_force = 0.0;    ///< N [N]
  double contact_angle = 0.0;   ///< gamma [rad]
  double rolling_radius = 0.0;  ///< r [m]
  tangential::Creepages creepages;
  double Fx = 0.0;  ///< longitudinal creep force on the wheel [N], + forward
  double Fy = 0.0;  ///< lateral creep force in the contact plane [N], + towards the gauge side
  double Mz = 0.0;  ///< spin moment about the contact normal [N m] (0 where the method has none)
};

/// The rail's forces on one wheel, summed over its patches (the `curving` contract's names).
struct WheelForces {
  contactgeom::WheelRailStatus status = contactgeom::WheelRailStatus::no_contact;
  /// Normal to the track plane, + up: sum of N cos(gamma) strip by strip, minus Fy sin(gamma).
  double Q = 0.0;
  /// In the track plane normal to the rail, + towards the track centre: sum of N sin(gamma)
  /// strip by strip, plus Fy cos(gamma).
  double Y = 0.0;
  double Fx = 0.0;             ///< sum of the patches' Fx [N], + forward
  double Fy = 0.0;             ///< sum of Fy cos(gamma) [N] (Y = sum N sin(gamma) + Fy)
  double N = 0.0;              ///< total normal force [N]
  double contact_angle = 0.0;  ///< of the patch with the largest N [rad]
  /// Moment of the contact forces about the axle, against the spin: sum of Fx r - Mz sin(gamma)
  /// [N m]; zero for a free-rolling wheel. (The contact's power into the spin is -spin times
  /// this: Fx acts at the radius r below the axle, the spin moment about the normal has the
  /// axle component Mz sin(gamma).)
  double torque = 0.0;
  std::vector<PatchForces> patches;
};

/// The rails' forces on the wheelset.
struct WheelsetForces {
  contactgeom::WheelsetContact contact;  ///< the geometry: roll, per-wheel poses and patches
  std::array<WheelForces, 2> wheels;     ///< left, right
  double lateral = 0.0;                  ///< along the track's y [N], + left: Y_right - Y_left
  /// About the vertical through the centre [N m], + counter-clockwise: the longitudinal creep
  /// forces at +-lateral_arm (the spin moments' vertical parts, Mz cos(gamma), below 1 % of it in
  /// curving, are left out).
  double yaw_moment = 0.0;
  double Fx_axle = 0.0;      ///< Fx of both wheels [N], + forward
  double axle_torque = 0.0;  ///< torque of both wheels [N m]; 0 for a free-rolling axle
  int load_iterations = 0;   ///< contact solves made to meet the wheels' loads Q
  /// Every wheel carrying load meets its Q to the model's tolerance, or (load_jump) the nearest
  /// a jump of its Q lets it, within 5 % of its load.
  bool loads_met = false;
  /// A wheel's Q jumps across its load (contact regions that merge or part, or a jump of its
  /// creep forces): no vertical force meets the load, and the wheel keeps a side of the jump
  /// within 5 % of its load (the nearer side of a bracket, or the side the contact answers from).
  bool load_jump = false;
  /// The vertical forces (left, right) the last contact was solved for [N]: the loads less
  /// the creep forces' vertical parts; a good start for a nearby state (vertical_start).
  std::array<double, 2> vertical_forces{};
  bool tabulated = false;  ///< the last contact came from WheelsetModel::table
  std::string message;     ///< why, when the loads were not met
};

/// The forces of the rails on the wheelset at `state`, each wheel carrying `load_left`,
/// `load_right` [N] (its Q, creep forces included: the vertical force the contact solves for is
/// corrected by the creep forces' vertical part until Q meets the load to
/// WheelsetModel::load_tolerance). Throws InputError on bad input; a wheel whose contact fails
/// keeps its status and no forces. `known_roll`: the roll an earlier evaluation at the same dy and
/// yaw found (WheelsetForces::contact.known_roll), which spares the roll iteration without changing
/// the result; the load iterations share one roll solve the same way. `vertical_start`: the
/// vertical forces to solve the contact for first (WheelsetForces::vertical_forces of a
/// nearby state), which saves load iterations; unset: the loads.
WheelsetForces wheelset_forces(const WheelsetModel& model, const WheelsetMotionState& state,
                               double load_left, double load_right,
                               const RunningConditions& running,
                               std::optional<contactgeom::KnownRoll> known_roll = std::nullopt,
                               std::optional<std::array<double, 2>> vertical_start = std::nullopt);

/// The torque a motor or brake puts on a powered axle that drives `traction` [N] (> 0 traction,
/// < 0 braking) through its wheels: traction times the wheels' nominal radius [N m]. In steady
/// rolling the contact's axle_torque balances it.
double drive_torque(const WheelsetModel& model, double traction);

/// The motion of wheel `side` (0 left, 1 right) in its own frame for kinematic_creepages.
contactgeom::WheelsetMotion wheel_motion(const WheelsetMotionState& state,
                                         const RunningConditions& running, int side,
                                         double lateral_arm);

}  // namespace wheelwear::vehicle
