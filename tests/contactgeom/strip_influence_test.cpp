// Strip influence integrals against tanh-sinh quadrature (Boost.Math) of their definitions. Nothing
// here uses elliptic integrals, so the reference is independent of the closed form under test.

#include "wheelwear/contactgeom/strip_influence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <numbers>

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

double rel(double a, double b) {
  return std::abs(a / b - 1.0);
}

// L(c, y) = int_{-c}^{c} sqrt(c^2 - x^2)/sqrt(x^2 + y^2) dx with x = |y| sinh(u), which
// removes the peak at x = 0: L = 2 int_0^asinh(c/|y|) sqrt(c^2 - y^2 sinh^2 u) du, smooth but
// for the square-root end point, which tanh-sinh handles.
double line_reference(double c, double y) {
  const double ay = std::abs(y);
  auto f = [c, ay](double u) {
    const double x = ay * std::sinh(u);
    return std::sqrt(std::max(0.0, (c - x) * (c + x)));
  };
  boost::math::quadrature::tanh_sinh<double> ts;
  return 2.0 * ts.integrate(f, 0.0, std::asinh(c / ay), 1e-14);
}

// S(c, y1, y2) = int_{y1}^{y2} L(c, y) dy with the y-integration done first, in closed form:
// int_{y1}^{y2} dy / sqrt(x^2 + y^2) = asinh(y2/|x|) - asinh(y1/|x|), written with logarithms
// that stay finite at the tiny |x| tanh-sinh samples. What remains is a 1-D integral over x
// with at worst a logarithmic singularity at x = 0, which tanh-sinh handles.
double strip_reference(double c, double y1, double y2) {
  auto log_term = [](double y, double x) { return std::log(y + std::hypot(x, y)); };
  auto f = [&](double x) {
    const double w = std::sqrt((c - x) * (c + x));
    double kernel;
    if (y1 >= 0.0) {
      kernel = log_term(y2, x) - log_term(y1, x);
    } else if (y2 <= 0.0) {
      kernel = log_term(-y1, x) - log_term(-y2, x);
    } else {
      kernel = log_term(y2, x) + log_term(-y1, x) - 2.0 * std::log(x);
    }
    return w * kernel;
  };
  boost::math::quadrature::tanh_sinh<double> ts;
  return 2.0 * ts.integrate(f, 0.0, c, 1e-14);
}

TEST(StripInfluence, LineInfluenceMatchesQuadrature) {
  const double c = 4e-3;
  for (double y : {1e-7, 1e-5, 1e-4, 1e-3, 4e-3, 2e-2, 0.3}) {
    // Hastings' approximation of K - E (1.4e-8 relative) bounds the accuracy.
    EXPECT_LT(rel(line_influence(c, y), line_reference(c, y)), 1.5e-8) << y;
    EXPECT_DOUBLE_EQ(line_influence(c, -y), line_influence(c, y));
  }
  // Far field: a line load pi c^2/2 per unit pressure at distance y.
  EXPECT_LT(rel(line_influence(c, 10.0), 0.5 * kPi * c * c / 10.0), 1e-6);
  EXPECT_EQ(line_influence(0.0, 1e-3), 0.0);
}

struct StripCase {
  double c, y1, y2, tolerance;
};

TEST(StripInfluence, StripIntegralMeetsItsDocumentedAccuracy) {
  const double w = 1e-4;  // 0.1 mm strips
  const StripCase cases[] = {
      // Strips holding the field point, centred and off-centre: closed-form expansion.
      {4e-3, -0.5 * w, 0.5 * w, 1e-7},
      {4e-3, -0.1 * w, 0.9 * w, 1e-7},
      {4e-3, -1e-9, w - 1e-9, 1e-7},
      // Neighbours within two widths: difference of integrals from the field point.
      {4e-3, 0.5 * w, 1.5 * w, 1e-7},
      {4e-3, 1e-12, w, 1e-7},
      {4e-3, -2.5 * w, -1.5 * w, 1e-7},
      // Either side of the switch from the closed-form expansion to quadrature at c/8.
      {4e-3, -0.5 * w, 0.5e-3 * (1.0 - 1e-9), 1e-7},
      {4e-3, -0.5 * w, 0.5e-3 * (1.0 + 1e-9), 1e-7},
      // 2 to 4 widths: three-point, 4 to 8 widths: two-point Gauss.
      {4e-3, 3.0 * w, 4.0 * w, 1e-6},
      {4e-3, 7.5 * w, 8.5 * w, 1e-6},
      // Farther: midpoint, (w/y)^2/12 relative.
      {4e-3, 8.5 * w, 9.5 * w, 1.3e-3},
      {4e-3, 40 * w, 41 * w, 1e-4},
      // Short strips (x_l < w, patch edges): graded Gauss-Legendre beyond c/8.
      {2e-5, -0.5 * w, 0.5 * w, 1e-7},
      {2e-5, 0.5 * w, 1.5 * w, 1e-7},
      {1e-6, 30 * w, 31 * w, 1.3e-3},
  };
  for (const StripCase& s : cases) {
    SCOPED_TRACE(::testing::Message() << "c=" << s.c << " y1=" << s.y1 << " y2=" << s.y2);
    const double ref = strip_reference(s.c, s.y1, s.y2);
    EXPECT_LT(rel(strip_influence(s.c, s.y1, s.y2), ref), s.tolerance);
  }
}

TEST(StripInfluence, SumOverACircularPatchGivesTheHertzIntegral) {
  // int int_circle sqrt(a^2 - r^2)/r dA = pi^2 a^2 / 2; with x_l(s) = sqrt(a^2 - s^2) sampled at
  // strip centres the strip model differs from the circle by O(ds^1.5) at its lateral edges.
  const double a = 5e-3;
  double previous_error = 1.0;
  for (int n : {50, 100, 200, 400}) {
    const double ds = 2.0 * a / n;
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
      const double s = -a + (j + 0.5) * ds;
      sum += strip_influence(std::sqrt(a * a - s * s), s - 0.5 * ds, s + 0.5 * ds);
    }
    const double error = rel(sum, 0.5 * kPi * kPi * a * a);
    EXPECT_LT(error, 2.0 * std::pow(1.0 / n, 1.5)) << n;  // 2 (ds/(2a))^1.5
    EXPECT_LT(error, previous_error) << n;
    previous_error = error;
  }
}

}  // namespace
}  // namespace wheelwear::contactgeom
