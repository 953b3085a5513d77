// Tests of the arc-length curve: exactness on circular arcs, arc length, derivatives.

#include "wheelwear/profiles/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {
namespace {

// Cubic interpolation of a circle errs by about 5 h^4 kappa^3 / 384 = 2e-11 m for h = 0.25 mm and
// R = 13 mm; 1e-9 m leaves room for the end intervals and the two-stage construction.
constexpr double kArcTolerance = 1e-9;

PointList arc_points(const Point& centre, double radius, double from, double to, double spacing) {
  PointList points;
  const int n = static_cast<int>(std::ceil(radius * std::abs(to - from) / spacing));
  for (int k = 0; k <= n; ++k) {
    const double a = from + (to - from) * k / n;
    points.push_back(centre + radius * Point(std::cos(a), std::sin(a)));
  }
  return points;
}

TEST(ArcLengthCurve, IsExactOnACircularArc) {
  const Point centre(0.01, 0.02);
  const double R = 0.013;
  const ArcLengthCurve curve(arc_points(centre, R, -2.5, -0.4, 0.1e-3));
  EXPECT_NEAR(curve.length(), R * 2.1, kArcTolerance);
  for (double s = 0.0; s <= curve.length(); s += 1e-5) {
    ASSERT_NEAR((curve.position(s) - centre).norm(), R, kArcTolerance) << "s = " << s;
    // The parameter is the arc length: the point lies at angle -2.5 + s / R.
    const Point expected = centre + R * Point(std::cos(-2.5 + s / R), std::sin(-2.5 + s / R));
    ASSERT_NEAR((curve.position(s) - expected).norm(), 0.0, 10 * kArcTolerance);
    ASSERT_NEAR(curve.derivative(s).norm(), 1.0, 1e-6);
  }
  // Curvature 1/R: a cubic spline's second derivative errs by h^2 f''''/12 at its knots, which
  // for a circle sampled in arc length is (h/R)^2 / 12 = 3.1e-5 relative (h = 0.25 mm, R = 13
  // mm); at the ends, where not-a-knot acts, up to (h/R)^2 = 4e-4. Counter-clockwise means
  // turning from +y towards +z: positive.
  double worst = 0.0;
  for (double s = 0.0; s <= curve.length(); s += 1e-4) {
    const double error = std::abs(curve.signed_curvature(s) * R - 1.0);
    worst = std::max(worst, error);
    if (s > 0.005 && s < curve.length() - 0.005) {
      ASSERT_LT(error, 4e-5) << "s = " << s;
    }
  }
  EXPECT_LT(worst, 4e-4);
}

TEST(ArcLengthCurve, StraightLineHasZeroCurvatureAndUnitSpeed) {
  PointList line;
  for (int i = 0; i <= 100; ++i) line.emplace_back(0.001 * i, -0.0005 * i);
  const ArcLengthCurve curve(line, {0.0, 0.5e-3});
  EXPECT_NEAR(curve.length(), std::hypot(0.1, 0.05), 1e-15);
  for (double s = 0.0; s <= curve.length(); s += 0.003) {
    EXPECT_NEAR(curve.signed_curvature(s), 0.0, 1e-9);
    EXPECT_NEAR(curve.derivative(s)[0], 0.1 / std::hypot(0.1, 0.05), 1e-12);
  }
}

TEST(ArcLengthCurve, HandlesVerticalAndOverhangingStretches) {
  // Down a vertical face, then around a half circle that comes back under itself.
  PointList points;
  for (int i = 0; i < 40; ++i) points.emplace_back(0.0, -0.01 + 0.00025 * i);
  for (const Point& p : arc_points(Point(0.005, 0.0), 0.005, std::numbers::pi, 0.0, 0.2e-3))
    points.push_back(p);
  const ArcLengthCurve curve(points);
  EXPECT_NEAR(curve.length(), 0.01 + std::numbers::pi * 0.005, 1e-7);
  EXPECT_NEAR(curve.position(0.005)[0], 0.0, 1e-9);
  EXPECT_NEAR(curve.derivative(0.005)[1], 1.0, 1e-6);
}

TEST(ArcLengthCurve, SampleIncludesBothEnds) {
  const ArcLengthCurve curve(arc_points(Point(0, 0), 0.02, 0.0, 1.0, 0.2e-3));
  const PointList samples = curve.sample(0.7e-3);
  EXPECT_NEAR((samples.front() - Point(0.02, 0.0)).norm(), 0.0, kArcTolerance);
  EXPECT_NEAR((samples.back() - 0.02 * Point(std::cos(1.0), std::sin(1.0))).norm(), 0.0,
              kArcTolerance);
  for (std::size_t i = 1; i < samples.size(); ++i)
    EXPECT_LE((samples[i] - samples[i - 1]).norm(), 0.7e-3);
}

TEST(ArcLengthCurve, TranslationKeepsTheParametrisation) {
  const ArcLengthCurve curve(arc_points(Point(0, 0), 0.02, 0.0, 1.0, 0.2e-3));
  const ArcLengthCurve moved = curve.translated(Point(0.003, -0.001));
  for (double s = 0.0; s <= curve.length(); s += 1e-3)
    EXPECT_NEAR((moved.position(s) - curve.position(s) - Point(0.003, -0.001)).norm(), 0.0, 1e-15);
}

TEST(ArcLengthCurve, SmoothingLeavesASmoothArcAlone) {
  // The smoothing filter passes wavelengths far above 2 pi L: a 20 mm radius arc is a feature of
  // that size, so L = 0.3 mm changes it by far less than a micrometre.
  const ArcLengthCurve curve(arc_points(Point(0, 0), 0.02, 0.5, 2.0, 0.2e-3), {0.3e-3, 0.25e-3});
  for (double s = 0.005; s <= curve.length() - 0.005; s += 1e-4)
    EXPECT_NEAR(curve.position(s).norm(), 0.02, 1e-7);
}

TEST(ArcLengthCurve, RejectsTooFewOrRepeatedPoints) {
  EXPECT_THROW(ArcLengthCurve({Point(0, 0), Point(1, 0), Point(2, 0)}), InputError);
  EXPECT_THROW(ArcLengthCurve({Point(0, 0), Point(1, 0), Point(1, 0), Point(2, 0)}), InputError);
  EXPECT_THROW(ArcLengthCurve({Point(0, 0), Point(1, 0), Point(std::nan(""), 0), Point(2, 0)}),
               InputError);
  EXPECT_THROW(ArcLengthCurve({Point(0, 0), Point(1, 0), Point(2, 1), Point(3, 0)}, {-1.0, 1e-3}),
               InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
