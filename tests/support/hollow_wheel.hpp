#pragma once
// A hollow-worn wheel whose tread has worn into the shape of its rail: new S1002 with its tread
// hollowed by `depth` where, centred on 60E1 1:40, it comes within that depth of the rail, so
// that the worn tread follows the rail's head up to a residual gap t^2 / (2 relative_radius)
// about the new wheel's contact point (t the lateral offset from it). Heavy-haul wheels wear so
// (a hollow of 2-3 mm; patches up to 35 mm wide); with depth 2 mm and 3 m it carries 150 kN
// on a patch 37 mm wide at the centred position (Hertz-calibrated strips; 34 mm with
// Kik-Piotrowski's fixed 0.55).

#include <algorithm>
#include <cmath>
#include <vector>

#include "wheelwear/contactgeom/undeformed_distance.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/wear_update.hpp"

namespace wheelwear::testing {

inline profiles::Profile hollow_worn_s1002(double depth = 2e-3, double relative_radius = 3.0) {
  const profiles::Profile wheel = profiles::s1002();
  const contactgeom::WheelRailPair pair(wheel, profiles::rail_60e1());
  const contactgeom::WheelsetPose centred;
  const contactgeom::WheelRailContact c = contactgeom::solve_wheel_rail(pair, centred, 55e3);
  // O in each profile's frame (+y towards the field side); at a fixed pose the wheel's y and
  // the rail's differ by a constant.
  const double wheel_O = -c.patches.at(0).y_wheel;
  const double rail_O = -c.patches.at(0).y_rail;
  profiles::WearDepth wear;
  std::vector<double> gap;
  for (double t = -45e-3; t <= 45e-3; t += 0.25e-3) {
    const auto d = contactgeom::undeformed_distance(pair, centred, 0.0, rail_O + t);
    if (!d) continue;
    wear.y.push_back(wheel_O + t);
    gap.push_back(*d);
  }
  const double least = *std::min_element(gap.begin(), gap.end());
  for (std::size_t k = 0; k < gap.size(); ++k) {
    const double t = wear.y[k] - wheel_O;
    const double residual = t * t / (2.0 * relative_radius);
    wear.depth.push_back(std::max(0.0, depth + residual - (gap[k] - least)));
  }
  return profiles::apply_wear(wheel, wear);
}

}  // namespace wheelwear::testing
