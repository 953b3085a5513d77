// Tests of the one-dimensional cubic spline: exactness, end conditions, lookup, convergence.

#include "wheelwear/profiles/cubic_spline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {
namespace {

// Round-off of a tridiagonal solve over a few dozen knots on O(1) values.
constexpr double kRoundOff = 1e-11;

double cubic(double t) {
  return 0.5 - 1.25 * t + 0.75 * t * t + 0.3 * t * t * t;
}

TEST(CubicSpline, NotAKnotReproducesACubicOnUnevenKnots) {
  std::vector<double> t, v;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(0.05, 0.4);
  for (double x = -1.0; x < 2.0; x += step(random)) {
    t.push_back(x);
    v.push_back(cubic(x));
  }
  const CubicSpline spline = CubicSpline::interpolate(t, v);
  EXPECT_FALSE(spline.uniform());
  for (double x = t.front(); x <= t.back(); x += 0.013) {
    EXPECT_NEAR(spline.value(x), cubic(x), kRoundOff);
    EXPECT_NEAR(spline.derivative(x), -1.25 + 1.5 * x + 0.9 * x * x, kRoundOff);
    EXPECT_NEAR(spline.second_derivative(x), 1.5 + 1.8 * x, 1e-9);
  }
}

TEST(CubicSpline, NaturalSplineInterpolatesWithZeroEndCurvature) {
  const std::vector<double> t = {0.0, 0.3, 0.7, 1.0, 1.6, 2.0};
  const std::vector<double> v = {1.0, -0.5, 0.25, 2.0, 0.0, 1.0};
  const CubicSpline spline = CubicSpline::interpolate(t, v, CubicSpline::EndCondition::natural);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(spline.value(t[i]), v[i], kRoundOff);
  EXPECT_NEAR(spline.second_derivative(t.front()), 0.0, kRoundOff);
  EXPECT_NEAR(spline.second_derivative(t.back()), 0.0, kRoundOff);
  // C2 across an interior knot: both neighbouring polynomials give the same derivatives there.
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    EXPECT_NEAR(spline.derivative(t[i] - 1e-12), spline.derivative(t[i] + 1e-12), 1e-9);
    EXPECT_NEAR(spline.second_derivative(t[i] - 1e-12), spline.second_derivative(t[i] + 1e-12),
                1e-9);
  }
}

TEST(CubicSpline, ThreePointsGiveTheirParabola) {
  const std::vector<double> t = {0.0, 1.0, 3.0};
  const std::vector<double> v = {1.0, 0.0, 4.0};  // on (t - 1)^2
  const CubicSpline spline = CubicSpline::interpolate(t, v);
  for (double x = 0.0; x <= 3.0; x += 0.1)
    EXPECT_NEAR(spline.value(x), (x - 1) * (x - 1), kRoundOff);
}

TEST(CubicSpline, UniformLookupAgreesWithBinarySearch) {
  std::vector<double> t, v;
  for (int i = 0; i <= 400; ++i) {
    t.push_back(-0.07 + 0.00025 * i);
    v.push_back(std::sin(40.0 * t.back()));
  }
  const CubicSpline spline = CubicSpline::interpolate(t, v);
  ASSERT_TRUE(spline.uniform());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> where(t.front() - 0.01, t.back() + 0.01);
  for (int k = 0; k < 20000; ++k) {
    const double x = where(random);
    const auto expected = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin() - 1, 0,
                                   static_cast<std::ptrdiff_t>(t.size()) - 2));
    ASSERT_EQ(spline.locate(x), expected) << "t = " << x;
  }
  // The knots themselves fall into the interval they start.
  for (std::size_t i = 0; i + 1 < t.size(); ++i) ASSERT_EQ(spline.locate(t[i]), i);
}

TEST(CubicSpline, ErrorFallsWithTheFourthPowerOfTheSpacing) {
  auto max_error = [](int n) {
    std::vector<double> t, v;
    for (int i = 0; i <= n; ++i) {
      t.push_back(3.0 * i / n);
      v.push_back(std::sin(t.back()));
    }
    const CubicSpline spline = CubicSpline::interpolate(t, v);
    double error = 0.0;
    for (double x = 0.0; x <= 3.0; x += 0.0007)
      error = std::max(error, std::abs(spline.value(x) - std::sin(x)));
    return error;
  };
  // Halving h should divide an O(h^4) error by 16; 12 leaves room for the pre-asymptotic range.
  EXPECT_GT(max_error(20) / max_error(40), 12.0);
  EXPECT_GT(max_error(40) / max_error(80), 12.0);
}

TEST(CubicSpline, ShiftedAddsAConstant) {
  const std::vector<double> t = {0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> v = {0.0, 1.0, 0.0, 2.0, 1.0};
  const CubicSpline spline = CubicSpline::interpolate(t, v);
  const CubicSpline moved = spline.shifted(2.5);
  for (double x = 0.0; x <= 4.0; x += 0.1)
    EXPECT_NEAR(moved.value(x), spline.value(x) + 2.5, 1e-14);
}

TEST(CubicSpline, RejectsBadKnots) {
  const std::vector<double> two = {0.0, 1.0};
  const std::vector<double> one = {0.0};
  EXPECT_THROW(CubicSpline::interpolate(one, one), InputError);
  const std::vector<double> repeated = {0.0, 1.0, 1.0, 2.0};
  const std::vector<double> values = {0.0, 1.0, 2.0, 3.0};
  EXPECT_THROW(CubicSpline::interpolate(repeated, values), InputError);
  const std::vector<double> nan_knot = {0.0, std::nan(""), 2.0, 3.0};
  EXPECT_THROW(CubicSpline::interpolate(nan_knot, values), InputError);
  EXPECT_THROW(CubicSpline::interpolate(two, values), InputError);  // size mismatch
  EXPECT_NO_THROW(CubicSpline::interpolate(two, two));
}

}  // namespace
}  // namespace wheelwear::profiles
