#pragma once
/// Creepages at a patch's initial contact point from the wheelset's rigid-body motion.

#include "wheelwear/contactgeom/creepages.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/core/enum_names.hpp"

namespace wheelwear::contactgeom {

/// Where the lateral creepage is the wheel's rigid slip (kinematic_creepages).
enum class SlipPoint {
  /// In the vertical plane through the axle, projected onto the contact plane: the convention of
  /// multibody codes (and of CONTACT for a prescribed lateral velocity).
  axle_plane,
  /// Where the wheel touches its rail, ahead of (or behind) the axle when it is yawed: the slip
  /// along the contact plane.
  contact_point,
};

/// The names scenes and the command line give them.
inline constexpr core::NameTable<SlipPoint, 2> kSlipPointNames = {{
    {SlipPoint::axle_plane, "axle-plane"},
    {SlipPoint::contact_point, "contact-point"},
}};

/// The wheelset's motion along the track, for the wheel whose contact is evaluated.
struct WheelsetMotion {
  double speed = 0.0;             ///< forward speed V of the wheelset centre [m/s], > 0
  double lateral_velocity = 0.0;  ///< dy/dt [m/s], + towards this wheel's flange
  /// Yaw rate of the wheelset in this wheel's frame [rad/s], + when this wheel moves ahead of
  /// the axle's centre (for the left wheel -d(yaw)/dt, yaw being + counter-clockwise seen from
  /// above; in a right-hand curve of radius R the left, outer wheel has +V/R).
  double yaw_rate = 0.0;
  double angular_velocity = 0.0;  ///< wheel spin about the axle [rad/s]; 0: free rolling on
                                  ///< the nominal radius, V / r0
  double lateral_arm = 0.75;      ///< distance from the wheelset centre to the contact [m]
  SlipPoint slip_point = SlipPoint::axle_plane;  ///< where the lateral creepage is taken

  void validate() const;  ///< throws InputError naming a bad field
};

/// Creepages at O of `patch` (Kalker's definition with the wheel as body 1: the velocity of the
/// wheel's material over the rail, divided by the rolling speed, the mean of the two surface
/// speeds, as CONTACT defines it):
///   V_w = V + yaw_rate * arm (this wheel's forward speed), r = rolling radius at O,
///   V_roll = (V_w + omega r)/2, vx = (V_w - omega r)/V_roll,
///   vy = (yaw V_w - dy/dt) cos(angle)/V_roll (+y: the gauge side) at the axle plane,
///   vy = (yaw V_w - dy/dt)/(cos(angle) V_roll) at the contact point,
///   phi = omega sin(angle)/V_roll.
/// At the axle plane (SlipPoint::axle_plane, the default) the horizontal lateral slip is
/// projected onto the contact plane, as multibody codes take it at O in the vertical plane
/// through the axle, and as CONTACT projects a prescribed VY. At the contact point
/// (SlipPoint::contact_point) the wheel's material slides along the contact plane, not through
/// it: a wheel that stays on its rail has no slip along the contact normal, so the slip's
/// vertical part is tan(angle) times its horizontal lateral part, and in the plane the two add
/// to the horizontal part over cos(angle). For the yaw that vertical slip is the spin's at the
/// contact point ahead of (or behind) the axle, X* = -r yaw dz/dy along the rolling direction
/// (undeformed_distance.hpp): omega X* = -yaw omega r tan(angle) (tested against the lead
/// undeformed_distance finds); for the lateral velocity it is the wheel's rise as the
/// wheelset's roll and height follow its shift. The two agree on the tread to within angle^2;
/// on a flange flank at 1.22 rad the contact point's is 8.5 times the axle plane's. The
/// yaw rate's share of the spin (below 1e-3 of omega sin(angle) in curves) is not included, nor
/// the roll rate's own lateral slip at the contact, r times the roll rate: small against the
/// yaw's in a curve, but on a flank of the same order as dy/dt itself, so that the contact
/// point's dy/dt part is incomplete there (its yaw part is not).
Creepages kinematic_creepages(const WheelRailPatch& patch, const WheelsetPose& pose,
                              const WheelsetMotion& motion, double nominal_radius);

}  // namespace wheelwear::contactgeom
