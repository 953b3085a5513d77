#pragma once
// A run of samples of the wheel/rail gap: one contact region, or a piece of one (internal to the
// wheel/rail contact).

#include <cstddef>
#include <limits>

#include "wheel_rail_gap.hpp"

namespace wheelwear::contactgeom::detail {

// One run of samples where the surfaces interpenetrate at the rigid approach.
struct Run {
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double y_O = 0.0, h_O = 0.0;      // gap minimum (parabola through the lowest sample)
  double share = 1.0;               // weight of this contact in a blend (interpenetration_runs)
  // Where a cut bounds the run: its position in samples (fractional), the gap rising to the
  // approach beyond it over one sample (strips_of); -inf, +inf: the run's own ends.
  double cut_before = -std::numeric_limits<double>::infinity();
  double cut_after = std::numeric_limits<double>::infinity();
};

// The run of samples [first, last] with its refined gap minimum.
Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last);

}  // namespace wheelwear::contactgeom::detail
