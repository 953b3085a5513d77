#include "wheelwear/tangential/kalker_coefficients.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/contact_cases.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {
namespace {

namespace contact = testing::contact;

// The table is stored with 3 significant digits; equality to far below that is exact recall.
constexpr double kTableExact = 1e-12;
// Quantities that are equal in closed form, computed along different paths: rounding only.
constexpr double kRounding = 1e-12;

// Kalker's values for nu = 0.25 as printed in Table 1 of Liu, Fu & Bruni (2022), copied into
// the reference file's C*_kalker columns: an independent transcription of the same table.
TEST(KalkerCoefficients, MatchTable1TranscriptionAtEveryRow) {
  std::size_t compared = 0;
  for (const contact::LinearFitCase& row : contact::linear_fit_cases()) {
    const double g = row.ellipticity;
    const KalkerCoefficients k = kalker_coefficients(g, contact::kMaterial.nu);
    EXPECT_NEAR(k.c11, row.kalker_c11, kTableExact) << "a/b = " << g;
    EXPECT_NEAR(k.c22, row.kalker_c22, kTableExact) << "a/b = " << g;
    EXPECT_NEAR(k.c23, row.kalker_c23, kTableExact) << "a/b = " << g;
    EXPECT_FALSE(k.extrapolated);
    ++compared;
  }
  EXPECT_EQ(compared, contact::kLinearFitCases);
}

// CONTACT's exact-theory values at psi = 0 differ from Kalker's table by at most 0.86 % for
// a/b <= 10/3 and 1.6 % at b/a = 0.1 (reference README, section 4); 1.7 % covers both.
TEST(KalkerCoefficients, AgreeWithExactTheoryWithinItsKnownSpread) {
  constexpr double kKnownSpread = 0.017;  // [relative]
  std::size_t compared = 0;
  for (const contact::LinearFitCase& row : contact::linear_fit_cases()) {
    const KalkerCoefficients k = kalker_coefficients(row.ellipticity, contact::kMaterial.nu);
    EXPECT_NEAR(k.c11 / row.c11, 1.0, kKnownSpread) << row.g_label;
    EXPECT_NEAR(k.c22 / row.c22, 1.0, kKnownSpread) << row.g_label;
    EXPECT_NEAR(k.c23 / row.c23, 1.0, kKnownSpread) << row.g_label;
    ++compared;
  }
  EXPECT_EQ(compared, contact::kLinearFitCases);
}

// For nu = 0 the elastic problem makes C11 = C22 exactly (Kalker 1990, Table E.3).
TEST(KalkerCoefficients, LongitudinalEqualsLateralForZeroPoisson) {
  for (double g : {0.1, 0.25, 0.5, 1.0, 1.5, 3.0, 10.0}) {
    const KalkerCoefficients k = kalker_coefficients(g, 0.0);
    EXPECT_NEAR(k.c11, k.c22, kRounding) << "a/b = " << g;
  }
}

// Spot values at nu = 0 and 0.5, g = 1 (DIGEST: 3.40/5.20, 3.40/3.98, 1.33/1.63).
TEST(KalkerCoefficients, CircleRowForAllTabulatedPoissonRatios) {
  const KalkerCoefficients k0 = kalker_coefficients(1.0, 0.0);
  const KalkerCoefficients k5 = kalker_coefficients(1.0, 0.5);
  EXPECT_NEAR(k0.c11, 3.40, kTableExact);
  EXPECT_NEAR(k0.c23, 1.33, kTableExact);
  EXPECT_NEAR(k5.c11, 5.20, kTableExact);
  EXPECT_NEAR(k5.c22, 3.98, kTableExact);
  EXPECT_NEAR(k5.c23, 1.63, kTableExact);
}

// Between rows and between Poisson ratios the interpolant stays between its neighbours.
TEST(KalkerCoefficients, InterpolatesMonotonicallyOnBothSidesOfTheCircle) {
  const double wide = kalker_coefficients(0.45, 0.25).c11;
  EXPECT_GT(wide, 3.53);
  EXPECT_LT(wide, 3.62);
  const double slender = kalker_coefficients(1.0 / 0.95, 0.25).c22;  // between b/a = 0.9 and 1
  EXPECT_GT(slender, 3.67);
  EXPECT_LT(slender, 3.81);
  const double mid_nu = kalker_coefficients(1.0, 0.3).c11;
  EXPECT_GT(mid_nu, 4.12);
  EXPECT_LT(mid_nu, 5.20);
}

// Outside the table the coefficients follow Kalker's asymptotes: C11, C22 tend to constants
// as a/b -> 0 and C23 scales as sqrt(g)(1 + nu(ln(16/g) - 5)) (Kalker 1990, App. E).
TEST(KalkerCoefficients, FollowsKalkersAsymptotesForWidePatches) {
  const double nu = 0.25;
  const KalkerCoefficients k1 = kalker_coefficients(1e-2, nu);
  const KalkerCoefficients k2 = kalker_coefficients(1e-3, nu);
  EXPECT_TRUE(k1.extrapolated);
  EXPECT_NEAR(k1.c11, k2.c11, kRounding);
  EXPECT_NEAR(k1.c22, k2.c22, kRounding);
  auto shape = [nu](double g) { return std::sqrt(g) * (1 + nu * (std::log(16 / g) - 5)); };
  EXPECT_NEAR(k1.c23 / k2.c23, shape(1e-2) / shape(1e-3), kRounding);
}

// For b/a -> 0, C23 grows like g^-1.5 / ((1-nu) ln(16/g^2) - 2 + 4 nu) with g = b/a.
TEST(KalkerCoefficients, FollowsKalkersAsymptotesForSlenderPatches) {
  const double nu = 0.25;
  const KalkerCoefficients k1 = kalker_coefficients(20.0, nu);
  const KalkerCoefficients k2 = kalker_coefficients(40.0, nu);
  EXPECT_TRUE(k1.extrapolated);
  auto shape = [nu](double g) {
    return std::pow(g, -1.5) / ((1 - nu) * std::log(16 / (g * g)) - 2 + 4 * nu);
  };
  EXPECT_NEAR(k1.c23 / k2.c23, shape(1.0 / 20) / shape(1.0 / 40), kRounding);
  EXPECT_GT(k2.c11, k1.c11);
}

// The asymptotes are matched to the end rows, so no coefficient jumps where the table ends
// (1e-6 relative: the change over a step of 1e-9 in a/b).
TEST(KalkerCoefficients, IsContinuousWhereTheTableEnds) {
  constexpr double kStep = 1e-6;  // [relative], see above
  for (double nu : {0.0, 0.25, 0.28, 0.5}) {
    for (double edge : {0.1, 10.0}) {
      const KalkerCoefficients in =
          kalker_coefficients(edge * (edge < 1 ? 1 + 1e-9 : 1 - 1e-9), nu);
      const KalkerCoefficients out =
          kalker_coefficients(edge * (edge < 1 ? 1 - 1e-9 : 1 + 1e-9), nu);
      EXPECT_NEAR(out.c11 / in.c11, 1.0, kStep);
      EXPECT_NEAR(out.c22 / in.c22, 1.0, kStep);
      EXPECT_NEAR(out.c23 / in.c23, 1.0, kStep);
      EXPECT_TRUE(out.extrapolated);
      EXPECT_FALSE(in.extrapolated);
    }
  }
}

TEST(KalkerCoefficients, RejectsInvalidInput) {
  EXPECT_THROW(kalker_coefficients(0.0, 0.25), InputError);
  EXPECT_THROW(kalker_coefficients(-1.0, 0.25), InputError);
  EXPECT_THROW(kalker_coefficients(std::nan(""), 0.25), InputError);
  EXPECT_THROW(kalker_coefficients(1.0, 0.6), InputError);
  EXPECT_THROW(kalker_coefficients(1.0, -0.1), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential
