#pragma once
// The default vehicle's wheelset: new S1002 wheels on 60E1 rails inclined 1:40, standard gauge,
// FASTSIM-SDEC creep forces (the project's default chain).

#include <array>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"

namespace wheelwear::vehicle::testing {

// `wheel` on `rail` (as it lies in the track), standard gauge.
inline WheelsetModel standard_wheelset(const profiles::Profile& wheel,
                                       const profiles::Profile& rail) {
  WheelsetModel model{
      {contactgeom::WheelRailPair(wheel, rail), contactgeom::WheelRailPair(wheel, rail)}};
  for (contactgeom::WheelRailPair* p : {&model.track.left, &model.track.right}) {
    p->wheel_radius = 0.46;
    p->youngs_modulus = 200e9;
    p->poisson = 0.25;
  }
  model.method = tangential::Method::fastsim_sdec;
  return model;
}

// `wheel` (default: a new S1002) on the default track.
inline WheelsetModel standard_wheelset(const profiles::Profile& wheel = profiles::s1002()) {
  profiles::Rail60E1Options rail_options;
  rail_options.inclination = 0.025;
  return standard_wheelset(wheel, profiles::rail_60e1(rail_options));
}

inline std::array<WheelsetModel, kWheelsets> four(const WheelsetModel& m) {
  return {m, m, m, m};
}

}  // namespace wheelwear::vehicle::testing
