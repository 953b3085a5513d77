#include "wheelwear/wear/wear_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::wear {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A depth is a product and quotient of a few doubles: a handful of roundings of 1.1e-16 each.
constexpr double kRoundingTolerance = 1e-14;
// K on the catastrophic branch, 61.9 x - 4778.7 of order 1e3: the rounding of that product.
constexpr double kBranchRounding = 1e-9;  // [ug/(m mm^2)]

// A cell whose frictional work density |tau||s| is x N/mm^2 (x 1e6 N/m^2), at slip 0.1.
CellState cell_with_work(double x_N_per_mm2) {
  return CellState{1e9, x_N_per_mm2 * 1e6 / 0.1, 0.1, 20.0};
}

double rel_diff(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// ---------------------------------------------------------------------------------------------
// USFD T gamma law

TEST(UsfdLaw, RegimesSwitchAtThePublishedThresholds) {
  const TgammaLaw law = TgammaLaw::usfd();
  ASSERT_EQ(law.regimes().size(), 3u);
  EXPECT_EQ(law.regime_name(0), "mild");
  EXPECT_EQ(law.regime_name(1), "severe");
  EXPECT_EQ(law.regime_name(2), "catastrophic");
  // Bounds are inclusive below, exclusive above: 10.4 is severe, as published.
  EXPECT_EQ(law.regime_of(0.0), 0);
  EXPECT_EQ(law.regime_of(std::nextafter(10.4, 0.0)), 0);
  EXPECT_EQ(law.regime_of(10.4), 1);
  EXPECT_EQ(law.regime_of(std::nextafter(77.2, 0.0)), 1);
  EXPECT_EQ(law.regime_of(77.2), 2);
  EXPECT_EQ(law.regime_of(1e6), 2);
  // The same thresholds reached through a cell's traction and slip.
  EXPECT_EQ(law.regime(cell_with_work(10.3)), 0);
  EXPECT_EQ(law.regime(cell_with_work(10.5)), 1);
  EXPECT_EQ(law.regime(cell_with_work(77.1)), 1);
  EXPECT_EQ(law.regime(cell_with_work(77.3)), 2);
}

TEST(UsfdLaw, WearRateFollowsThePublishedBranches) {
  const TgammaLaw law = TgammaLaw::usfd();
  // 1e-12: K is one multiply-add of numbers of order 1e3; this allows a few ulps of slack.
  constexpr double tol = 1e-12;
  EXPECT_NEAR(law.wear_rate(5.0), 5.3 * 5.0, tol);
  EXPECT_NEAR(law.wear_rate(std::nextafter(10.4, 0.0)), 5.3 * 10.4, tol);  // 55.12
  EXPECT_EQ(law.wear_rate(10.4), 55.0);
  EXPECT_EQ(law.wear_rate(40.0), 55.0);
  EXPECT_EQ(law.wear_rate(std::nextafter(77.2, 0.0)), 55.0);
  // Above the crossing x* = (4778.7 + 55) / 61.9 = 78.09 the published line itself applies.
  EXPECT_NEAR(law.wear_rate(100.0), 61.9 * 100.0 - 4778.7, kBranchRounding);  // 1411.3
  EXPECT_NEAR(law.wear_rate(200.0), 61.9 * 200.0 - 4778.7, kBranchRounding);  // 7601.3
}

// The published catastrophic branch is 61.9 x - 4778.7 = -0.02 at x = 77.2: without a fix K
// would fall from 55 to ~0 there. The floor 55 holds K at 55 up to x* = 78.09, where the line
// crosses 55, so K is continuous at 77.2 and continuous and non-decreasing beyond.
TEST(UsfdLaw, FloorRemovesTheDropAt77p2) {
  const TgammaLaw law = TgammaLaw::usfd();
  const double just_above = std::nextafter(77.2, kInf);
  EXPECT_NEAR(61.9 * just_above - 4778.7, 0.0, 0.05);  // the published branch starts at ~0 ...
  EXPECT_EQ(law.wear_rate(just_above), 55.0);          // ... the fixed law at 55
  EXPECT_EQ(law.wear_rate(77.2), 55.0);
  EXPECT_EQ(law.wear_rate(78.0), 55.0);  // published line: 49.5
  const double crossing = (4778.7 + 55.0) / 61.9;
  EXPECT_NEAR(crossing, 78.0888, 1e-4);
  EXPECT_NEAR(law.wear_rate(crossing), 55.0, kBranchRounding);
  EXPECT_NEAR(law.wear_rate(crossing + 1.0), 55.0 + 61.9, kBranchRounding);
  // Continuous and non-decreasing from the severe regime on (10.4 ... 200 N/mm^2).
  double previous = law.wear_rate(10.4);
  for (double x = 10.4; x <= 200.0; x += 0.001) {
    const double k = law.wear_rate(x);
    EXPECT_GE(k, previous) << "x = " << x;
    // 61.9 * 0.001 plus rounding: the largest step the steepest branch can take.
    EXPECT_LE(k - previous, 61.9 * 0.001 + kBranchRounding) << "x = " << x;
    previous = k;
  }
}

// Hand computation for T gamma / A = 20 N/mm^2 (severe regime, K = 55 ug/(m mm^2)), dx = 1 mm:
//   K = 55 ug/(m mm^2) = 55e-9 kg / (1 m * 1e-6 m^2) = 0.055 kg/m^3 (per metre rolled, per m^2)
//   mass per area per passage = K dx = 0.055 * 1e-3 = 5.5e-5 kg/m^2
//   depth = 5.5e-5 kg/m^2 / 7850 kg/m^3 = 7.00637e-9 m (7.0 nm)
// Cross-check in mm: 55 ug/m over 1 mm rolled is 0.055 ug = 5.5e-11 kg per mm^2, i.e.
// 5.5e-11 / 7.85e-6 kg/mm^3 = 7.00637e-6 mm^3 per mm^2 = 7.00637e-6 mm.
TEST(UsfdLaw, DepthPerPassageHandComputedUnits) {
  const TgammaLaw law = TgammaLaw::usfd();
  const CellState cell{1.2e9, 2e8, 0.1, 30.0};  // |tau||s| = 2e7 N/m^2 = 20 N/mm^2
  EXPECT_EQ(law.regime(cell), 1);
  const double expected = 55.0 * 1e-9 / 1e-6 * 1e-3 / 7850.0;
  EXPECT_NEAR(expected, 7.00637e-9, 5e-15);  // the hand value, to its 6 printed digits
  EXPECT_LT(rel_diff(law.depth_per_passage(cell, 1e-3), expected), kRoundingTolerance);
  // Mild regime, 5 N/mm^2: K = 26.5 ug/(m mm^2), so 26.5/55 of the value above.
  const CellState mild{1.2e9, 5e7, 0.1, 30.0};
  EXPECT_LT(rel_diff(law.depth_per_passage(mild, 1e-3), expected * 26.5 / 55.0),
            kRoundingTolerance);
}

TEST(UsfdLaw, LinearInDistanceAndZeroWithoutWork) {
  const TgammaLaw law = TgammaLaw::usfd();
  for (double x : {3.0, 20.0, 77.5, 150.0}) {  // one point per regime, and the fixed range
    const CellState cell = cell_with_work(x);
    const double once = law.depth_per_passage(cell, 0.2e-3);
    EXPECT_GT(once, 0.0);
    EXPECT_LT(rel_diff(law.depth_per_passage(cell, 0.4e-3), 2.0 * once), kRoundingTolerance);
  }
  // The mild regime is linear in T gamma / A: doubling the slip doubles the depth.
  const CellState slow{1e9, 4e7, 0.05, 20.0};  // 2 N/mm^2
  const CellState fast{1e9, 4e7, 0.10, 20.0};  // 4 N/mm^2
  EXPECT_LT(rel_diff(law.depth_per_passage(fast, 1e-3), 2.0 * law.depth_per_passage(slow, 1e-3)),
            kRoundingTolerance);
  // No slip (adhesion) or no traction: no frictional work, no wear.
  EXPECT_EQ(law.depth_per_passage(CellState{1e9, 3e8, 0.0, 20.0}, 1e-3), 0.0);
  EXPECT_EQ(law.depth_per_passage(CellState{1e9, 0.0, 0.3, 20.0}, 1e-3), 0.0);
  // The density divides the depth.
  const TgammaLaw light = TgammaLaw::usfd(7850.0 / 2);
  const CellState cell = cell_with_work(20.0);
  EXPECT_LT(rel_diff(light.depth_per_passage(cell, 1e-3), 2.0 * law.depth_per_passage(cell, 1e-3)),
            kRoundingTolerance);
}

TEST(UsfdLaw, InvalidStatesGiveNaNAndInvalidParametersThrow) {
  const TgammaLaw law = TgammaLaw::usfd();
  EXPECT_EQ(law.regime(CellState{1e9, 1e8, -0.1, 20.0}), -1);
  EXPECT_TRUE(std::isnan(law.depth_per_passage(CellState{1e9, 1e8, -0.1, 20.0}, 1e-3)));
  EXPECT_TRUE(std::isnan(law.depth_per_passage(CellState{1e9, std::nan(""), 0.1, 20.0}, 1e-3)));
  EXPECT_THROW(TgammaLaw::usfd(0.0), InputError);
  EXPECT_THROW(TgammaLaw::usfd(std::nan("")), InputError);
  EXPECT_THROW(CellState({1e9, 1e8, -0.1, 20.0}).validate(), InputError);
  EXPECT_THROW(CellState({1e9, kInf, 0.1, 20.0}).validate(), InputError);
  EXPECT_NO_THROW(CellState({1e9, 1e8, 0.1, 20.0}).validate());
}

// ---------------------------------------------------------------------------------------------
// Archard law with the KTH map

TEST(ArchardLaw, RegionsByPressureAndSlidingSpeed) {
  const ArchardLaw law = ArchardLaw::kth();  // H = 2.5 GPa: seizure above p = 2.0 GPa
  ASSERT_EQ(law.regimes().size(), 4u);
  const auto name = [&](const CellState& c) { return std::string(law.regime_name(law.regime(c))); };
  // p = 1 GPa = 0.4 H; V = 20 m/s, so slip 0.005 / 0.02 / 0.05 slide at 0.1 / 0.4 / 1.0 m/s.
  EXPECT_EQ(name({1e9, 3e8, 0.005, 20.0}), "mild_low_speed");
  EXPECT_EQ(name({1e9, 3e8, 0.02, 20.0}), "severe");
  EXPECT_EQ(name({1e9, 3e8, 0.05, 20.0}), "mild_high_speed");
  EXPECT_EQ(law.coefficient({1e9, 3e8, 0.005, 20.0}), 5.5e-4);
  EXPECT_EQ(law.coefficient({1e9, 3e8, 0.02, 20.0}), 35e-4);
  EXPECT_EQ(law.coefficient({1e9, 3e8, 0.05, 20.0}), 5.5e-4);
  // p = 2.1 GPa = 0.84 H seizes at every sliding speed, adhesion included.
  for (double slip : {0.0, 0.005, 0.02, 0.05}) {
    EXPECT_EQ(name({2.1e9, 7e8, slip, 20.0}), "seizure") << "slip " << slip;
    EXPECT_EQ(law.coefficient({2.1e9, 7e8, slip, 20.0}), 350e-4);
  }
  // It is the sliding speed |s| V that counts, not the slip: the same slip at 5 m/s is slow.
  EXPECT_EQ(name({1e9, 3e8, 0.02, 5.0}), "mild_low_speed");  // 0.1 m/s
  // The bounds, exactly (inclusive below, exclusive above).
  EXPECT_EQ(law.regime_name(law.regime_of(0.8, 0.1)), "seizure");
  EXPECT_EQ(law.regime_name(law.regime_of(std::nextafter(0.8, 0.0), 0.1)), "mild_low_speed");
  EXPECT_EQ(law.regime_name(law.regime_of(0.5, std::nextafter(0.2, 0.0))), "mild_low_speed");
  EXPECT_EQ(law.regime_name(law.regime_of(0.5, 0.2)), "severe");
  EXPECT_EQ(law.regime_name(law.regime_of(0.5, std::nextafter(0.7, 0.0))), "severe");
  EXPECT_EQ(law.regime_name(law.regime_of(0.5, 0.7)), "mild_high_speed");
  EXPECT_EQ(law.regime_of(-0.1, 0.1), -1);
  EXPECT_EQ(law.regime_of(0.5, std::nan("")), -1);
}

// Hand computation: p = 1 GPa, slip 0.02 at V = 20 m/s (0.4 m/s, severe: k = 35e-4), dx = 1 mm:
//   ds = |s| dx = 0.02 * 1e-3 = 2e-5 m of sliding during the passage
//   dz = k p ds / H = 35e-4 * 1e9 * 2e-5 / 2.5e9 = 2.8e-8 m (28 nm)
TEST(ArchardLaw, DepthPerPassageHandComputed) {
  const ArchardLaw law = ArchardLaw::kth();
  const CellState cell{1e9, 3e8, 0.02, 20.0};
  EXPECT_LT(rel_diff(law.depth_per_passage(cell, 1e-3), 2.8e-8), kRoundingTolerance);
  // A harder steel wears less in proportion, as long as the cell stays in its region.
  const ArchardLaw hard = ArchardLaw::kth(5e9);
  EXPECT_LT(rel_diff(hard.depth_per_passage(cell, 1e-3), 1.4e-8), kRoundingTolerance);
}

TEST(ArchardLaw, LinearInDistanceAndPressureAndZeroWithoutSliding) {
  const ArchardLaw law = ArchardLaw::kth();
  for (const CellState& cell :
       {CellState{1e9, 3e8, 0.005, 20.0}, CellState{1e9, 3e8, 0.02, 20.0},
        CellState{1e9, 3e8, 0.05, 20.0}, CellState{2.1e9, 7e8, 0.02, 20.0}}) {
    const double once = law.depth_per_passage(cell, 0.25e-3);
    EXPECT_GT(once, 0.0);
    EXPECT_LT(rel_diff(law.depth_per_passage(cell, 0.5e-3), 2.0 * once), kRoundingTolerance);
  }
  // Within a region the depth is proportional to the pressure (0.2 H and 0.4 H, both mild).
  const double low = law.depth_per_passage({0.5e9, 1e8, 0.005, 20.0}, 1e-3);
  const double high = law.depth_per_passage({1.0e9, 1e8, 0.005, 20.0}, 1e-3);
  EXPECT_LT(rel_diff(high, 2.0 * low), kRoundingTolerance);
  // No sliding, not even in the seizure region, or no pressure: no wear.
  EXPECT_EQ(law.depth_per_passage({2.1e9, 7e8, 0.0, 20.0}, 1e-3), 0.0);
  EXPECT_EQ(law.depth_per_passage({0.0, 0.0, 0.02, 20.0}, 1e-3), 0.0);
  EXPECT_TRUE(std::isnan(law.depth_per_passage({-1e9, 3e8, 0.02, 20.0}, 1e-3)));
  EXPECT_THROW(ArchardLaw::kth(0.0), InputError);
  EXPECT_THROW(ArchardLaw::kth(-2e9), InputError);
}

// ---------------------------------------------------------------------------------------------
// The laws as one model

TEST(WearLaw, BuiltInLawsByName) {
  for (std::string_view name : kWearLawNames) {
    const std::optional<WearLaw> law = default_wear_law(name);
    ASSERT_TRUE(law.has_value()) << name;
    EXPECT_EQ(law_name(*law), name);
  }
  EXPECT_TRUE(std::holds_alternative<TgammaLaw>(*default_wear_law("usfd")));
  EXPECT_TRUE(std::holds_alternative<ArchardLaw>(*default_wear_law("archard")));
  EXPECT_FALSE(default_wear_law("USFD").has_value());
  EXPECT_FALSE(default_wear_law("tgamma").has_value());
}

// The strip path computes in blocks of 64 cells with the regimes in the outer loop; it must
// give each cell what the per-cell path gives, over more than two blocks, through every regime,
// at the bounds of the tables, and for invalid states (NaN).
TEST(WearLaw, StripDispatchMatchesPerCellCalls) {
  std::vector<CellState> cells;
  for (int i = 0; i < 150; ++i) {  // p up to 2.2 GPa (0.88 H), T gamma / A up to 98 N/mm^2
    cells.push_back({2.2e9 * i / 149.0, 2e8 + 5e6 * i, 0.0007 * i, 20.0});
  }
  cells.push_back({2e9, 2e8, 0.2, 1.0});            // p/H = 0.8 and 0.2 m/s, up to rounding
  cells.push_back({1e9, 2e8, 0.7, 1.0});            // 0.7 m/s
  cells.push_back({1e9, 10.4e7, 0.1, 20.0});        // 10.4 N/mm^2
  cells.push_back({1e9, 77.2e7, 0.1, 20.0});        // 77.2 N/mm^2
  cells.push_back({1e9, 2e8, -0.1, 20.0});          // invalid: negative slip
  cells.push_back({std::nan(""), 2e8, 0.1, 20.0});  // invalid: NaN pressure (Archard only)
  for (std::string_view name : kWearLawNames) {
    const WearLaw law = *default_wear_law(name);
    std::vector<double> depth(cells.size());
    depths_per_passage(law, cells, 0.3e-3, depth);
    std::vector<int> cells_per_regime(
        std::visit([](const auto& l) { return l.regimes().size(); }, law));
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const double expected = depth_per_passage(law, cells[i], 0.3e-3);
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(depth[i])) << name << " cell " << i;
        EXPECT_EQ(regime(law, cells[i]), -1) << name << " cell " << i;
        continue;
      }
      // The same expressions in the same order; DOUBLE_EQ's 4 ulps leave room for a compiler
      // that fuses a multiply-add in the vectorised loop and not in the scalar one.
      EXPECT_DOUBLE_EQ(depth[i], expected) << name << " cell " << i;
      ++cells_per_regime.at(regime(law, cells[i]));
    }
    for (std::size_t r = 0; r < cells_per_regime.size(); ++r) {
      EXPECT_GT(cells_per_regime[r], 0)
          << name << ": no cell in " << regime_name(law, static_cast<int>(r));
    }
    EXPECT_TRUE(std::isnan(depth[cells.size() - 2])) << name;  // negative slip
    std::vector<double> short_output(cells.size() - 1);
    EXPECT_THROW(depths_per_passage(law, cells, 0.3e-3, short_output), InputError);
  }
}

// Cells given as columns give what the same cells given as CellStates give.
TEST(WearLaw, ColumnsMatchCellStates) {
  std::vector<CellState> cells;
  std::vector<double> pressure, work, slip;
  for (int i = 0; i < 150; ++i) {  // through every regime of both laws, as above
    const CellState c{2.2e9 * i / 149.0, 2e8 + 5e6 * i, 0.0007 * i, 20.0};
    cells.push_back(c);
    pressure.push_back(c.pressure);
    work.push_back(c.work_density());
    slip.push_back(c.slip);
  }
  for (std::string_view name : kWearLawNames) {
    const WearLaw law = *default_wear_law(name);
    std::vector<double> from_states(cells.size()), from_columns(cells.size());
    depths_per_passage(law, cells, 0.3e-3, from_states);
    depths_per_passage(law, CellColumns{pressure, work, slip, 20.0}, 0.3e-3, from_columns);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      // The same expressions, up to where the multiply by dx is grouped: 4 ulps.
      EXPECT_DOUBLE_EQ(from_columns[i], from_states[i]) << name << " cell " << i;
    }
    std::vector<double> short_output(cells.size() - 1);
    EXPECT_THROW(
        depths_per_passage(law, CellColumns{pressure, work, slip, 20.0}, 0.3e-3, short_output),
        InputError);
  }
}

}  // namespace
}  // namespace wheelwear::wear
