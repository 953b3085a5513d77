// Kalker's linear theory recomputed with the exact theory: C11, C22, C23 of ellipses at
// vanishing creepage (no slip) against Kalker's table (Kalker 1990, Table E.3, as stored in
// kalker_coefficients.cpp) for nu = 0, 0.25, 0.5 and a/b = 0.2 ... 5.
//
// Grids: square elements, 12 and 24 of them across the short axis of the ellipse. The
// coefficient of each grid is normalised by the area of its contact elements (the grid's
// ellipse is the set of element centres inside the ellipse, whose area scatters by up to 2 %
// about pi a b), and the two grids are extrapolated to zero element size assuming first-order
// convergence (Richardson: C = 2 C(h/2) - C(h)); the discretisation (backward difference in
// the rolling direction) is first order. Measured, the extrapolation reaches Kalker's table
// within 0.9 % for a/b <= 2 and within 1.6 % at a/b = 5, against 1.4 ... 2.2 % for the finer
// grid alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"

namespace wheelwear::tangential {
namespace {

struct Coefficients {
  double c11, c22, c23;
};

// C11 = -Fx/(G c^2 vx), C22 = -Fy/(G c^2 vy), C23 = -Fy/(G c^3 phi) with c^2 = A/pi, A the
// area of the grid's contact elements. Friction is made large enough that nothing slips.
Coefficients exact_coefficients(double a_over_b, double nu, int nx, int ny) {
  const double a = 4.25e-3, b = a / a_over_b;
  const Material material{80e9, nu};
  const ContactLoad load{1e4, 1e6};
  SdecGridOptions options;
  options.nx = nx;
  options.ny = ny;
  const contactgeom::Sdec ellipse{a, b, 0.0};
  const double creep = 1e-6;
  const double c0 = std::sqrt(a * b);
  const ExactSolution fx = exact_sdec(ellipse, {creep, 0, 0}, load, material, options);
  const ExactSolution fy = exact_sdec(ellipse, {0, creep, 0}, load, material, options);
  const ExactSolution fs = exact_sdec(ellipse, {0, 0, creep / c0}, load, material, options);
  EXPECT_EQ(fx.slip_elements + fy.slip_elements + fs.slip_elements, 0);
  EXPECT_EQ(fs.status, ExactStatus::converged);
  const double c = std::sqrt(fx.contact_elements * fx.grid.area() / std::numbers::pi);
  const double g = material.G;
  return {-fx.forces.Fx / (g * c * c * creep), -fy.forces.Fy / (g * c * c * creep),
          -fs.forces.Fy / (g * c * c * c * creep / c0)};
}

Coefficients extrapolated(double a_over_b, double nu) {
  constexpr int kShort = 12;  // elements across the short axis of the coarse grid
  const double ratio = std::max(a_over_b, 1.0 / a_over_b);
  const int n_long = static_cast<int>(std::lround(kShort * ratio));
  const int nx = a_over_b >= 1.0 ? n_long : kShort, ny = a_over_b >= 1.0 ? kShort : n_long;
  const Coefficients coarse = exact_coefficients(a_over_b, nu, nx, ny);
  const Coefficients fine = exact_coefficients(a_over_b, nu, 2 * nx, 2 * ny);
  return {2 * fine.c11 - coarse.c11, 2 * fine.c22 - coarse.c22, 2 * fine.c23 - coarse.c23};
}

class ExactLinearTheory : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(ExactLinearTheory, ReproducesKalkersTable) {
  const auto [a_over_b, nu] = GetParam();
  const Coefficients c = extrapolated(a_over_b, nu);
  const KalkerCoefficients k = kalker_coefficients(a_over_b, nu);
  // 1 % for a/b <= 2. For slender ellipses the converged discrete theory itself lies up to
  // 1.6 % above the table (CONTACT at b/a = 0.1 on 120 x 120 and 160 x 80 grids,
  // tests/data/contact/README.md section 4), hence 1.6 % at a/b = 5.
  const double tolerance = a_over_b <= 2.0 ? 0.01 : 0.016;
  EXPECT_NEAR(c.c11 / k.c11, 1.0, tolerance) << "C11 " << c.c11 << " Kalker " << k.c11;
  EXPECT_NEAR(c.c22 / k.c22, 1.0, tolerance) << "C22 " << c.c22 << " Kalker " << k.c22;
  EXPECT_NEAR(c.c23 / k.c23, 1.0, tolerance) << "C23 " << c.c23 << " Kalker " << k.c23;
  RecordProperty("C11_rel", std::to_string(c.c11 / k.c11 - 1));
  RecordProperty("C22_rel", std::to_string(c.c22 / k.c22 - 1));
  RecordProperty("C23_rel", std::to_string(c.c23 / k.c23 - 1));
}

INSTANTIATE_TEST_SUITE_P(EllipticitiesAndPoissonRatios, ExactLinearTheory,
                         ::testing::Combine(::testing::Values(0.2, 0.5, 1.0, 2.0, 5.0),
                                            ::testing::Values(0.0, 0.25, 0.5)));

}  // namespace
}  // namespace wheelwear::tangential
