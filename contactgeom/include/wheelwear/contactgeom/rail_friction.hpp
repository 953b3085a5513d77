#pragma once
/// The coefficient of friction a patch sees: the rail top's or the gauge face's, so that flange
/// lubrication lowers the friction of flange contacts only.

namespace wheelwear::contactgeom {

/// Contact angle from which a patch lies on the gauge face and the flange [rad] (20 degrees).
/// S1002 on 60E1 jumps from tread contact (below 10 degrees) to the flange root (above 30
/// degrees), so any threshold between them sorts its patches alike; 20 degrees is a modelling
/// choice, not a figure from a standard.
inline constexpr double kFlangeContactAngle = 0.349;

/// Friction on the rail top and on the gauge face.
struct RailFriction {
  double top = 0.3;     ///< rail top, tread contact [-]
  double flange = 0.3;  ///< gauge face, flange contact [-]

  /// The friction of a patch at `contact_angle` [rad]: the gauge face's from
  /// kFlangeContactAngle on (either sign: a flange-back contact is lubricated alike).
  double at(double contact_angle) const {
    const double angle = contact_angle < 0.0 ? -contact_angle : contact_angle;
    return angle >= kFlangeContactAngle ? flange : top;
  }
};

}  // namespace wheelwear::contactgeom
