#include "wheelwear/profiles/cubic_spline.hpp"

#include <algorithm>
#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

void check_knots(std::span<const double> t, std::size_t values) {
  require(t.size() >= 2, "spline knot count", static_cast<double>(t.size()), "at least 2 knots");
  require(values == t.size(), "spline value count", static_cast<double>(values),
          "must equal the knot count");
  for (std::size_t i = 0; i < t.size(); ++i) {
    require_finite("spline knot", t[i]);
    if (i > 0) require(t[i] > t[i - 1], "spline knot", t[i], "knots must increase strictly");
  }
}

}  // namespace

void solve_tridiagonal(std::vector<double> lower, std::vector<double> diagonal,
                       std::vector<double> upper, std::vector<double>& rhs) {
  const std::size_t n = diagonal.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double w = lower[i] / diagonal[i - 1];
    diagonal[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  rhs[n - 1] /= diagonal[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) rhs[i] = (rhs[i] - upper[i] * rhs[i + 1]) / diagonal[i];
}

CubicSpline CubicSpline::interpolate(std::span<const double> t, std::span<const double> v,
                                     EndCondition end) {
  check_knots(t, v.size());
  const std::size_t n = t.size();
  std::vector<double> m(n, 0.0);
  if (n == 3 && end == EndCondition::not_a_knot) {
    // Not-a-knot on three points is the parabola through them: one constant second derivative.
    const double d0 = (v[1] - v[0]) / (t[1] - t[0]);
    const double d1 = (v[2] - v[1]) / (t[2] - t[1]);
    std::fill(m.begin(), m.end(), 2.0 * (d1 - d0) / (t[2] - t[0]));
  } else if (n >= 3) {
    // Moment equations h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (d_i - d_{i-1})
    // for the interior knots; the end conditions eliminate m_0 and m_{n-1}.
    const std::size_t k = n - 2;
    std::vector<double> h(n - 1), lower(k), diagonal(k), upper(k), rhs(k);
    for (std::size_t i = 0; i + 1 < n; ++i) h[i] = t[i + 1] - t[i];
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t i = j + 1;
      lower[j] = h[i - 1];
      diagonal[j] = 2.0 * (h[i - 1] + h[i]);
      upper[j] = h[i];
      rhs[j] = 6.0 * ((v[i + 1] - v[i]) / h[i] - (v[i] - v[i - 1]) / h[i - 1]);
    }
    const bool not_a_knot = end == EndCondition::not_a_knot;
    if (not_a_knot) {
      // m_0 = (1 + h0/h1) m_1 - (h0/h1) m_2, and symmetrically at the far end.
      const double r0 = h[0] / h[1];
      diagonal[0] += h[0] * (1.0 + r0);
      upper[0] -= h[0] * r0;
      const double r1 = h[n - 2] / h[n - 3];
      diagonal[k - 1] += h[n - 2] * (1.0 + r1);
      lower[k - 1] -= h[n - 2] * r1;
    }
    solve_tridiagonal(lower, diagonal, upper, rhs);
    std::copy(rhs.begin(), rhs.end(), m.begin() + 1);
    if (not_a_knot) {
      const double r0 = h[0] / h[1];
      m[0] = (1.0 + r0) * m[1] - r0 * m[2];
      const double r1 = h[n - 2] / h[n - 3];
      m[n - 1] = (1.0 + r1) * m[n - 2] - r1 * m[n - 3];
    }
  }
  return from_second_derivatives(t, v, m);
}

CubicSpline CubicSpline::from_second_derivatives(std::span<const double> t,
                                                 std::span<const double> v,
                                                 std::span<const double> m) {
  check_knots(t, v.size());
  require(m.size() == t.size(), "spline second-derivative count", static_cast<double>(m.size()),
          "must equal the knot count");
  CubicSpline spline;
  spline.knots_.assign(t.begin(), t.end());
  const std::size_t n = t.size();
  spline.coefficients_.resize(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = t[i + 1] - t[i];
    spline.coefficients_[i] = {v[i], (v[i + 1] - v[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0,
                               0.5 * m[i], (m[i + 1] - m[i]) / (6.0 * h)};
  }
  // Equal spacing to 1e-9 relative, except perhaps a last interval of its own length, is treated
  // as uniform: the O(1) lookup then misplaces a point by at most that fraction of an interval,
  // which locate() corrects, and clamps everything beyond into the last interval.
  const double step = t[1] - t[0];
  spline.uniform_ = true;
  for (std::size_t i = 0; i + 2 < n && spline.uniform_; ++i)
    spline.uniform_ = std::abs(t[i + 1] - t[i] - step) <= 1e-9 * step;
  spline.inverse_spacing_ = 1.0 / step;
  return spline;
}

std::size_t CubicSpline::locate(double t) const {
  const std::size_t last = coefficients_.size() - 1;
  if (!(t > knots_.front())) return 0;
  if (t >= knots_.back()) return last;
  if (uniform_) {
    auto i = static_cast<std::size_t>((t - knots_.front()) * inverse_spacing_);
    i = std::min(i, last);
    // Rounding can put t one interval off; step back into [t_i, t_{i+1}).
    if (t < knots_[i] && i > 0) --i;
    if (t >= knots_[i + 1] && i < last) ++i;
    return i;
  }
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), t);
  return std::min(static_cast<std::size_t>(it - knots_.begin()) - 1, last);
}

double CubicSpline::value(double t) const {
  const std::size_t i = locate(t);
  const auto& c = coefficients_[i];
  const double u = t - knots_[i];
  return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
}

double CubicSpline::derivative(double t) const {
  const std::size_t i = locate(t);
  const auto& c = coefficients_[i];
  const double u = t - knots_[i];
  return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]);
}

double CubicSpline::second_derivative(double t) const {
  const std::size_t i = locate(t);
  const auto& c = coefficients_[i];
  return 2.0 * c[2] + 6.0 * c[3] * (t - knots_[i]);
}

CubicSpline CubicSpline::shifted(double offset) const {
  CubicSpline copy = *this;
  for (auto& c : copy.coefficients_) c[0] += offset;
  return copy;
}

}  // namespace wheelwear::profiles
