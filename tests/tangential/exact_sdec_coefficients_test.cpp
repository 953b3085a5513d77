// The SDEC coefficients of Liu, Fu & Bruni 2022 (Table 1: K13, B11, B22, B23, nu = 0.25)
// recomputed with the exact theory on SDEC patches, fitted as CONTACT's reference data were
// (tests/data/contact/README.md): K13 by least squares of C13s = -K13 psi and the B's by least
// squares of Cs(psi) - Cs(0) = B psi^2, over psi = 0.2, 0.4, 0.6, 0.8 (the negative psi give
// the same equations by symmetry), on 40 x 40 grids.

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/tangential/exact/sdec_fit.hpp"
#include "wheelwear/tangential/sdec_coefficients.hpp"

namespace wheelwear::tangential {
namespace {

class ExactSdecCoefficients : public ::testing::TestWithParam<double> {};

TEST_P(ExactSdecCoefficients, ReproduceTable1) {
  const double g = GetParam();
  SdecGridOptions options;
  options.nx = options.ny = 40;
  constexpr double kPsi[] = {0.2, 0.4, 0.6, 0.8};
  const SdecCoefficientFit fit = fit_sdec_coefficients(g, {80e9, 0.25}, options, kPsi);
  EXPECT_TRUE(fit.clean);
  const double k13 = fit.k13, b11 = fit.b11, b22 = fit.b22, b23 = fit.b23;
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
}  // namespace wheelwear::tangential
