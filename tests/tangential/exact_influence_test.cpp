// Influence coefficients of a uniformly loaded rectangle against closed forms that do not use
// the corner-sum integrals: the centre of a square (Love 1929, by polar integration) and the
// point-load solutions of Boussinesq and Cerruti far from the rectangle (Johnson 1985, 3.86).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/tangential/exact/influence.hpp"

namespace wheelwear::tangential {
namespace {

constexpr double kPi = std::numbers::pi;
// Closed forms evaluated in double precision: only rounding separates them from the code.
constexpr double kRounding = 1e-12;

// int over the square [-c, c]^2 of 1/r = 8 c ln(1 + sqrt 2) (polar coordinates; Love 1929).
double square_integral(double c) {
  return 8.0 * c * std::log(1.0 + std::sqrt(2.0));
}

TEST(ExactInfluence, CentreOfASquareMatchesLovesClosedForm) {
  for (const double nu : {0.0, 0.25, 0.5}) {
    const Material m{80e9, nu};
    const double c = 0.3e-3;
    const InfluenceCoefficients k = rectangle_influence(-c, c, -c, c, m);
    const double i1 = square_integral(c);
    // u_n = (1 - nu)/(pi G) int 1/r; by symmetry int x^2/r^3 = int y^2/r^3 = (1/2) int 1/r.
    EXPECT_NEAR(k.nn, (1.0 - nu) / (kPi * m.G) * i1, kRounding * k.nn) << "nu " << nu;
    EXPECT_NEAR(k.xx, (1.0 - 0.5 * nu) / (kPi * m.G) * i1, kRounding * k.xx) << "nu " << nu;
    EXPECT_NEAR(k.yy, k.xx, kRounding * k.xx);
    EXPECT_NEAR(k.xy, 0.0, kRounding * k.xx);  // odd in x and in y
  }
}

TEST(ExactInfluence, FarFieldApproachesThePointLoadSolutions) {
  const Material m{80e9, 0.3};
  const double h = 0.1e-3;  // element side
  // A source 40 elements away: the rectangle differs from a point load by O((h/r)^2) ~ 1e-4.
  constexpr double kFarField = 2e-4;
  for (const auto& [x, y] : {std::pair{40 * h, 0.0}, {0.0, 40 * h}, {28 * h, 28 * h}}) {
    const InfluenceCoefficients k =
        rectangle_influence(x - 0.5 * h, x + 0.5 * h, y - 0.5 * h, y + 0.5 * h, m);
    const double r = std::hypot(x, y), area = h * h, s = area / (kPi * m.G);
    EXPECT_NEAR(k.nn, s * (1.0 - m.nu) / r, kFarField * k.nn);
    EXPECT_NEAR(k.xx, s * ((1.0 - m.nu) / r + m.nu * x * x / (r * r * r)), kFarField * k.xx);
    EXPECT_NEAR(k.yy, s * ((1.0 - m.nu) / r + m.nu * y * y / (r * r * r)), kFarField * k.yy);
    EXPECT_NEAR(k.xy, s * m.nu * x * y / (r * r * r), kFarField * k.xx);
  }
}

TEST(ExactInfluence, CouplingIsOddInEachCoordinate) {
  const Material m{80e9, 0.25};
  const double h = 0.1e-3;
  const InfluenceCoefficients a = rectangle_influence(h, 2 * h, h, 2 * h, m);
  const InfluenceCoefficients b = rectangle_influence(-2 * h, -h, h, 2 * h, m);
  EXPECT_GT(a.xy, 0.0);
  EXPECT_NEAR(a.xy, -b.xy, kRounding * a.xx);
  EXPECT_NEAR(a.xx, b.xx, kRounding * a.xx);
}

}  // namespace
}  // namespace wheelwear::tangential
