#pragma once
// The vertex of the parabola through three equally spaced samples of a gap around its lowest
// one (internal to contactgeom): how O is refined between samples, as CONTACT's reference data
// locate s_icp.

#include <optional>

namespace wheelwear::contactgeom::detail {

struct ParabolaVertex {
  double offset = 0.0;  // from the middle sample, in samples: |offset| <= 1/2 at a minimum
  double h = 0.0;       // the parabola's value there
};

// The vertex of the parabola through (-1, left), (0, middle), (1, right); none unless it opens
// upwards.
inline std::optional<ParabolaVertex> parabola_vertex(double left, double middle, double right) {
  const double curvature = left - 2.0 * middle + right;
  if (!(curvature > 0.0)) return std::nullopt;
  const double offset = 0.5 * (left - right) / curvature;
  return ParabolaVertex{offset, middle - 0.25 * (left - right) * offset};
}

}  // namespace wheelwear::contactgeom::detail
