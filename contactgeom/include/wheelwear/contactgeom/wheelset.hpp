#pragma once
/// A rigid wheelset on its track: both wheels' contacts at one lateral shift and yaw, with the
/// roll that puts both wheels on their rails, and optionally each wheel's lateral force
/// prescribed instead of its lateral position.

#include <optional>
#include <string>

#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom {

/// Both wheels of a wheelset on their rails. Each pair is in its own frame with the per-wheel
/// conventions of WheelsetPose (the right wheel is the mirror image of a left wheel). The two
/// pairs share the track's gauge, gauge depth and the back-to-back distance; the rails' tops
/// lie at one height (no cant).
struct WheelsetOnTrack {
  WheelRailPair left;
  WheelRailPair right;
};

/// The roll of a rigid wheelset as solve_wheelset found it at some dy and yaw. It does not depend
/// on the loads (both wheels touch with undeformed surfaces), so a solve for other loads at the
/// same dy and yaw can take it instead of iterating again, with identical results.
struct KnownRoll {
  double dy = 0.0;             ///< the WheelsetState::dy it was found at [m]
  double yaw = 0.0;            ///< the WheelsetState::yaw it was found at [rad]
  double roll = 0.0;           ///< [rad]
  double centre_height = 0.0;  ///< WheelsetContact::centre_height [m]
  bool converged = false;      ///< WheelsetContact::roll_converged
};

/// The state of the wheelset for one evaluation.
struct WheelsetState {
  /// Lateral shift of the wheelset's centre (on the axle, midway between the flange backs) from
  /// the track centre [m], + towards the LEFT wheel's flange (to the left).
  double dy = 0.0;
  double yaw = 0.0;                   ///< yaw [rad], sign as WheelsetPose::yaw of the left wheel
  double vertical_force_left = 0.0;   ///< [N] > 0
  double vertical_force_right = 0.0;  ///< [N] > 0
  /// Prescribed lateral force on the left wheel [N], as WheelRailContact::lateral_force (+
  /// pushes the wheel towards the track centre); nullopt: the position is prescribed.
  std::optional<double> lateral_force_left;
  std::optional<double> lateral_force_right;  ///< [N], as lateral_force_left for the right wheel
  /// The roll found by an earlier solve (WheelsetContact::known_roll); when it was found at
  /// exactly this dy and yaw the roll iteration is skipped. Ignored otherwise, and when a
  /// lateral force is prescribed (the wheels' adjusted positions move the roll).
  std::optional<KnownRoll> known_roll;
};

/// How a wheel's prescribed lateral force was met.
enum class LateralFit {
  not_prescribed,   ///< no lateral force given: the wheel sits at the rigid wheelset's position
  matched,          ///< the wheel's position was adjusted until its lateral force matched
  kept_position,    ///< the force is below what the tread gives at the given position, without
                    ///< flange contact: the position is kept (the flange is not loaded)
  flange_unloaded,  ///< the force is below what the tread gives once the flange unloads: the
                    ///< wheel sits where the flange just unloads (to 10 um)
  not_matched,      ///< no position within reach gives the force (see the message)
};

/// A wheel's contact with its lateral force prescribed.
struct WheelRailLateral {
  WheelRailContact contact;                     ///< the contact at `pose`
  WheelsetPose pose;                            ///< the pose with the adjusted lateral shift
  LateralFit fit = LateralFit::not_prescribed;  ///< how the force was met
  double shift = 0.0;   ///< adjustment of pose.dy from the given one [m], + towards the flange
  int evaluations = 0;  ///< contact solves made
  std::string message;  ///< why, when fit is not_matched
};

/// Both wheels' contacts.
struct WheelsetContact {
  /// Wheelset roll [rad], + when the left wheel goes down relative to the right one (a rotation
  /// about the track's longitudinal axis; WheelsetPose::roll of the left wheel, minus that of the
  /// right wheel). Moving towards its flange the left wheel rolls on a larger radius: roll < 0.
  double roll = 0.0;
  WheelsetPose left_pose, right_pose;  ///< the per-wheel poses the contacts were solved at
  WheelRailContact left, right;
  LateralFit left_fit = LateralFit::not_prescribed;   ///< how the left lateral force was met
  LateralFit right_fit = LateralFit::not_prescribed;  ///< how the right lateral force was met
  /// Adjustment of the left wheel's position on its rail from the rigid wheelset's [m], + towards
  /// its flange: the rail head is displaced by -left_shift (0 unless the lateral force is
  /// prescribed).
  double left_shift = 0.0;
  double right_shift = 0.0;     ///< as left_shift, for the right wheel [m]
  double centre_height = 0.0;   ///< height of the wheelset centre above the top of the rails
                                ///< with both wheels at rest (resting_gap) [m]
  bool roll_converged = false;  ///< the roll iteration met its tolerance
  int touch_evaluations = 0;    ///< first-touch evaluations of both wheels (roll iteration)
  int contact_solves = 0;       ///< wheel/rail contact solves, lateral searches included
  std::string message;          ///< why, when something did not converge or match
  /// The roll for a later solve at the same dy and yaw (WheelsetState::known_roll); empty when
  /// a wheel did not reach its rail or a lateral force was prescribed.
  std::optional<KnownRoll> known_roll;
};

/// Solves both wheels' contacts of a rigid wheelset.
///
/// Rigid-body placement: the wheelset turns by `roll` about its centre, which lies wheel_radius
/// above each taping point and midway between the flange backs, and moves laterally by dy. With
/// Y_w = back_to_back/2 - flange_back_y the distance of wheel w's taping point from the centre
/// and r_w its wheel_radius, the per-wheel poses are
/// dy_left = dy + (cos(roll) - 1) Y_left - sin(roll) r_left, roll_left = roll, yaw_left = yaw;
/// dy_right = -dy + (cos(roll) - 1) Y_right + sin(roll) r_right, roll_right = -roll,
/// yaw_right = -yaw (the right wheel mirrored).
/// The roll is such that both wheels rest on their rails with undeformed surfaces (the minimum
/// gap zero on both sides, but where a steep flank shares the load, below):
/// sin(roll) (Y_left + Y_right) + cos(roll) (r_left - r_right) = Z_left - Z_right, with
/// Z = z_tape + WheelRailTouch::resting_gap - z_top(rail) the depth below the top of rail at
/// which each taping point rests (z down): the gap's lowest minimum, or where a minimum on a
/// flank nearly as steep as atan(D/r) lies within an elastic approach of it, a depth between
/// them that moves continuously as one overtakes the other (without it the roll ran away where
/// such a flank's minimum overtook the tread's).
/// The difference of the two wheels' elastic approaches is neglected (each ~0.1 mm at 55 kN, the
/// same for equal loads and contacts, 0.01 mm apart for 60 against 48 kN): it would tilt the
/// wheelset by 1e-5 rad, below 1e-4 rad even between tread and flange contact. The
/// residual rises with the roll at the rate D = Y_left + Y_right less r tan(contact angle) of a
/// wheel on its flange (the roll about the centre moves the contact by r roll): a Newton step
/// with the slope D brackets the root and Anderson-Bjorck regula falsi meets |residual| <=
/// 1e-11 m. Note that in flange contact the roll moves the contact towards the flange by
/// r_left |roll| beyond dy (3 mm at a roll of 6 mrad).
///
/// A prescribed lateral force (solve_wheel_rail_lateral) moves that wheel alone relative to its
/// rail: the rail's lateral flexibility (and the wheel's) takes up the difference from the rigid
/// wheelset's position, which stays at dy. The roll is then solved again at the moved wheels'
/// positions, alternating (with secant steps on the roll) until it changes by less than 1e-9 rad,
/// each lateral solve starting from the previous shift; a force that is not met (not_matched)
/// ends the alternation with the contacts at the last roll.
/// Throws InputError on bad input (including pairs that disagree on gauge or back-to-back).
WheelsetContact solve_wheelset(const WheelsetOnTrack& track, const WheelsetState& state,
                               const WheelRailOptions& options = {});

/// The contact of one wheel whose vertical force Fz [N] > 0 and lateral force Fy [N]
/// (as WheelRailContact::lateral_force) are prescribed: pose.dy is adjusted by a bracketed
/// regula falsi (Anderson & Bjorck 1973) until |lateral_force - Fy| <= options.lateral_tolerance
/// Fz (1e-6 Fz), with the roll
/// and yaw of `pose` kept. Lateral force grows with dy as the flange takes load, so the
/// bracket is sought towards the flange when Fy is larger than at pose.dy and away from it when
/// smaller. When Fy is smaller and no patch at pose.dy lies on the flange (contact angle above
/// options.flange_angle), the position is kept: the flange is not loaded and the tread's
/// lateral force is whatever its contact angle gives. When Fy is smaller than the tread gives
/// once the flange has unloaded, the wheel stays where the flange just unloads
/// (flange_unloaded). The search reaches 20 mm either way. Where the force jumps across the target
/// (the load moving between tread and flange) the side nearest the target is reported with
/// fit not_matched. Throws InputError on bad input.
WheelRailLateral solve_wheel_rail_lateral(const WheelRailPair& pair, const WheelsetPose& pose,
                                          double vertical_force, double lateral_force,
                                          const WheelRailOptions& options = {});

/// The name of a lateral fit ("matched", ...).
const char* lateral_fit_name(LateralFit fit);

}  // namespace wheelwear::contactgeom
