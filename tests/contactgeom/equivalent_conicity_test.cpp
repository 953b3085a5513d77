// Equivalent conicity (EN 15302, Annex C) against the closed form of a conical wheel.

#include "wheelwear/contactgeom/equivalent_conicity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::contactgeom {
namespace {

// A conical tread of slope `lambda` (radius falling towards the field side), 130 mm wide, with
// the taping line at y = 0 and the flange back 70 mm from it, as S1002.
contactgeom::WheelRailPair cone_pair(double lambda) {
  profiles::PointList points;
  for (double y = -0.070; y <= 0.060 + 1e-12; y += 0.5e-3) points.emplace_back(y, -lambda * y);
  profiles::Profile wheel(points, {"cone", profiles::Body::wheel, profiles::Side::left, 0.46});
  return contactgeom::WheelRailPair(wheel, profiles::rail_60e1());
}

TEST(EquivalentConicity, ConeGivesItsSlope) {
  // On a cone, the contact stays where the rail's slope equals the cone's, so the rolling radius
  // changes by lambda per unit shift on each wheel: Delta r = 2 lambda y, tan(gamma_e) = lambda.
  for (double lambda : {0.05, 0.1}) {
    const auto pair = cone_pair(lambda);
    const RollingRadiusDifference dr = rolling_radius_difference(pair, pair, 4e-3, 41);
    for (std::size_t i = 0; i < dr.dy.size(); ++i) {
      // The contact point is located on the 0.1 mm strips of the gap: within half a strip on
      // each wheel, so Delta r within 2 lambda * 0.05 mm (plus the interpolation's rounding).
      EXPECT_NEAR(dr.delta_r[i], 2.0 * lambda * dr.dy[i], 2.0 * lambda * 0.06e-3) << dr.dy[i];
    }
    // The strip error averages over the cycle; 1 % of lambda is 1/60 of a strip over 3 mm.
    EXPECT_NEAR(equivalent_conicity(dr, 3e-3), lambda, 0.01 * lambda);
  }
}

TEST(EquivalentConicity, LinearRegressionOfAKnownFunction) {
  // Delta r = 2 k y + c y^3: over y = A sin t, the least-squares slope is
  // 2k + c A^2 (sum sin^4 / sum sin^2) = 2k + (3/4) c A^2.
  RollingRadiusDifference f;
  const double k = 0.15, c = 400.0, amplitude = 3e-3;
  for (int i = -100; i <= 100; ++i) {
    const double y = i * 5e-5;
    f.dy.push_back(y);
    f.delta_r.push_back(2 * k * y + c * y * y * y);
  }
  const double expected = k + 0.375 * c * amplitude * amplitude;
  // Linear interpolation of a cubic on 0.05 mm steps: relative error below 1e-4.
  EXPECT_NEAR(equivalent_conicity(f, amplitude), expected, 1e-4 * expected);
}

TEST(EquivalentConicity, S1002On60E1IsOddAndPlausible) {
  const contactgeom::WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  const RollingRadiusDifference dr = rolling_radius_difference(pair, pair, 3e-3, 31);
  // Left and right are mirror images: Delta r(-y) = -Delta r(y) exactly.
  for (std::size_t i = 0; i < dr.dy.size(); ++i)
    EXPECT_DOUBLE_EQ(dr.delta_r[i], -dr.delta_r[dr.dy.size() - 1 - i]);
  const double conicity = equivalent_conicity(dr, 3e-3);
  // New S1002 on 60E1 1:40 at 1435/1360 mm is known as a moderate-conicity pair (0.1 ... 0.3).
  EXPECT_GT(conicity, 0.1);
  EXPECT_LT(conicity, 0.3);
  // An amplitude beyond the sampled shifts is not extrapolated.
  EXPECT_TRUE(std::isnan(equivalent_conicity(dr, 4e-3)));
}

}  // namespace
}  // namespace wheelwear::contactgeom
