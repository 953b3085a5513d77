// Kik-Piotrowski with several contact regions: two minima of the gap give two patches at one
// approach, a second patch appears continuously with the load, and regions merge when the
// rigid approach clears the rise between them.

#include <gtest/gtest.h>

#include <cmath>

#include "kp_test_support.hpp"
#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom {
namespace {

using kp_test::double_well;
using kp_test::format_number;
using kp_test::kA;
using kp_test::kLoad;
using kp_test::rel;
using kp_test::Strips;
using kp_test::with_epsilon;

const double kEstar = combined_modulus(200e9, 0.25);

TEST(KikPiotrowski, TwoSeparatedMinimaGiveTwoPatchesAtOneApproach) {
  const double h2 = 5e-6;
  const Strips s([h2](double y) { return double_well(y, h2); }, -20e-3, 20e-3, 1e-4);
  const KpResult r = solve_kp_load(s.gap, kEstar, kLoad);
  ASSERT_EQ(r.status, KpStatus::converged) << r.message;
  ASSERT_EQ(r.patches.size(), 2u);
  double sum = 0.0;
  for (const KpPatch& p : r.patches) {
    // Each patch's local approach is the common approach less its own gap minimum.
    EXPECT_NEAR(p.approach + p.h_O, r.approach, 1e-15);
    sum += p.normal_force;
  }
  EXPECT_LT(rel(sum, r.normal_force), 1e-14);
  EXPECT_LT(rel(r.normal_force, kLoad), 2e-10);
  EXPECT_NEAR(r.patches[0].s_O, -6e-3, 1e-12);
  EXPECT_NEAR(r.patches[1].s_O, 9e-3, 1e-12);
  EXPECT_NEAR(r.patches[1].h_O, h2, 1e-15);
  // Each patch carries the load KP gives its region alone at that approach.
  for (int side = 0; side < 2; ++side) {
    const Strips alone(
        [h2, side](double y) {
          const bool left_region = y < 4e-3;  // the hump between the wells
          return (left_region == (side == 0)) ? double_well(y, h2)
                                              : std::numeric_limits<double>::infinity();
        },
        -20e-3, 20e-3, 1e-4);
    const KpResult single = solve_kp_approach(alone.gap, kEstar, r.approach);
    ASSERT_EQ(single.patches.size(), 1u);
    EXPECT_LT(rel(single.normal_force, r.patches[side].normal_force), 1e-13);
  }
  // The stiffer, sharper flange-like well takes the larger share even though it starts later.
  EXPECT_GT(r.patches[1].pmax, r.patches[0].pmax);
}

TEST(KikPiotrowski, SecondPatchAppearsContinuouslyWithLoad) {
  // As the load grows, the second region enters with zero load: N_2 is continuous in N.
  const double h2 = 3e-5;
  const Strips s([h2](double y) { return double_well(y, h2); }, -20e-3, 20e-3, 1e-4);
  double previous_n2 = 0.0;
  int previous_count = 1;
  ASSERT_EQ(solve_kp_load(s.gap, kEstar, 2e3).patches.size(), 1u);
  for (double N = 2e3; N <= 120e3; N += 1e3) {
    const KpResult r = solve_kp_load(s.gap, kEstar, N);
    ASSERT_EQ(r.status, KpStatus::converged) << N;
    const double n2 = r.patches.size() == 2 ? r.patches[1].normal_force : 0.0;
    EXPECT_LT(n2 - previous_n2, 2.5e3) << N;  // no jump: at most 2.5 x the load step
    EXPECT_GE(n2, previous_n2) << N;
    EXPECT_GE(static_cast<int>(r.patches.size()), previous_count);
    previous_n2 = n2;
    previous_count = static_cast<int>(r.patches.size());
  }
  EXPECT_EQ(previous_count, 2);
}

TEST(KikPiotrowski, RegionsMergeWhenTheRigidApproachClearsTheRiseBetweenThem) {
  // Two wells 4 mm apart with a rise of 0.371 mm between them: below that approach they are
  // two regions (two patches, each with its own O), above it one run with O at the deeper
  // minimum. There N(delta) drops (the shallower lobe loses its own contact point), so a load
  // in that window has two solutions; the load solve must still converge to one of them.
  auto gap = [](double y) {
    return std::min(40.0 * (y + 2e-3) * (y + 2e-3), 1e-5 + 400.0 * (y - 2e-3) * (y - 2e-3));
  };
  const Strips s(gap, -20e-3, 20e-3, 1e-4);
  double rise = 0.0;
  for (std::size_t j = 0; j < s.h.size(); ++j) {
    const double y = s.gap.s(j);
    if (y > -2e-3 && y < 2e-3) rise = std::max(rise, s.h[j]);
  }
  const KpResult below = solve_kp_approach(s.gap, kEstar, 0.99 * rise);
  const KpResult above = solve_kp_approach(s.gap, kEstar, 1.01 * rise);
  ASSERT_EQ(below.patches.size(), 2u);
  ASSERT_EQ(above.patches.size(), 1u);
  EXPECT_NEAR(above.patches[0].s_O, -2e-3, 1e-12);
  EXPECT_LT(above.normal_force, below.normal_force);
  RecordProperty("merge_drop", format_number(above.normal_force / below.normal_force - 1.0));
  for (double N = 0.5 * above.normal_force; N < 1.5 * below.normal_force; N *= 1.1) {
    const KpResult r = solve_kp_load(s.gap, kEstar, N);
    EXPECT_EQ(r.status, KpStatus::converged) << N << " " << r.message;
    EXPECT_LT(rel(r.normal_force, N), 2e-10) << N;
  }
}

}  // namespace
}  // namespace wheelwear::contactgeom
