#pragma once
/// The normal contact problem of Kalker's exact theory on a grid: non-negative pressure, zero
/// gap where it acts, prescribed total force (Kalker 1990, Ch. 5).

#include <vector>

#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

/// Pressure per element of `grid` for the undeformed distance `h` [m] per element (index
/// j*nx + i) and the normal force `normal_force` [N]: gap h - approach + u_n >= 0, p_n >= 0,
/// p_n gap = 0, sum p_n dA = N. Solved by the constrained conjugate-gradient method of
/// Polonsky & Keer (1999) with FFT products; stops when sum|p_k - p_(k-1)| dA <=
/// options.normal_tolerance * N. Throws InputError on invalid input.
NormalSolution exact_normal(const ElementGrid& grid, const std::vector<double>& h,
                            double normal_force, const Material& material,
                            const ExactSolverOptions& options = {});

}  // namespace wheelwear::tangential
