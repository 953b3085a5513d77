#pragma once
/// The undeformed distance between a wheel and its rail over the track plane (x, y), with the
/// x-dependence from the wheel's curvature along x and from its yaw (the gap the contact patch
/// sees beyond the strip-wise h(y) + A(y) x^2 of the Kik-Piotrowski solver).

#include <optional>

#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom {

/// Vertical distance z_rail - z_wheel [m] at track-plane point (x, y) between the rail, a prism
/// along x with the rail profile's cross-section, and the wheel, the body of revolution of its
/// profile about the axle (rolling radius R(eta) = wheel_radius + z(eta) - z_tape of the profile
/// point at eta), placed as `pose` says: shifted by dy, rolled by pose.roll about the taping
/// point as WheelsetPose documents, and yawed by pose.yaw about the vertical through the taping
/// point, + turning the rolling direction (+x) towards the profile's +y (the wheel's field side,
/// where it moves when it moves towards its flange; the sign of kinematic_creepages).
///
/// x [m] along the track from the vertical plane through the (unyawed) axle; y [m] in the rail
/// profile's frame. Same datum as first_touch(): at x = 0 without yaw it is the gap whose
/// minimum first_touch() finds. The wheel point is found by Newton's method on its two surface
/// coordinates (lateral eta, angle phi about the axle) to 1e-14 m. The yawed axle crosses
/// lateral eta at x = -yaw eta; along its own rolling direction X the wheel's height at fixed y is
/// z(eta - yaw X) - X^2/(2 R) to first order in yaw, highest at X* = -R yaw dz/dy, the classic
/// lead of a yawed wheel's contact point, so the distance is least at x* = -yaw (eta + R dz/dy)
/// (tested). The strip-wise gap h(y) + A(y) x^2 of the Kik-Piotrowski solver leaves this out.
/// nullopt where (x, y) lies off either profile or beyond the wheel's lowest quarter
/// (|phi| >= 45 deg). Throws InputError on bad input.
std::optional<double> undeformed_distance(const WheelRailPair& pair, const WheelsetPose& pose,
                                          double x, double y);

}  // namespace wheelwear::contactgeom
