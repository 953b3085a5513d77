// Complete elliptic integrals by the AGM against Carlson's symmetric forms as implemented in
// Boost.Math (an independent algorithm: duplication instead of the AGM), taken with the
// complementary modulus itself so that no precision is lost in forming k:
// K = RF(0, k'^2, 1), K - E = k^2/3 RD(0, k'^2, 1), E - k'^2 K = k^2 k'^2/3 RD(0, 1, k'^2)
// (DLMF 19.25.1).

#include "wheelwear/contactgeom/elliptic_integrals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

// Both algorithms are accurate to a few ulp, but E = K (1 - S) and E - k'^2 K = K (m - S) lose
// digits in proportion to K ~ ln(4/k') (<= 29 for k' >= 1e-12): up to ~60 ulp.
constexpr double kTolerance = 2e-14;

double rel(double a, double b) {
  return std::abs(a / b - 1.0);
}

struct Reference {
  double K, E, K_minus_E, E_minus_kc2_K;
};
Reference carlson(double kc) {
  const double m = (1.0 - kc) * (1.0 + kc);
  const double kc2 = kc * kc;
  Reference r;
  r.K = boost::math::ellint_rf(0.0, kc2, 1.0);
  r.K_minus_E = m / 3.0 * boost::math::ellint_rd(0.0, kc2, 1.0);
  r.E = r.K - r.K_minus_E;
  r.E_minus_kc2_K = m * kc2 / 3.0 * boost::math::ellint_rd(0.0, 1.0, kc2);
  return r;
}

std::vector<double> complementary_moduli() {
  std::vector<double> kc;
  for (double e = -12.0; e <= 0.0; e += 0.25) kc.push_back(std::pow(10.0, e));
  for (double v : {0.3, 0.5, 0.7, 0.9, 0.99, 0.999999}) kc.push_back(v);
  return kc;
}

TEST(EllipticIntegrals, MatchCarlsonFormsOverTheWholeRange) {
  for (double kc : complementary_moduli()) {
    SCOPED_TRACE(kc);
    const CompleteEllipticIntegrals e = complete_elliptic_integrals_kc(kc);
    if (kc < 1.0) {
      const Reference r = carlson(kc);
      EXPECT_LT(rel(e.K, r.K), kTolerance);
      EXPECT_LT(rel(e.E, r.E), kTolerance);
      // The differences have no cancellation on either side: full precision is testable.
      EXPECT_LT(rel(e.K_minus_E, r.K_minus_E), kTolerance);
      EXPECT_LT(rel(e.E_minus_kc2_K, r.E_minus_kc2_K), kTolerance);
    } else {
      EXPECT_DOUBLE_EQ(e.K, 0.5 * std::numbers::pi);
      EXPECT_DOUBLE_EQ(e.E, 0.5 * std::numbers::pi);
      EXPECT_EQ(e.K_minus_E, 0.0);
    }
  }
}

TEST(EllipticIntegrals, DifferencesKeepTheirPrecisionForSmallModulus) {
  // k = 1e-6: K - E = pi k^2/4 (1 + 3k^2/8 + ...) while K and E agree to 12 digits.
  const double k = 1e-6;
  const CompleteEllipticIntegrals e = complete_elliptic_integrals(k);
  EXPECT_LT(rel(e.K_minus_E, 0.25 * std::numbers::pi * k * k * (1.0 + 0.375 * k * k)), 1e-14);
  EXPECT_LT(rel(e.E_minus_kc2_K, 0.25 * std::numbers::pi * k * k), 1e-11);
}

TEST(EllipticIntegrals, ModulusAndComplementaryFormsAgree) {
  for (double k : {0.0, 0.1, 0.5, 0.9, 0.999}) {
    const double kc = std::sqrt((1.0 - k) * (1.0 + k));
    EXPECT_DOUBLE_EQ(complete_elliptic_integrals(k).K, complete_elliptic_integrals_kc(kc).K);
  }
}

TEST(EllipticIntegrals, FastKernelMeetsItsDocumentedAccuracy) {
  // m = 1 - kc^2 <= 0.1: Maclaurin series, to rounding. Above: Hastings' approximations,
  // documented as 1.4e-8 relative (measured; the published bounds give 2e-7).
  double worst_series = 0.0, worst_hastings = 0.0;
  for (int i = 1; i <= 4000; ++i) {
    const double m = i / 4000.0 * (1.0 - 1e-12);
    const double kc = std::sqrt(1.0 - m);
    const double error = rel(k_minus_e_unchecked(kc), carlson(kc).K_minus_E);
    double& worst = (1.0 - kc) * (1.0 + kc) <= 0.1 ? worst_series : worst_hastings;
    worst = std::max(worst, error);
  }
  for (double kc : complementary_moduli()) {
    if (kc < 0.9)
      worst_hastings =
          std::max(worst_hastings, rel(k_minus_e_unchecked(kc), carlson(kc).K_minus_E));
  }
  RecordProperty("series_worst", ::testing::PrintToString(worst_series));
  RecordProperty("hastings_worst", ::testing::PrintToString(worst_hastings));
  EXPECT_LT(worst_series, kTolerance);
  EXPECT_LT(worst_hastings, 1.5e-8);
  EXPECT_LT(
      rel(k_minus_e_unchecked(std::sqrt(1.0 - 1e-8)), carlson(std::sqrt(1.0 - 1e-8)).K_minus_E),
      kTolerance);
}

TEST(EllipticIntegrals, RejectBadModulus) {
  EXPECT_THROW(complete_elliptic_integrals_kc(0.0), InputError);
  EXPECT_THROW(complete_elliptic_integrals_kc(1.5), InputError);
  EXPECT_THROW(complete_elliptic_integrals_kc(std::nan("")), InputError);
  EXPECT_THROW(complete_elliptic_integrals(1.0), InputError);
  EXPECT_THROW(complete_elliptic_integrals(-0.1), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
