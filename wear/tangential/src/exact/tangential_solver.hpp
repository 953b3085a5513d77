#pragma once
// The steady-rolling tangential problem of Kalker's exact theory on a grid with given traction
// bound and rigid slip.

#include <vector>

#include "influence_operator.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential::detail {

/// Solves for the tractions (px, py) of `solution` (which holds pn and the grid) with the
/// traction bound `bound` = mu pn [Pa] and the rigid slip (wx, wy) [-] per element, writing
/// tractions, slip, element states, iteration count and status into `solution`.
/// `with_near_rows` false leaves the near rows of long elements (InfluenceOperator::near_rows)
/// to the next sweep's FFT, as on shorter elements.
void solve_tangential(const InfluenceOperator& op, const std::vector<double>& bound,
                      const std::vector<double>& wx, const std::vector<double>& wy,
                      const ExactSolverOptions& options, ExactSolution& solution,
                      bool with_near_rows = true);

}  // namespace wheelwear::tangential::detail
