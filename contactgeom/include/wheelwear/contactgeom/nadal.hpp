#pragma once
/// Nadal's flange-climb criterion for one wheel on its rail (Nadal 1908; EN 14363 uses the same
/// quotient): the wheel may climb when the ratio of its lateral to its vertical force Y/Q exceeds
/// (tan(delta) - mu) / (1 + mu tan(delta)), delta being the flange contact angle and mu the
/// friction there. A flag beside the geometric status: a position-prescribed flange state can
/// exceed it (CONTACT's y_ws = -8 mm case has Y/Q of about 2.5) without anything being wrong.

#include <optional>
#include <vector>

#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom {

/// Patches carrying at least this share of the wheel's normal load define delta: a light touch
/// of the flange beside a loaded tread does not make the wheel climb.
inline constexpr double kNadalLoadShare = 0.10;

/// The criterion applies from this contact angle on [rad]: it is a derailment criterion for the
/// flange flank. Nadal's limit presumes the flange cannot offer a steeper slope; at the flange
/// root a lateral slide moves the contact up to steeper angles, where the limit grows, so a root
/// contact beyond its own limit is not climbing (its Y/Q exceeds tan(delta - atan mu) whenever
/// the creep force is not saturated). S1002 on 60E1 touches its flange root at 0.28 ... 0.5 rad
/// in curves down to R500 and its flank at 0.8 ... 1.22 rad; worn wheels reach 1.32 rad. Below
/// atan(mu) the limit is negative and the criterion means nothing in any case.
inline constexpr double kNadalFlankAngle = 0.6;

/// The criterion's verdict for one wheel.
struct NadalCheck {
  double delta = 0.0;     ///< largest contact angle among the patches carrying the load [rad]
  double limit = 0.0;     ///< (tan(delta) - mu) / (1 + mu tan(delta)) [-]
  double Y_over_Q = 0.0;  ///< lateral over vertical force of the whole wheel [-]
  /// delta >= kNadalFlankAngle and tan(delta) > mu: contact on the flange flank.
  bool applies = false;
  bool exceeded = false;  ///< applies and Y_over_Q > limit
};

/// A patch's tangential force along its contact plane's lateral axis [N] (+ towards the gauge
/// side, the creep forces' y; tangential::CreepForces::Fy), where it is known.
using PatchLateralCreep = std::optional<std::vector<double>>;

/// The wheel's forces in the track plane [N]: Y lateral, + pushing the wheel towards the track
/// centre (as WheelRailContact::lateral_force), Q vertical, + pressing the wheel up. The normal
/// forces' share is the contact's own strip-wise sum; a patch's lateral creep force Fy, on its
/// contact plane inclined by the patch's angle gamma, adds Fy cos(gamma) to Y and -Fy sin(gamma)
/// to Q (the plane's lateral axis runs towards the track centre and down the gauge face).
struct TrackPlaneForces {
  double Y = 0.0;
  double Q = 0.0;
};
TrackPlaneForces track_plane_forces(const WheelRailContact& contact,
                                    const PatchLateralCreep& creep_Fy = std::nullopt);

/// Nadal's criterion for `contact` with flange friction `mu` (>= 0) and the wheel's forces `f`.
/// A contact without patches, or with Q <= 0, gives delta = 0 and exceeded = false.
NadalCheck nadal_check(const WheelRailContact& contact, double mu, const TrackPlaneForces& f);

/// The same with the forces of track_plane_forces(contact, creep_Fy).
NadalCheck nadal_check(const WheelRailContact& contact, double mu,
                       const PatchLateralCreep& creep_Fy = std::nullopt);

}  // namespace wheelwear::contactgeom
