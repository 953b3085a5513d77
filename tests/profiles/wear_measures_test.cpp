// The worn depth along the original's normal and the change of rolling radius, against
// concentric arcs (closed forms), and against a wear depth applied by apply_wear.

#include "wheelwear/profiles/wear_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/wear_update.hpp"

namespace wheelwear::profiles {
namespace {

// A wheel tread that is one circular arc of radius R about (0, zc - R): convex towards +z, so
// its outward normal is radial. Points 0.5 mm apart, +-0.3 rad.
Profile arc_wheel(double R, double zc) {
  PointList points;
  const int n = static_cast<int>(std::ceil(0.3 * R / 0.5e-3));
  for (int k = -n; k <= n; ++k) {
    const double a = 0.3 * k / n;
    points.emplace_back(R * std::sin(a), zc - R + R * std::cos(a));
  }
  return Profile(points, {"arc", Body::wheel, Side::right, 0.46}, {0.0, 0.1e-3});
}

TEST(WearMeasures, ConcentricArcsAreWornByTheDifferenceOfRadiiEverywhere) {
  const double R = 0.1, d = 0.8e-3;
  const Profile original = arc_wheel(R, 0.0), worn = arc_wheel(R - d, -d);  // same centre
  const NormalWear w = normal_wear(original, worn);
  ASSERT_EQ(w.s.size(),
            static_cast<std::size_t>(std::floor(original.length() / 0.1e-3 + 1e-9)) + 1);
  int compared = 0;
  for (std::size_t i = 0; i < w.s.size(); ++i) {
    // The worn arc is shorter: normals from the original's last 0.25 mm of either end miss it.
    const double a = w.s[i] / R - 0.3;
    if (std::abs(a) > 0.3 - 0.25e-3 / R) continue;
    // Radial, so exactly d; the splines through points 0.5 mm apart on R 0.1 m are off by
    // (h^4 / R^3 scale) far below 1e-8 m.
    ASSERT_NEAR(w.depth[i], d, 1e-8) << "s " << w.s[i];
    ++compared;
  }
  EXPECT_GT(compared, 500);

  const RadiusChange r = radius_change(original, worn);
  compared = 0;
  for (std::size_t i = 0; i < r.y.size(); ++i) {
    const double y = r.y[i];
    ASSERT_NEAR(y / 0.1e-3, std::round(y / 0.1e-3), 1e-9);  // on the fixed grid
    if (std::abs(y) >= (R - d) * std::sin(0.3)) {
      EXPECT_TRUE(std::isnan(r.delta[i]) || std::abs(y) < worn.y_max()) << y;
      continue;
    }
    const double expected =
        (-d - (R - d) + std::sqrt((R - d) * (R - d) - y * y)) - (-R + std::sqrt(R * R - y * y));
    ASSERT_NEAR(r.delta[i], expected, 1e-8) << "y " << y;
    ++compared;
  }
  EXPECT_GT(compared, 500);
}

TEST(WearMeasures, AWearDepthAppliedAlongTheNormalIsMeasuredBack) {
  // 0.5 mm worn over the tread by apply_wear (which moves the knots along the inward normal)
  // reads back as 0.5 mm where the tread is straight enough that the normals do not fan out.
  const Profile wheel = s1002();
  WearDepth depth;
  for (double y = -0.02; y <= 0.05; y += 1e-3) {
    depth.y.push_back(y);
    depth.depth.push_back(0.5e-3);
  }
  WearUpdateOptions no_smoothing;
  no_smoothing.smoothing_length = 0.0;
  const Profile worn = apply_wear(wheel, depth, no_smoothing);
  const NormalWear w = normal_wear(wheel, worn);
  int compared = 0;
  for (std::size_t i = 0; i < w.s.size(); ++i) {
    const double y = wheel.position(w.s[i]).x();
    if (y < -0.015 || y > 0.045) continue;
    // The knots move exactly 0.5 mm; between them the re-interpolated curve follows to the
    // interpolation error of 0.5 mm knot spacing on the tread's curvature (< 1 um).
    ASSERT_NEAR(w.depth[i], 0.5e-3, 1e-6) << "y " << y;
    ++compared;
  }
  EXPECT_GT(compared, 500);
  // Nothing worn beyond the flange root: depth 0 there.
  for (std::size_t i = 0; i < w.s.size(); ++i) {
    const double y = wheel.position(w.s[i]).x();
    if (y < -0.045 && y > -0.06) ASSERT_NEAR(w.depth[i], 0.0, 1e-7) << "y " << y;
  }
}

}  // namespace
}  // namespace wheelwear::profiles
