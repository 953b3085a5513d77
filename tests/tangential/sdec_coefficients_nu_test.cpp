// The SDEC coefficients for Poisson's ratios other than 0.25: the generated table
// (data/sdec_coefficients.csv, generators/sdec_table_generator.cpp) against the paper's Table 1 at
// nu = 0.25 and the compiled table, and the linear theory built on it against fresh
// exact-theory solves in the linear limit.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/contact_cases.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/linear_theory.hpp"
#include "wheelwear/tangential/sdec_coefficients.hpp"

namespace wheelwear::tangential {
namespace {

struct GeneratedRow {
  double nu, a_over_b, k13, b11, b22, b23;
};

// data/sdec_coefficients.csv without its '#' provenance lines.
std::vector<GeneratedRow> generated_rows() {
  std::ifstream in(std::string(WHEELWEAR_SOURCE_DIR) + "/data/sdec_coefficients.csv");
  EXPECT_TRUE(in) << "data/sdec_coefficients.csv is missing";
  std::vector<GeneratedRow> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      EXPECT_EQ(line.rfind("nu,g_label,a_over_b,K13,B11,B22,B23", 0), 0u) << line;
      header = false;
      continue;
    }
    std::stringstream cells(line);
    std::string nu, label, ratio, k13, b11, b22, b23;
    std::getline(cells, nu, ',');
    std::getline(cells, label, ',');
    std::getline(cells, ratio, ',');
    std::getline(cells, k13, ',');
    std::getline(cells, b11, ',');
    std::getline(cells, b22, ',');
    std::getline(cells, b23, ',');
    rows.push_back({std::stod(nu), testing::ellipticity_from_label(label), std::stod(k13),
                    std::stod(b11), std::stod(b22), std::stod(b23)});
  }
  return rows;
}

// The generated file's rows: 5 Poisson's ratios x the 19 ellipticities of Table 1.
constexpr std::size_t kGeneratedRows = 95;

const GeneratedRow* find(const std::vector<GeneratedRow>& rows, double nu, double a_over_b) {
  for (const auto& r : rows)
    if (std::abs(r.nu - nu) < 1e-9 && std::abs(r.a_over_b / a_over_b - 1) < 1e-9) return &r;
  return nullptr;
}

// The nu = 0.25 column of the generated file (80 x 80 grids) reproduces Table 1 within the
// bounds of the exact-solver test (exact_sdec_coefficients_test.cpp: K13 1.5 %, B's 0.01 for
// a/b <= 1 and 0.02 up to a/b = 2). For b/a < 0.5 the paper's rows lie below CONTACT's own
// 80 x 80 fit (B23 at b/a = 0.1: paper 0.088, CONTACT 0.113), so every row CONTACT has
// (tests/data/contact/a_linear_fit_mx80.csv, same grid and fit, an independent code) is also
// held to CONTACT's: 0.2 % in K13 and 0.001 in the B's (the file's four decimals and, at
// b/a = 0.1, 0.0008 in B22 from the two codes' discretisations of the slender patch).
TEST(SdecCoefficientsNu, GeneratedColumnAtQuarterReproducesTable1) {
  const auto rows = generated_rows();
  ASSERT_EQ(rows.size(), kGeneratedRows);
  int checked = 0;
  for (int k = 1; k <= 19; ++k) {
    const double g = k <= 10 ? k / 10.0 : 10.0 / (20 - k);
    const GeneratedRow* r = find(rows, 0.25, g);
    ASSERT_NE(r, nullptr) << "a/b = " << g;
    const SdecTableRow paper = sdec_table_row(g, 0.25);
    if (g <= 2.0 + 1e-9) {
      EXPECT_NEAR(r->k13 / paper.k13, 1.0, 0.015) << "K13 at a/b = " << g;
      // The exact-solver test's rows (a/b = 0.5, 1, 2) take its bounds; elsewhere the paper's
      // B's scatter about a smooth curve by up to 0.014 (B11 = 0.123, 0.119, 0.123, 0.143 for
      // a/b = 0.7 ... 1.0), hence 0.015.
      const bool test_row = k == 5 || k == 10 || k == 15;
      const double tolerance = !test_row ? 0.015 : g <= 1.0 ? 0.01 : 0.02;
      EXPECT_NEAR(r->b11, paper.b11, tolerance) << "B11 at a/b = " << g;
      EXPECT_NEAR(r->b22, paper.b22, tolerance) << "B22 at a/b = " << g;
      EXPECT_NEAR(r->b23, paper.b23, tolerance) << "B23 at a/b = " << g;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 15);
  constexpr double kContactK13 = 0.002;  // [relative], see above
  constexpr double kContactB = 0.001;    // see above
  std::size_t compared = 0;
  for (const testing::contact::LinearFitCase& row : testing::contact::linear_fit_cases()) {
    const double g = row.ellipticity;
    const GeneratedRow* r = find(rows, 0.25, g);
    ASSERT_NE(r, nullptr) << "a/b = " << g;
    EXPECT_NEAR(r->k13 / row.k13, 1.0, kContactK13) << "K13 at a/b = " << g;
    EXPECT_NEAR(r->b11, row.b11, kContactB) << "B11 at a/b = " << g;
    EXPECT_NEAR(r->b22, row.b22, kContactB) << "B22 at a/b = " << g;
    EXPECT_NEAR(r->b23, row.b23, kContactB) << "B23 at a/b = " << g;
    ++compared;
  }
  EXPECT_EQ(compared, testing::contact::kLinearFitCases);
}

// The compiled table is the file: at every tabulated nu and row, sdec_table_row is Table 1
// carried by the file's change from 0.25 (K13 by ratio, B's by difference). The file has four
// decimals, the compiled table the same digits: 1e-12.
TEST(SdecCoefficientsNu, CompiledTableIsTheDataFile) {
  constexpr double kSameDigits = 1e-12;  // see above
  const auto rows = generated_rows();
  ASSERT_EQ(rows.size(), kGeneratedRows);
  for (const auto& r : rows) {
    const GeneratedRow* base = find(rows, 0.25, r.a_over_b);
    ASSERT_NE(base, nullptr);
    const SdecTableRow paper = sdec_table_row(r.a_over_b, 0.25);
    const SdecTableRow t = sdec_table_row(r.a_over_b, r.nu);
    EXPECT_NEAR(t.k13, paper.k13 * r.k13 / base->k13, kSameDigits) << r.nu << " " << r.a_over_b;
    EXPECT_NEAR(t.b11, paper.b11 + r.b11 - base->b11, kSameDigits) << r.nu << " " << r.a_over_b;
    EXPECT_NEAR(t.b22, paper.b22 + r.b22 - base->b22, kSameDigits) << r.nu << " " << r.a_over_b;
    EXPECT_NEAR(t.b23, paper.b23 + r.b23 - base->b23, kSameDigits) << r.nu << " " << r.a_over_b;
  }
}

// Continuity in nu at 0.25 (the spline passes through the node) and no flag for nu != 0.25.
TEST(SdecCoefficientsNu, ContinuousInNuAndUnflagged) {
  CoefficientFlags flags;
  const SdecTableRow at = sdec_table_row(0.6, 0.25);
  const SdecTableRow near = sdec_table_row(0.6, 0.25 + 1e-7, &flags);
  EXPECT_NEAR(near.k13, at.k13, 1e-5);
  EXPECT_NEAR(near.b23, at.b23, 1e-6);
  EXPECT_FALSE(flags.any());
}

// Linear-limit forces of the linear theory (Eq. 11-12 with the carried coefficients) against
// fresh exact solves at nu between and at the tabulated ratios. The exact solves use a
// 48 x 48 grid (not the generator's), so they are independent of the table.
struct Case {
  double a_over_b, psi, nu;
};

class SdecLinearAgainstExact : public ::testing::TestWithParam<Case> {};

TEST_P(SdecLinearAgainstExact, LinearLimitForces) {
  const Case c = GetParam();
  const double a = 5e-3, b = a / c.a_over_b, cc = std::sqrt(a * b), creep = 1e-6;
  const Material material{80e9, c.nu};
  const ContactLoad load{1e4, 1e6};  // friction large enough that nothing slips
  SdecGridOptions options;
  options.nx = options.ny = 48;
  const contactgeom::Sdec patch{a, b, c.psi};
  for (const Creepages v :
       {Creepages{creep, 0, 0}, Creepages{0, creep, 0}, Creepages{0, 0, creep / cc}}) {
    const ExactSolution exact = exact_sdec(patch, v, load, material, options);
    ASSERT_EQ(exact.status, ExactStatus::converged);
    ASSERT_EQ(exact.slip_elements, 0);
    const CreepForces linear = linear_sdec_forces(patch, v, material);
    const double scale = material.G * cc * cc * creep;  // force of a unit coefficient
    // The exact theory on a 48 x 48 grid differs from Kalker's C11, C22, C23 by up to 1.5 %
    // (the grid's error, exact_linear_theory_test.cpp) and the SDEC terms carry the 1.5 % of
    // Table 1's fit: 2.5 % of the dominant component, and for the spin's Fx (K13 psi) 3 %.
    constexpr double kDominant = 0.025, kSpinFx = 0.03;  // [relative]
    if (v.vx != 0) {
      EXPECT_NEAR(linear.Fx / exact.forces.Fx, 1.0, kDominant) << "Fx from vx";
    }
    if (v.vy != 0) {
      EXPECT_NEAR(linear.Fy / exact.forces.Fy, 1.0, kDominant) << "Fy from vy";
    }
    if (v.phi != 0) {
      EXPECT_NEAR(linear.Fy / exact.forces.Fy, 1.0, kDominant) << "Fy from phi";
      EXPECT_NEAR(linear.Fx / exact.forces.Fx, 1.0, kSpinFx) << "Fx from phi";
    }
    RecordProperty("scale", std::to_string(scale));
  }
}

INSTANTIATE_TEST_SUITE_P(Patches, SdecLinearAgainstExact,
                         ::testing::Values(Case{1.0, 0.6, 0.28}, Case{0.5, 0.4, 0.4},
                                           Case{2.0, 0.5, 0.3}, Case{1.0, 0.7, 0.1}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return "case" + std::to_string(param.index);
                         });

}  // namespace
}  // namespace wheelwear::tangential
