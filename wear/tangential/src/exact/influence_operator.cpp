#include "influence_operator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unsupported/Eigen/FFT>

#include "wheelwear/tangential/exact/influence.hpp"

namespace wheelwear::tangential::detail {

using Complex = std::complex<double>;

// Unscaled 2-D complex FFT of an mx x my array (index jj*mx + ii) whose rows jj >= rows are
// zero on input (forward) or not wanted on output (inverse): those rows' x-transforms are
// skipped.
class Fft2d {
 public:
  Fft2d(int mx, int my) : mx_(mx), my_(my), in_(std::max(mx, my)), out_(std::max(mx, my)) {
    fft_.SetFlag(Eigen::FFT<double>::Unscaled);
  }

  void forward(std::vector<Complex>& a, int rows) {
    for (int jj = 0; jj < rows; ++jj) {
      Complex* row = a.data() + static_cast<std::ptrdiff_t>(jj) * mx_;
      std::copy(row, row + mx_, in_.begin());
      fft_.fwd(out_.data(), in_.data(), mx_);
      std::copy(out_.begin(), out_.begin() + mx_, row);
    }
    columns(a, true, my_);
  }

  void inverse(std::vector<Complex>& a, int rows) {
    columns(a, false, rows);
    for (int jj = 0; jj < rows; ++jj) {
      Complex* row = a.data() + static_cast<std::ptrdiff_t>(jj) * mx_;
      std::copy(row, row + mx_, in_.begin());
      fft_.inv(out_.data(), in_.data(), mx_);
      std::copy(out_.begin(), out_.begin() + mx_, row);
    }
  }

 private:
  void columns(std::vector<Complex>& a, bool forward, int rows_out) {
    for (int ii = 0; ii < mx_; ++ii) {
      for (int jj = 0; jj < my_; ++jj) in_[jj] = a[static_cast<std::size_t>(jj * mx_ + ii)];
      if (forward) {
        fft_.fwd(out_.data(), in_.data(), my_);
      } else {
        fft_.inv(out_.data(), in_.data(), my_);
      }
      for (int jj = 0; jj < rows_out; ++jj) a[static_cast<std::size_t>(jj * mx_ + ii)] = out_[jj];
    }
  }

  int mx_, my_;
  Eigen::FFT<double> fft_;
  std::vector<Complex> in_, out_;
};

namespace {

// Smallest n' >= n whose prime factors are 2, 3 and 5, for which the FFT is fast (a large prime
// factor turns it into an O(n^2) transform).
int fft_size(int n) {
  for (int m = n;; ++m) {
    int r = m;
    for (const int p : {2, 3, 5})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

// Complex product without the NaN/infinity recovery of operator* (which stops inlining).
inline Complex mul(Complex a, Complex b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// The kernel k(m, n), |m| < nx, |n| < ny (given by `at`), wrapped into the padded mx x my
// array and transformed; the inverse transform's 1/(mx my) is folded in.
template <typename At>
std::vector<Complex> transform(At at, int nx, int ny, int mx, int my, Fft2d& fft) {
  std::vector<Complex> a(static_cast<std::size_t>(mx) * my);
  const double scale = 1.0 / (static_cast<double>(mx) * my);
  for (int n = -(ny - 1); n < ny; ++n) {
    for (int m = -(nx - 1); m < nx; ++m) {
      const int ii = m < 0 ? m + mx : m, jj = n < 0 ? n + my : n;
      a[static_cast<std::size_t>(jj * mx + ii)] = scale * at(m, n);
    }
  }
  fft.forward(a, my);
  return a;
}

// Rows above a solved row whose slip the sweep updates at once (Gauss-Seidel across rows, the
// other rows see the change at the next sweep's FFT, Jacobi across rows). Where the elements are
// long against their width, the rows within about an element's length feel a row's change about
// as strongly as its own diagonal, and left to the FFT they made the sweep diverge: on 80 x 80
// elements over an SDEC of a/b = 10 (elements 10 times longer than wide) under mixed creepage
// it wandered for 3000 sweeps. With the rows within a quarter of an element's length it
// converged in 276. Below 6:1 the update did not pay: the sweeps it saved it lost in cost, and
// on square elements it slowed the Anderson-accelerated iteration (160 x 160, mixed creepage:
// 384 sweeps against 215).
int near_row_count(const ElementGrid& grid) {
  constexpr double kLongElements = 6.0;  // dx/dy from which the near rows are updated
  const double ratio = grid.dx / grid.dy;
  if (ratio < kLongElements) return 0;
  return std::min(grid.ny - 1, static_cast<int>(std::ceil(0.25 * ratio)));
}

}  // namespace

InfluenceOperator::InfluenceOperator(const ElementGrid& grid, const Material& material,
                                     bool tangential, bool normal)
    : grid_(grid) {
  const int nx = grid.nx, ny = grid.ny;
  // Zero padding to at least 2n - 1 makes the circular convolution the linear one.
  mx_ = fft_size(2 * nx - 1);
  my_ = fft_size(2 * ny - 1);
  const int mx = mx_, my = my_;
  fft_ = std::make_unique<Fft2d>(mx, my);
  const double dx = grid.dx, dy = grid.dy;
  // K(m, n): the source element lies at (-m dx, -n dy) from the field point.
  auto rect = [&](int m, int n) {
    const double xc = -m * dx, yc = -n * dy;
    return rectangle_influence(xc - 0.5 * dx, xc + 0.5 * dx, yc - 0.5 * dy, yc + 0.5 * dy,
                               material);
  };
  // K for m in [-nx, nx] (the difference needs m + 1), n in (-ny, ny).
  const int row = 2 * nx + 1;
  auto at_k = [&](int m, int n) {
    return static_cast<std::size_t>(n + ny - 1) * static_cast<std::size_t>(row) +
           static_cast<std::size_t>(m + nx);
  };
  if (tangential) {
    const std::size_t size = static_cast<std::size_t>(row) * (2 * ny - 1);
    std::vector<InfluenceCoefficients> k(size);
    for (int n = -(ny - 1); n < ny; ++n)
      for (int m = -nx; m <= nx; ++m) k[at_k(m, n)] = rect(m, n);
    auto c = [&](double InfluenceCoefficients::*entry) {
      return [&, entry](int m, int n) {
        return (k[at_k(m, n)].*entry - k[at_k(m + 1, n)].*entry) / dx;
      };
    };
    const auto cxx = c(&InfluenceCoefficients::xx), cxy = c(&InfluenceCoefficients::xy),
               cyy = c(&InfluenceCoefficients::yy);
    cxx_hat_ = transform(cxx, nx, ny, mx, my, *fft_);
    cxy_hat_ = transform(cxy, nx, ny, mx, my, *fft_);
    cyy_hat_ = transform(cyy, nx, ny, mx, my, *fft_);
    near_rows_ = near_row_count(grid);
    for (int n = 1; n <= near_rows_; ++n)
      for (int m = -(nx - 1); m < nx; ++m) {
        cxx_near_.push_back(cxx(m, n));
        cxy_near_.push_back(cxy(m, n));
        cyy_near_.push_back(cyy(m, n));
      }
    kxx_row_.resize(static_cast<std::size_t>(row));
    kyy_row_.resize(static_cast<std::size_t>(row));
    for (int m = -nx; m <= nx; ++m) {
      kxx_row_[static_cast<std::size_t>(m + nx)] = k[at_k(m, 0)].xx;
      kyy_row_[static_cast<std::size_t>(m + nx)] = k[at_k(m, 0)].yy;
    }
  }
  if (normal) {
    knn_hat_ = transform([&](int m, int n) { return rect(m, n).nn; }, nx, ny, mx, my, *fft_);
  }
  work_a_.resize(static_cast<std::size_t>(mx) * my);
  work_b_.resize(static_cast<std::size_t>(mx) * my);
}

InfluenceOperator::~InfluenceOperator() = default;

void InfluenceOperator::slip(const double* px, const double* py, double* sx, double* sy) const {
  const int nx = grid_.nx, ny = grid_.ny, mx = mx_, my = my_;
  auto& z = work_a_;
  std::fill(z.begin(), z.end(), Complex{});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(j * nx + i);
      z[static_cast<std::size_t>(j * mx + i)] = Complex(px[e], py[e]);
    }
  fft_->forward(z, ny);
  // z = Px + i Py with Px, Py the transforms of real arrays: Px(k) = (z(k) + conj z(-k))/2,
  // Py(k) = (z(k) - conj z(-k))/(2i). The result Sx + i Sy transforms back to sx + i sy.
  auto& out = work_b_;
  for (int jj = 0; jj < my; ++jj) {
    const int jn = jj == 0 ? 0 : my - jj;
    for (int ii = 0; ii < mx; ++ii) {
      const int in = ii == 0 ? 0 : mx - ii;
      const std::size_t k = static_cast<std::size_t>(jj * mx + ii);
      const Complex zk = z[k], zm = std::conj(z[static_cast<std::size_t>(jn * mx + in)]);
      const Complex p_x = 0.5 * (zk + zm);
      const Complex d = zk - zm;
      const Complex p_y(0.5 * d.imag(), -0.5 * d.real());  // d/(2i)
      const Complex s_x = mul(cxx_hat_[k], p_x) + mul(cxy_hat_[k], p_y);
      const Complex s_y = mul(cxy_hat_[k], p_x) + mul(cyy_hat_[k], p_y);
      out[k] = Complex(s_x.real() - s_y.imag(), s_x.imag() + s_y.real());  // s_x + i s_y
    }
  }
  fft_->inverse(out, ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(j * nx + i);
      const Complex v = out[static_cast<std::size_t>(j * mx + i)];
      sx[e] = v.real();
      sy[e] = v.imag();
    }
}

void InfluenceOperator::normal(const double* pn, double* un) const {
  const int nx = grid_.nx, ny = grid_.ny, mx = mx_;
  auto& z = work_a_;
  std::fill(z.begin(), z.end(), Complex{});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      z[static_cast<std::size_t>(j * mx + i)] = pn[static_cast<std::size_t>(j * nx + i)];
  fft_->forward(z, ny);
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = mul(z[k], knn_hat_[k]);
  fft_->inverse(z, ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      un[static_cast<std::size_t>(j * nx + i)] = z[static_cast<std::size_t>(j * mx + i)].real();
}

}  // namespace wheelwear::tangential::detail
