#pragma once
/// The cubic smoothing spline (Reinsch 1967), with its strength set by a physical length scale.

#include <Eigen/Core>
#include <span>

namespace wheelwear::profiles {

/// Reinsch's smoothing weight lambda [m^3 when t and the values are in m] for a length scale L
/// [m] and a mean data spacing h [m]: lambda = L^4 / h. The fit then acts on a wavelength w like
/// the filter 1 / (1 + (2 pi L / w)^4): features of wavelength 2 pi L are halved, much longer ones
/// pass unchanged (continuous limit of the Reinsch functional). L = 0 gives interpolation.
double smoothing_lambda(double length_scale, double mean_spacing);

/// Values at the sites t of the cubic smoothing spline f minimising
///   sum_i |v_i - f(t_i)|^2 + lambda * integral |f''(t)|^2 dt
/// (Reinsch, Numer. Math. 10, 1967; natural end conditions). Each column of `values` is smoothed
/// with the same lambda. t strictly increasing; with fewer than 3 sites or lambda = 0 the values
/// are returned unchanged. Throws InputError on bad arguments.
Eigen::MatrixXd smooth_values(std::span<const double> t, const Eigen::MatrixXd& values,
                              double lambda);

}  // namespace wheelwear::profiles
