// The SDEC coefficients of Liu, Fu & Bruni 2022 (Table 1: K13, B11, B22, B23, nu = 0.25)
// recomputed with the exact theory on SDEC patches, fitted as CONTACT's reference data were
// (tests/data/contact/README.md): K13 by least squares of C13s = -K13 psi and the B's by least
// squares of Cs(psi) - Cs(0) = B psi^2, over psi = 0.2, 0.4, 0.6, 0.8 (the negative psi give
// the same equations by symmetry), on 40 x 40 grids.

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/wear/exact/steady_rolling.hpp"
#include "wheelwear/wear/sdec_coefficients.hpp"

namespace wheelwear::wear {
namespace {

struct Linear {
  double c11, c22, c23, c13;
};

// Eq. 9 of the paper: C11s = -Fx/(G c^2 vx), C22s = -Fy/(G c^2 vy), C23s = -Fy/(G c^3 phi),
// C13s = -Fx/(G c^3 phi), creepages at O, no slip.
Linear sdec_linear(double a_over_b, double psi) {
  const double a = 4.25e-3, b = a / a_over_b, c = std::sqrt(a * b), creep = 1e-6;
  const Material material{80e9, 0.25};
  const ContactLoad load{1e4, 1e6};
  ExactOptions options;
  options.nx = options.ny = 40;
  const contactgeom::Sdec patch{a, b, psi};
  const ExactSolution fx = exact_sdec(patch, {creep, 0, 0}, load, material, options);
  const ExactSolution fy = exact_sdec(patch, {0, creep, 0}, load, material, options);
  const ExactSolution fs = exact_sdec(patch, {0, 0, creep / c}, load, material, options);
  const double gc2 = material.G * c * c * creep;
  return {-fx.forces.Fx / gc2, -fy.forces.Fy / gc2, -fs.forces.Fy / gc2, -fs.forces.Fx / gc2};
}

class ExactSdecCoefficients : public ::testing::TestWithParam<double> {};

TEST_P(ExactSdecCoefficients, ReproduceTable1) {
  const double g = GetParam();
  const Linear base = sdec_linear(g, 0.0);
  double k13 = 0, b11 = 0, b22 = 0, b23 = 0, s2 = 0, s4 = 0;
  for (const double psi : {0.2, 0.4, 0.6, 0.8}) {
    const Linear l = sdec_linear(g, psi);
    k13 -= l.c13 * psi;
    b11 += (l.c11 - base.c11) * psi * psi;
    b22 += (l.c22 - base.c22) * psi * psi;
    b23 += (l.c23 - base.c23) * psi * psi;
    s2 += psi * psi;
    s4 += psi * psi * psi * psi;
  }
  k13 /= s2;
  b11 /= s4;
  b22 /= s4;
  b23 /= s4;
  const SdecTableRow t = sdec_table_row(g, 0.25);
  // K13: 40 x 40 against 80 x 80 changes C13s by < 0.7 % (and 80 x 80 against 120 x 120 by
  // < 0.6 %, README section 4); the paper's value at a/b = 2 is itself 0.5 % below CONTACT's
  // 80 x 80 fit: 1.5 %.
  EXPECT_NEAR(k13 / t.k13, 1.0, 0.015) << "K13 " << k13 << " paper " << t.k13;
  // The B's are differences of nearly equal coefficients: CONTACT's 80 x 80 fit agrees with
  // the paper to +-0.007 for a/b <= 1 and lies 0.009 ... 0.012 above it at a/b = 2 (README
  // section 4); the 40 x 40 grid adds up to 0.005.
  const double tolerance = g <= 1.0 ? 0.01 : 0.02;
  EXPECT_NEAR(b11, t.b11, tolerance) << "B11";
  EXPECT_NEAR(b22, t.b22, tolerance) << "B22";
  EXPECT_NEAR(b23, t.b23, tolerance) << "B23";
  RecordProperty("K13", std::to_string(k13));
  RecordProperty("B11", std::to_string(b11));
  RecordProperty("B22", std::to_string(b22));
  RecordProperty("B23", std::to_string(b23));
}

INSTANTIATE_TEST_SUITE_P(Ellipticities, ExactSdecCoefficients, ::testing::Values(0.5, 1.0, 2.0));

}  // namespace
}  // namespace wheelwear::wear
