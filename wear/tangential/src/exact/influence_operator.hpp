#pragma once
// The influence operators of one grid, applied as zero-padded FFT convolutions, and the row of
// the tangential kernel that the steady-rolling sweep updates directly.

#include <complex>
#include <memory>
#include <vector>

#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential::detail {

class Fft2d;

class InfluenceOperator {
 public:
  /// Kernels for `grid` and `material`: the steady-rolling tangential ones when `tangential`,
  /// the normal one when `normal`.
  InfluenceOperator(const ElementGrid& grid, const Material& material, bool tangential,
                    bool normal);
  ~InfluenceOperator();
  InfluenceOperator(const InfluenceOperator&) = delete;
  InfluenceOperator& operator=(const InfluenceOperator&) = delete;

  /// Steady-rolling slip part (sx, sy) = C (px, py) [-] with Kalker's backward difference
  /// C(m, n) = (K(m, n) - K(m + 1, n))/dx: s_i = (u(x_i) - u(x_i + dx))/dx, the displacement
  /// difference between the element and the position its material came from. K(m, n) [m/Pa]
  /// is the displacement of the field element from unit traction on the source element,
  /// (m, n) = (i - i', j - j'). Arrays of grid.size(), tractions in Pa.
  void slip(const double* px, const double* py, double* sx, double* sy) const;
  /// Normal displacement difference un = K_nn pn [m] for pn [Pa].
  void normal(const double* pn, double* un) const;

  /// K_xx(m, 0) and K_yy(m, 0) [m/Pa] (within a row K_xy vanishes), indexable by m in
  /// [-nx, nx].
  const double* kxx_row() const { return kxx_row_.data() + grid_.nx; }
  const double* kyy_row() const { return kyy_row_.data() + grid_.nx; }

  /// Rows of the steady-rolling kernel C(m, n) for n = 1 ... near_rows() (field row n rows
  /// above the source row), m in [-(nx - 1), nx - 1]: the slip the sweep adds to the rows it
  /// has still to solve after solving one.
  int near_rows() const { return near_rows_; }
  const double* cxx_near(int n) const { return near_at(cxx_near_, n); }
  const double* cxy_near(int n) const { return near_at(cxy_near_, n); }
  const double* cyy_near(int n) const { return near_at(cyy_near_, n); }

  const ElementGrid& grid() const { return grid_; }

 private:
  const double* near_at(const std::vector<double>& c, int n) const {
    const std::size_t row = static_cast<std::size_t>(2 * grid_.nx - 1);
    return c.data() + static_cast<std::size_t>(n - 1) * row +
           static_cast<std::size_t>(grid_.nx - 1);
  }

  ElementGrid grid_;
  int near_rows_ = 0;
  std::vector<double> cxx_near_, cxy_near_, cyy_near_;
  int mx_ = 0, my_ = 0;  // padded FFT sizes
  std::vector<double> kxx_row_, kyy_row_;
  std::vector<std::complex<double>> cxx_hat_, cxy_hat_, cyy_hat_, knn_hat_;
  std::unique_ptr<Fft2d> fft_;
  mutable std::vector<std::complex<double>> work_a_, work_b_;
};

}  // namespace wheelwear::tangential::detail
