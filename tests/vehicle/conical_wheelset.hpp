#pragma once
// A wheelset of conical wheels (profiles::conical_wheel) on 60E1 rails without inclination,
// with Kalker's linear creep theory on the equivalent ellipse: the textbook wheelset of linear
// curving theory.

#include "wheelwear/profiles/conical_wheel.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle::testing {

inline constexpr double kNominalRadius = 0.46;  // [m]

inline WheelsetModel conical_wheelset(double conicity) {
  profiles::ConicalWheelOptions cone;
  cone.conicity = conicity;
  cone.nominal_radius = kNominalRadius;
  const profiles::Profile wheel = profiles::conical_wheel(cone);
  profiles::Rail60E1Options rail_options;
  rail_options.inclination = 0.0;
  const profiles::Profile rail = profiles::rail_60e1(rail_options);
  WheelsetModel model{
      {contactgeom::WheelRailPair(wheel, rail), contactgeom::WheelRailPair(wheel, rail)}};
  model.method = tangential::Method::linear_sdec;  // Kalker's linear creep on the ellipse
  model.ellipse_at_O = true;
  model.material = {80e9, 0.25};
  return model;
}

}  // namespace wheelwear::vehicle::testing
