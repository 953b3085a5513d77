// The initial contact point of a gap with several minima (blended_minimum.hpp): exact for one
// parabolic basin, symmetric for two equal ones, continuous where two depths cross or a
// minimum is born.

#include "blended_minimum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace wheelwear::contactgeom::detail {
namespace {

// The samples as the callable blended_minimum takes: +inf outside.
struct Samples {
  std::vector<double> h;
  double operator()(std::ptrdiff_t j) const {
    return j < 0 || j >= static_cast<std::ptrdiff_t>(h.size())
               ? std::numeric_limits<double>::infinity()
               : h[static_cast<std::size_t>(j)];
  }
  std::ptrdiff_t last() const { return static_cast<std::ptrdiff_t>(h.size()) - 1; }
};

// Two parabolic basins at samples 10.3 and 30.3, the second one lowered by `lower` [m].
Samples two_basins(double lower) {
  Samples s;
  for (int j = 0; j <= 40; ++j) {
    const double left = 1e-7 * (j - 10.3) * (j - 10.3);
    const double right = 1e-7 * (j - 30.3) * (j - 30.3) - lower;
    s.h.push_back(std::min(left, right));
  }
  return s;
}

TEST(BlendedMinimum, OneParabolicBasinIsItsVertex) {
  // The parabola through the lowest sample and its neighbours is the gap itself: exact.
  for (double vertex : {7.0, 7.2, 7.45, 6.8}) {
    Samples s;
    for (int j = 0; j <= 14; ++j) s.h.push_back(3e-7 * (j - vertex) * (j - vertex) - 2e-6);
    const BlendedMinimum m = blended_minimum(s, 0, s.last());
    EXPECT_NEAR(m.index, vertex, 1e-9);
    EXPECT_NEAR(m.h, -2e-6, 1e-18);
  }
}

TEST(BlendedMinimum, TwoEqualBasinsMeetHalfWay) {
  const BlendedMinimum m = blended_minimum(two_basins(0.0), 0, 40);
  EXPECT_NEAR(m.index, 20.3, 1e-9);  // by symmetry
  EXPECT_NEAR(m.h, 0.0, 1e-18);
}

TEST(BlendedMinimum, MovesContinuouslyWhereTwoDepthsCross) {
  // Beyond kMinimumBlendDepth (4 um) of depth difference O is the lower basin's vertex (the lowest
  // minimum, as before); in between it moves across without a jump.
  EXPECT_NEAR(blended_minimum(two_basins(-4.04e-6), 0, 40).index, 10.3, 1e-9);
  EXPECT_NEAR(blended_minimum(two_basins(4.04e-6), 0, 40).index, 30.3, 1e-9);
  double previous = blended_minimum(two_basins(-4.8e-6), 0, 40).index, largest = 0.0;
  int compared = 0;
  for (int step = 1; step <= 240; ++step) {
    const double index = blended_minimum(two_basins(-4.8e-6 + step * 4e-8), 0, 40).index;
    largest = std::max(largest, std::abs(index - previous));
    previous = index;
    ++compared;
  }
  EXPECT_EQ(compared, 240);
  // The weight 1 - smoothstep(t) changes by at most 1.5 dt, dt = 0.01 a step: at most
  // 20 samples x 1.5 x 0.01 = 0.3 samples per step; the lowest sample's jump was 20.
  EXPECT_LT(largest, 0.3);
  EXPECT_GT(largest, 0.05);  // and it does move
}

TEST(BlendedMinimum, AMinimumBornOnASlopeEntersWithoutWeight) {
  // The gap beyond the lowest basin flattens into a shoulder, then dips by p into a second
  // minimum 0.3 um above the lowest one: within the blending depth, but only p deep.
  const auto with_dip = [](double p) {
    return Samples{{5e-6, 2e-6, 0.0, 0.2e-6, 0.3e-6, 0.3e-6 - p, 0.31e-6, 2e-6, 5e-6}};
  };
  const double alone = blended_minimum(with_dip(0.0), 0, 8).index;  // no second minimum yet
  EXPECT_NEAR(alone, blended_minimum(Samples{{5e-6, 2e-6, 0.0, 0.2e-6, 5e-6}}, 0, 4).index, 1e-12);
  for (double p : {1e-11, 1e-10, 1e-9, 1e-8}) {
    const double moved = blended_minimum(with_dip(p), 0, 8).index - alone;
    // Its weight is at most p / kMinimumProminence (times the depth factor <= 1): O moves
    // towards it (3 samples away) by less than 3 p / kMinimumProminence samples.
    EXPECT_GT(moved, 0.0) << p;
    EXPECT_LT(moved, 3.0 * p / kMinimumProminence) << p;
  }
}

// An asymmetric coarse basin (a steep flank on strips half a millimetre wide) whose lowest sample
// passes to its neighbour: the parabola through either one and its neighbours puts the minimum
// 0.375 um apart at the tie (-0.125 and -0.5 um here), a jump of the local approach that made a
// wheel's load jump by 2 kN. Blended near the tie, the refined gap moves by at most 5e-8 m per
// step of 4e-9 m (measured 2.3e-8, a sixteenth of the jump), its position by at most 0.1 sample.
TEST(BlendedMinimum, TheRefinedMinimumIsContinuousWhereTheLowestSamplePasses) {
  double previous_h = 0.0, previous_index = 0.0, largest_h = 0.0, largest_index = 0.0;
  int compared = 0;
  for (int step = 0; step <= 100; ++step) {
    const double e = 0.2e-6 - step * 4e-9;  // sample 3 against sample 2 (0)
    const BlendedMinimum m = blended_minimum(Samples{{8e-6, 1e-6, 0.0, e, 4e-6, 9e-6}}, 0, 5);
    if (step > 0) {
      largest_h = std::max(largest_h, std::abs(m.h - previous_h));
      largest_index = std::max(largest_index, std::abs(m.index - previous_index));
      ++compared;
    }
    previous_h = m.h;
    previous_index = m.index;
  }
  EXPECT_EQ(compared, 100);
  EXPECT_LT(largest_h, 5e-8);
  EXPECT_LT(largest_index, 0.1);
  RecordProperty("largest_h_step", std::to_string(largest_h));
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
