#include "wheelwear/profiles/smoothing_spline.hpp"

#include <Eigen/Sparse>
#include <cmath>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

double smoothing_lambda(double length_scale, double mean_spacing) {
  require(std::isfinite(length_scale) && length_scale >= 0.0, "smoothing length [m]", length_scale,
          "must be finite and >= 0");
  require(std::isfinite(mean_spacing) && mean_spacing > 0.0, "mean point spacing [m]", mean_spacing,
          "must be finite and > 0");
  const double l2 = length_scale * length_scale;
  return l2 * l2 / mean_spacing;
}

Eigen::MatrixXd smooth_values(std::span<const double> t, const Eigen::MatrixXd& values,
                              double lambda) {
  const auto n = static_cast<Eigen::Index>(t.size());
  require(values.rows() == n, "smoothing value rows", static_cast<double>(values.rows()),
          "must equal the number of sites");
  require(std::isfinite(lambda) && lambda >= 0.0, "smoothing lambda", lambda,
          "must be finite and >= 0");
  for (std::size_t i = 1; i < t.size(); ++i)
    require(t[i] > t[i - 1], "smoothing site", t[i], "sites must increase strictly");
  if (n < 3 || lambda == 0.0) return values;

  // Reinsch's banded form: with h_i = t_{i+1} - t_i, Q (n x m) and R (m x m), m = n - 2, the
  // interior second derivatives g solve (R + lambda Q^T Q) g = Q^T v, and f = v - lambda Q g.
  const Eigen::Index m = n - 2;
  std::vector<Eigen::Triplet<double>> q_entries, r_entries;
  q_entries.reserve(static_cast<std::size_t>(3 * m));
  r_entries.reserve(static_cast<std::size_t>(3 * m));
  for (Eigen::Index j = 0; j < m; ++j) {
    const auto i = static_cast<std::size_t>(j + 1);
    const double h0 = t[i] - t[i - 1];
    const double h1 = t[i + 1] - t[i];
    q_entries.emplace_back(j, j, 1.0 / h0);
    q_entries.emplace_back(j + 1, j, -1.0 / h0 - 1.0 / h1);
    q_entries.emplace_back(j + 2, j, 1.0 / h1);
    r_entries.emplace_back(j, j, (h0 + h1) / 3.0);
    if (j + 1 < m) {
      r_entries.emplace_back(j, j + 1, h1 / 6.0);
      r_entries.emplace_back(j + 1, j, h1 / 6.0);
    }
  }
  Eigen::SparseMatrix<double> q(n, m), r(m, m);
  q.setFromTriplets(q_entries.begin(), q_entries.end());
  r.setFromTriplets(r_entries.begin(), r_entries.end());
  const Eigen::SparseMatrix<double> qt = q.transpose();
  const Eigen::SparseMatrix<double> a = r + lambda * (qt * q);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  // R + lambda Q^T Q is symmetric positive definite for increasing sites, so this only fails on
  // sites so close that the matrix underflows; the cleaning step merges such points first.
  require(solver.info() == Eigen::Success, "smoothing spline sites", static_cast<double>(n),
          "the sites are too close together to smooth (merge near-duplicate points first)");
  const Eigen::MatrixXd g = solver.solve(qt * values);
  return values - lambda * (q * g);
}

}  // namespace wheelwear::profiles
