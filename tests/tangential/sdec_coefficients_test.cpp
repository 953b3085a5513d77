#include "wheelwear/tangential/sdec_coefficients.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/contact_cases.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {
namespace {

using contactgeom::Sdec;
namespace contact = testing::contact;

// The stored table has the paper's digits; equality to far below them is exact recall.
constexpr double kTableExact = 1e-12;

// The reference file carries the paper's Table 1 (K13, B11, B22, B23) as printed; the stored
// table must reproduce it to the last digit.
TEST(SdecCoefficients, MatchTable1TranscriptionAtEveryRow) {
  std::size_t compared = 0;
  for (const contact::LinearFitCase& row : contact::linear_fit_cases()) {
    const double g = row.ellipticity;
    const SdecTableRow t = sdec_table_row(g, contact::kMaterial.nu);
    EXPECT_NEAR(t.k13, row.paper_k13, kTableExact) << "a/b = " << g;
    EXPECT_NEAR(t.b11, row.paper_b11, kTableExact) << "a/b = " << g;
    EXPECT_NEAR(t.b22, row.paper_b22, kTableExact) << "a/b = " << g;
    EXPECT_NEAR(t.b23, row.paper_b23, kTableExact) << "a/b = " << g;
    ++compared;
  }
  EXPECT_EQ(compared, contact::kLinearFitCases);
}

// Eq. 12 against CONTACT's exact-theory coefficients for 10 ellipticities x 9 shape numbers.
// Bounds: Kalker's C's differ from CONTACT's by up to 1.6 % at psi = 0 (README section 4), and
// the quadratic/linear fits in psi add the curvature of C13s/psi (1 % between |psi| = 0.2 and
// 0.8 at g = 1, README) and CONTACT's grid error at b/a = 0.1 (0.6 % in C22s, 1.9 % in K13
// at 80x80).
TEST(SdecCoefficients, AgreeWithExactTheoryOverTheWholeGrid) {
  constexpr double kC11C22C23 = 0.018;  // [relative]
  constexpr double kC13 = 0.025;        // [relative]
  double worst_c = 0.0, worst_c13 = 0.0;
  std::size_t compared = 0;
  for (const contact::LinearCoefficientCase& row : contact::linear_coefficient_cases()) {
    const Sdec& patch = row.patch;
    const SdecCoefficients k = sdec_coefficients(patch, row.material.nu);
    const double dc11 = std::abs(k.c11s / row.c11s - 1);
    const double dc22 = std::abs(k.c22s / row.c22s - 1);
    const double dc23 = std::abs(k.c23s / row.c23s - 1);
    EXPECT_LT(std::max({dc11, dc22, dc23}), kC11C22C23)
        << "a/b " << row.g_label << " psi " << patch.psi;
    worst_c = std::max({worst_c, dc11, dc22, dc23});
    if (patch.psi != 0.0) {
      const double dc13 = std::abs(k.c13s / row.c13s - 1);
      EXPECT_LT(dc13, kC13) << "a/b " << row.g_label << " psi " << patch.psi;
      worst_c13 = std::max(worst_c13, dc13);
    } else {
      EXPECT_EQ(k.c13s, 0.0);
    }
    ++compared;
  }
  EXPECT_EQ(compared, contact::kLinearCoefficientCases);
  RecordProperty("worst_C11s_C22s_C23s_rel", std::to_string(worst_c));
  RecordProperty("worst_C13s_rel", std::to_string(worst_c13));
}

// Eq. 12: C11s, C22s, C23s are even in psi, C13s is odd.
TEST(SdecCoefficients, HaveTheParityOfEquation12) {
  const SdecCoefficients plus = sdec_coefficients(Sdec{4e-3, 6e-3, 0.4}, 0.25);
  const SdecCoefficients minus = sdec_coefficients(Sdec{4e-3, 6e-3, -0.4}, 0.25);
  EXPECT_DOUBLE_EQ(plus.c11s, minus.c11s);
  EXPECT_DOUBLE_EQ(plus.c22s, minus.c22s);
  EXPECT_DOUBLE_EQ(plus.c23s, minus.c23s);
  EXPECT_DOUBLE_EQ(plus.c13s, -minus.c13s);
  EXPECT_LT(plus.c13s, 0.0);  // psi > 0 gives C13s = -K13 psi < 0
}

TEST(SdecCoefficients, FlagApproximationsAndHoldTheEndRows) {
  const SdecCoefficients inside = sdec_coefficients(Sdec{4e-3, 4e-3, 0.3}, 0.25);
  EXPECT_FALSE(inside.flags.any());

  const SdecCoefficients slender = sdec_coefficients(Sdec{20e-3, 1e-3, 0.3}, 0.25);
  EXPECT_TRUE(slender.flags.sdec_held);
  EXPECT_TRUE(slender.flags.kalker_extrapolated);
  EXPECT_DOUBLE_EQ(slender.row.k13, 2.30);  // the b/a = 0.1 row, held

  // Other nu come from the generated table (sdec_coefficients_nu_test.cpp): not flagged.
  const SdecCoefficients other_nu = sdec_coefficients(Sdec{4e-3, 4e-3, 0.3}, 0.3);
  EXPECT_FALSE(other_nu.flags.any());
}

TEST(SdecCoefficients, RejectInvalidPatches) {
  EXPECT_THROW(sdec_coefficients(Sdec{4e-3, 4e-3, 1.0}, 0.25), InputError);
  EXPECT_THROW(sdec_coefficients(Sdec{0.0, 4e-3, 0.0}, 0.25), InputError);
  EXPECT_THROW(sdec_coefficients(Sdec{4e-3, -1e-3, 0.0}, 0.25), InputError);
  EXPECT_THROW(sdec_coefficients(Sdec{4e-3, 4e-3, std::nan("")}, 0.25), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential
