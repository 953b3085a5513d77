#pragma once
/// Creepages at a patch's initial contact point from the wheelset's rigid-body motion.

#include "wheelwear/contactgeom/creepages.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom {

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

  void validate() const;  ///< throws InputError naming a bad field
};

/// Creepages at O of `patch` (Kalker's definition with the wheel as body 1: the velocity of the
/// wheel's material over the rail, divided by the rolling speed, the mean of the two surface
/// speeds, as CONTACT defines it):
///   V_w = V + yaw_rate * arm (this wheel's forward speed), r = rolling radius at O,
///   V_roll = (V_w + omega r)/2, vx = (V_w - omega r)/V_roll,
///   vy = (yaw - (dy/dt)/V_w) V_w cos(angle)/V_roll (+y: the gauge side),
///   phi = omega sin(angle)/V_roll.
/// The rigid lateral slip is projected onto the contact plane, as CONTACT does for prescribed
/// velocities; the wheelset's roll rate and the yaw rate's share of the spin (below 1e-3 of
/// omega sin(angle) in curves) are not included.
Creepages kinematic_creepages(const WheelRailPatch& patch, const WheelsetPose& pose,
                              const WheelsetMotion& motion, double nominal_radius);

}  // namespace wheelwear::contactgeom
