#pragma once
/// A one-dimensional cubic spline stored as one polynomial per knot interval.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace wheelwear::profiles {

/// Piecewise cubic v(t) on increasing knots t_0 < ... < t_{n-1}, C2 across the knots.
/// Segment i holds v(t) = c0 + c1 u + c2 u^2 + c3 u^3 with u = t - t_i. Outside the knots the
/// end polynomials are extended. Units are the caller's (profiles use metres).
class CubicSpline {
 public:
  /// End conditions of an interpolating spline.
  enum class EndCondition {
    not_a_knot,  ///< third derivative continuous at t_1 and t_{n-2}: exact for cubics, O(h^4) at
                 ///< the ends
    natural,     ///< zero second derivative at both ends
  };

  /// An empty spline; assign one from interpolate() before use.
  CubicSpline() = default;

  /// Interpolating spline through (t_i, v_i); t strictly increasing, at least 2 knots (de Boor,
  /// A Practical Guide to Splines, ch. IV). Throws InputError on bad knots.
  static CubicSpline interpolate(std::span<const double> t, std::span<const double> v,
                                 EndCondition end = EndCondition::not_a_knot);

  /// Spline with values v_i and second derivatives m_i at the knots t_i.
  static CubicSpline from_second_derivatives(std::span<const double> t, std::span<const double> v,
                                             std::span<const double> m);

  /// Number of knot intervals (n - 1).
  std::size_t segment_count() const { return coefficients_.size(); }
  /// The knots t_i.
  const std::vector<double>& knots() const { return knots_; }
  /// Whether the knots are equally spaced, the last interval excepted (then locate() is O(1),
  /// otherwise O(log n)).
  bool uniform() const { return uniform_; }

  /// Index of the interval that holds t, clamped to [0, segment_count() - 1].
  std::size_t locate(double t) const;
  /// Polynomial coefficients {c0, c1, c2, c3} of interval i, in u = t - t_i.
  const std::array<double, 4>& coefficients(std::size_t i) const { return coefficients_[i]; }

  /// v(t).
  double value(double t) const;
  /// dv/dt.
  double derivative(double t) const;
  /// d2v/dt2.
  double second_derivative(double t) const;

  /// This spline plus a constant offset [units of v].
  CubicSpline shifted(double offset) const;

 private:
  std::vector<double> knots_;
  std::vector<std::array<double, 4>> coefficients_;
  bool uniform_ = false;
  double inverse_spacing_ = 0.0;
};

/// Solves a tridiagonal system in place (Thomas algorithm, no pivoting: for diagonally dominant
/// systems). lower[0] and upper[n-1] are unused; the solution replaces rhs.
void solve_tridiagonal(std::vector<double> lower, std::vector<double> diagonal,
                       std::vector<double> upper, std::vector<double>& rhs);

}  // namespace wheelwear::profiles
