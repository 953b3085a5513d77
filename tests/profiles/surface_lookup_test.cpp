// Tests of z(y) on curves, against a brute-force search over all branches.

#include "wheelwear/profiles/surface_lookup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace wheelwear::profiles {
namespace {

// Every crossing of the vertical line at y with the curve, by bisection between knot-spaced
// samples: independent of the lookup's pieces, buckets and Newton steps.
std::vector<double> crossings(const ArcLengthCurve& curve, double y) {
  std::vector<double> z;
  const double step = curve.knot_spacing() / 8.0;
  for (double s = 0.0; s < curve.length(); s += step) {
    double a = s, b = std::min(s + step, curve.length());
    double fa = curve.position(a)[0] - y, fb = curve.position(b)[0] - y;
    if (fa == 0.0) {
      z.push_back(curve.position(a)[1]);
      continue;
    }
    if ((fa > 0) == (fb > 0)) continue;
    for (int i = 0; i < 100; ++i) {
      const double m = 0.5 * (a + b), fm = curve.position(m)[0] - y;
      if ((fm > 0) == (fa > 0)) {
        a = m;
        fa = fm;
      } else {
        b = m;
      }
    }
    z.push_back(curve.position(0.5 * (a + b))[1]);
  }
  return z;
}

TEST(SurfaceLookup, MatchesTheCurveOnAGraph) {
  PointList points;
  for (int i = 0; i <= 600; ++i) {
    const double y = -0.06 + 0.0002 * i;
    points.emplace_back(y, 0.002 * std::sin(y / 0.01) + 0.5 * y * y);
  }
  const ArcLengthCurve curve(points);
  const SurfaceLookup lookup(curve, SurfaceLookup::Envelope::max_z);
  EXPECT_NEAR(lookup.y_min(), -0.06, 1e-12);
  EXPECT_NEAR(lookup.y_max(), 0.06, 1e-12);
  std::mt19937 random(2);
  std::uniform_real_distribution<double> where(-0.06, 0.06);
  for (int k = 0; k < 500; ++k) {
    const double y = where(random);
    const auto sample = lookup.at(y);
    ASSERT_TRUE(sample);
    const auto z = crossings(curve, y);
    ASSERT_EQ(z.size(), 1u);
    // Both solve y(s) = y to round-off on the same spline.
    EXPECT_NEAR(sample->z, z.front(), 1e-13);
    EXPECT_NEAR(curve.position(sample->s)[0], y, 1e-13);
    const Point d = curve.derivative(sample->s);
    EXPECT_NEAR(sample->dz_dy, d[1] / d[0], 1e-9);
  }
  EXPECT_FALSE(lookup.at(-0.0601));
  EXPECT_FALSE(lookup.at(0.0601));
  EXPECT_FALSE(lookup.at(std::nan("")));
}

TEST(SurfaceLookup, PicksTheBranchFacingTheMatingBody) {
  // An S-shaped overhang: along +y, back under itself, then along +y again.
  PointList points;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.01 * i;  // 0 ... 1
    const double y = 0.02 * t - 0.012 * std::sin(2 * std::numbers::pi * t);
    const double z = 0.01 * std::sin(std::numbers::pi * t);
    points.emplace_back(y, z);
  }
  const ArcLengthCurve curve(points);
  const SurfaceLookup highest(curve, SurfaceLookup::Envelope::max_z);
  const SurfaceLookup lowest(curve, SurfaceLookup::Envelope::min_z);
  EXPECT_GT(highest.piece_count(), curve.segment_count());  // turning points split intervals
  int multi = 0;
  // From just inside the extremes: at the turning points themselves y(s) only touches the line.
  for (double y = highest.y_min() + 1e-7; y <= highest.y_max() - 1e-7; y += 1e-4) {
    const auto z = crossings(curve, y);
    ASSERT_FALSE(z.empty());
    if (z.size() > 1) ++multi;
    EXPECT_NEAR(highest.at(y)->z, *std::max_element(z.begin(), z.end()), 1e-12) << y;
    EXPECT_NEAR(lowest.at(y)->z, *std::min_element(z.begin(), z.end()), 1e-12) << y;
  }
  EXPECT_GT(multi, 10);  // the test did visit the overhang
}

}  // namespace
}  // namespace wheelwear::profiles
