#pragma once
/// The cheapest FASTSIM grid for a target error, from the discretisation-error model measured
/// by studies/runtime_error_study.cpp (results in bench/results/grid_error_constants.csv).

#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::tangential {

/// The discretisation error of an n x n FASTSIM grid, e(n) = C / n^order, as a fraction of
/// mu N: an upper bound of max(|Fx(n) - Fx(conv)|, |Fy(n) - Fy(conv)|)/(mu N), where conv is the
/// same method's converged answer, over the pure-spin cases of CONTACT's reference set b (g = 1,
/// psi = -0.8 ... 0.8, phi = 0.2 ... 1.6 1/m, p0 = 1000 MPa, mu = 0.35).
struct GridErrorModel {
  /// Order of convergence: 1 for Kalker's scheme; for the second-order scheme 2 with the
  /// parabolic bound and 1.5 with the semi-elliptic one (its slope is unbounded at the edges).
  double order = 1.0;
  double constant = 0.0;  ///< C [-]: the largest e(n) n^order measured for n = min_cells ... 1000
  /// The smallest n the model holds from (5 for Kalker's scheme; 10 for the second-order one
  /// with the parabolic bound, 20 with the semi-elliptic one: below, it is not yet second order).
  int min_cells = 5;
};

/// A grid chosen for a target error.
struct GridChoice {
  int nx = 0, ny = 0;          ///< cells per strip and strips (nx = ny = n)
  double predicted_error = 0;  ///< the model's bound C/n^order at that grid [fraction of mu N]
};

/// The largest n that choose_grid returns: the end of the range the model was measured over.
inline constexpr int kGridChoiceMaxCells = 1000;

/// The error model of a method, scheme and traction bound (constants of the study, see
/// grid_choice.cpp for their provenance).
GridErrorModel grid_error_model(FastsimMethod method, FastsimScheme scheme, TractionBound bound);

/// The cheapest n x n grid whose modelled error C/n^order is at most `target_error` (a
/// fraction of mu N, against the method's converged answer; 0 < target_error < 1), at least
/// the model's min_cells. A tighter target never gives a coarser grid. Throws InputError naming
/// target_error when it is not in (0, 1) or needs more than kGridChoiceMaxCells per side.
GridChoice choose_grid(FastsimMethod method, FastsimScheme scheme, TractionBound bound,
                       double target_error);

}  // namespace wheelwear::tangential
