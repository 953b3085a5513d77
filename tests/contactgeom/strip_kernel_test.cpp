// The inline kernels behind the strip influence integrals: the fast logarithm, and the series
// that replaces quadrature next to the field point.

#include "strip_kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace wheelwear::contactgeom::detail {
namespace {

TEST(StripKernel, FastLogMatchesStdLog) {
  // Truncated atanh series: < 4e-13 absolute on the mantissa's logarithm; the exponent part is
  // exact up to rounding of e ln 2.
  double worst = 0.0;
  for (double x = 1e-300; x < 1e300; x *= 1.37) {
    worst =
        std::max(worst, std::abs(fast_log(x) - std::log(x)) / std::max(1.0, std::abs(std::log(x))));
  }
  for (double x = 0.5; x < 2.0; x += 1e-4) {
    worst = std::max(worst, std::abs(fast_log(x) - std::log(x)));
  }
  EXPECT_LT(worst, 5e-13);
  EXPECT_EQ(fast_log(1.0), 0.0);
  // Outside the normal range it defers to std::log.
  EXPECT_EQ(fast_log(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(fast_log(1e-310), std::log(1e-310));
}

TEST(StripKernel, ExpansionAndQuadratureAgreeAtTheirSwitch) {
  // G(u) switches from the closed-form expansion (u <= c/8) to quadrature; both are accurate
  // to ~1e-9 there, so G is continuous across the switch to that level.
  const double c = 4e-3;
  const double below = integral_from_zero(c, 0.125 * c);
  const double above = integral_from_zero(c, std::nextafter(0.125 * c, 1.0));
  EXPECT_NEAR(above / below, 1.0, 1e-8);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
