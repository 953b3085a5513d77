// FASTSIM-SDEC and its comparators against Kalker's exact theory (CONTACT-SDEC, 80x80) under
// pure spin: sets b1 (g = 1, psi = 0.6, phi = 0.2 ... 1.6 1/m) and b2 (g = 1, phi = 1 1/m,
// psi = -0.8 ... 0.8) of tests/data/contact/b_pure_spin_mx80.csv.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/contact_cases.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::tangential {
namespace {

namespace contact = testing::contact;

struct Deviation {
  double fx_rel = 0, fy_rel = 0;    // largest |ours/CONTACT - 1|
  double fx_abs = 0, fy_abs = 0;    // largest |ours - CONTACT|/(mu N)
  double fy_rel_moderate_spin = 0;  // the same for phi <= 1 1/m
  std::size_t compared = 0;         // cases
};

Deviation compare(FastsimMethod method, int n) {
  FastsimOptions options;
  options.nx = options.ny = n;
  Deviation d;
  for (const contact::PureSpinCase& c : contact::pure_spin_cases_with_spin()) {
    const CreepForces f = fastsim(method, c.patch, c.creepages, c.load, c.material, options).forces;
    const double fx = f.Fx / c.mu_N(), fy = f.Fy / c.mu_N();
    d.fx_abs = std::max(d.fx_abs, std::abs(fx - c.Fx_muN));
    d.fy_abs = std::max(d.fy_abs, std::abs(fy - c.Fy_muN));
    if (c.patch.psi != 0.0) d.fx_rel = std::max(d.fx_rel, std::abs(fx / c.Fx_muN - 1));
    d.fy_rel = std::max(d.fy_rel, std::abs(fy / c.Fy_muN - 1));
    if (c.creepages.phi <= 1.0)
      d.fy_rel_moderate_spin = std::max(d.fy_rel_moderate_spin, std::abs(fy / c.Fy_muN - 1));
    ++d.compared;
  }
  return d;
}

// The bounds are the deviations this implementation reaches at 100x100 (rounded up by
// ~10 %): they document the method's modelling error, which grid refinement does not
// remove (the 80x80 reference itself is within 0.4 % of 120x120, README section 4).
TEST(FastsimVersusContact, SdecReproducesExactTheoryWithinTheSimplifiedTheorysError) {
  const Deviation d = compare(FastsimMethod::sdec, 100);
  ASSERT_EQ(d.compared, contact::kPureSpinCasesWithSpin);
  RecordProperty("fx_rel", std::to_string(d.fx_rel));
  RecordProperty("fy_rel", std::to_string(d.fy_rel));
  EXPECT_LT(d.fx_rel, 0.030);  // paper: < 2 % at its (unstated) load; 2.7 % here
  EXPECT_LT(d.fx_abs, 0.016);  // in units of mu N
  EXPECT_LT(d.fy_rel_moderate_spin, 0.06);
  EXPECT_LT(d.fy_rel, 0.22);  // phi >= 1.4: the simplified theory overshoots Fy by ~20 %
}

// The paper's ranking (Section 5): FASTSIM-SDEC is closest in Fx, EQ.L ~10 % and EQ.E with
// the shifted ellipse ~30 % off.
TEST(FastsimVersusContact, ComparatorsRankAsInThePaper) {
  const Deviation sdec = compare(FastsimMethod::sdec, 50);
  const Deviation eql = compare(FastsimMethod::eql, 50);
  const Deviation eqe = compare(FastsimMethod::eqe_shifted, 50);
  for (const Deviation& d : {sdec, eql, eqe})
    ASSERT_EQ(d.compared, contact::kPureSpinCasesWithSpin);
  RecordProperty("eql_fx_rel", std::to_string(eql.fx_rel));
  RecordProperty("eqe_shifted_fx_rel", std::to_string(eqe.fx_rel));
  EXPECT_LT(sdec.fx_rel, eql.fx_rel);
  EXPECT_LT(eql.fx_rel, eqe.fx_rel);
  EXPECT_GT(eql.fx_rel, 0.05);
  EXPECT_GT(eqe.fx_rel, 0.20);
}

// The centred equivalent ellipse cannot produce Fx under pure spin (symmetry), so it misses
// CONTACT's Fx entirely.
TEST(FastsimVersusContact, CentredEllipseMissesTheSpinInducedFx) {
  const Deviation eqe = compare(FastsimMethod::eqe, 50);
  ASSERT_EQ(eqe.compared, contact::kPureSpinCasesWithSpin);
  EXPECT_NEAR(eqe.fx_rel, 1.0, 1e-9);  // Fx is zero up to rounding
}

}  // namespace
}  // namespace wheelwear::tangential
