#include "wheelwear/profiles/curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/smoothing_spline.hpp"

namespace wheelwear::profiles {

namespace {

// Five-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun, Table 25.4): exact for
// polynomials up to degree 9, so the speed sqrt(y'^2 + z'^2) of a cubic piece is integrated to
// near round-off wherever it does not approach zero.
constexpr std::array<double, 5> kNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                          -0.9061798459386640, 0.9061798459386640};
constexpr std::array<double, 5> kWeights = {0.5688888888888889, 0.4786286704993665,
                                            0.4786286704993665, 0.2369268850561891,
                                            0.2369268850561891};

double speed(const CubicSpline& y, const CubicSpline& z, std::size_t i, double u) {
  const auto& a = y.coefficients(i);
  const auto& b = z.coefficients(i);
  const double dy = a[1] + u * (2.0 * a[2] + 3.0 * u * a[3]);
  const double dz = b[1] + u * (2.0 * b[2] + 3.0 * u * b[3]);
  return std::hypot(dy, dz);
}

// Arc length of interval i of the chord-length splines from its start to local parameter u.
double partial_length(const CubicSpline& y, const CubicSpline& z, std::size_t i, double u) {
  double sum = 0.0;
  for (std::size_t k = 0; k < kNodes.size(); ++k)
    sum += kWeights[k] * speed(y, z, i, 0.5 * u * (1.0 + kNodes[k]));
  return 0.5 * u * sum;
}

std::vector<double> chord_lengths(const PointList& points) {
  std::vector<double> u(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double d = (points[i] - points[i - 1]).norm();
    require(d > 0.0, "distance between consecutive profile points [m]", d,
            "must be > 0 (merge duplicate points first)");
    u[i] = u[i - 1] + d;
  }
  return u;
}

}  // namespace

void CurveOptions::validate() const {
  require(std::isfinite(smoothing_length) && smoothing_length >= 0.0, "smoothing length [m]",
          smoothing_length, "must be finite and >= 0");
  require(std::isfinite(knot_spacing) && knot_spacing > 0.0, "knot spacing [m]", knot_spacing,
          "must be finite and > 0");
}

ArcLengthCurve::ArcLengthCurve(const PointList& input, const CurveOptions& options) {
  options.validate();
  require(input.size() >= 4, "number of curve points", static_cast<double>(input.size()),
          "at least 4 points are needed");
  for (const Point& p : input) {
    require_finite("profile y [m]", p[0]);
    require_finite("profile z [m]", p[1]);
  }
  PointList points = input;
  std::vector<double> u = chord_lengths(points);
  if (options.smoothing_length > 0.0) {
    Eigen::MatrixXd values(static_cast<Eigen::Index>(points.size()), 2);
    for (std::size_t i = 0; i < points.size(); ++i)
      values.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    const double lambda =
        smoothing_lambda(options.smoothing_length, u.back() / static_cast<double>(u.size() - 1));
    const Eigen::MatrixXd smoothed = smooth_values(u, values, lambda);
    for (std::size_t i = 0; i < points.size(); ++i)
      points[i] = smoothed.row(static_cast<Eigen::Index>(i)).transpose();
    // The smoothed points have their own chord lengths, closer to the arc length of the result.
    u = chord_lengths(points);
  }
  std::vector<double> py(points.size()), pz(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    py[i] = points[i][0];
    pz[i] = points[i][1];
  }
  const CubicSpline cy = CubicSpline::interpolate(u, py);
  const CubicSpline cz = CubicSpline::interpolate(u, pz);

  // Cumulative arc length at the chord-length knots.
  const std::size_t segments = cy.segment_count();
  std::vector<double> cumulative(segments + 1, 0.0);
  for (std::size_t i = 0; i < segments; ++i)
    cumulative[i + 1] = cumulative[i] + partial_length(cy, cz, i, u[i + 1] - u[i]);
  const double total = cumulative.back();
  require(total > 0.0, "profile length [m]", total, "must be > 0");

  // Arc lengths 0, h, 2h, ... and the end; for each, the chord parameter by safeguarded Newton
  // iteration on the partial arc length within its interval. A curve shorter than 3 h gets 3 equal
  // intervals (the not-a-knot spline needs 4 knots).
  const auto count =
      static_cast<std::size_t>(std::max(3.0, std::round(total / options.knot_spacing)));
  const double step = total < 3.0 * options.knot_spacing ? total / 3.0 : options.knot_spacing;
  std::vector<double> s(count + 1), ys(count + 1), zs(count + 1);
  for (std::size_t j = 0; j <= count; ++j) {
    const double target = j == count ? total : step * static_cast<double>(j);
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
    const std::size_t i = std::min<std::size_t>(
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cumulative.begin() - 1, 0)),
        segments - 1);
    const double h = u[i + 1] - u[i];
    const double piece = cumulative[i + 1] - cumulative[i];
    double lo = 0.0, hi = h;
    double x = piece > 0.0 ? h * (target - cumulative[i]) / piece : 0.0;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double g = cumulative[i] + partial_length(cy, cz, i, x) - target;
      if (g > 0.0)
        hi = x;
      else
        lo = x;
      if (std::abs(g) <= 1e-14 * total) break;
      const double v = speed(cy, cz, i, x);
      double next = v > 0.0 ? x - g / v : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - x) <= 1e-15 * h) break;
      x = next;
    }
    s[j] = target;
    const auto& a = cy.coefficients(i);
    const auto& b = cz.coefficients(i);
    ys[j] = a[0] + x * (a[1] + x * (a[2] + x * a[3]));
    zs[j] = b[0] + x * (b[1] + x * (b[2] + x * b[3]));
  }
  s.back() = total;
  y_ = CubicSpline::interpolate(s, ys);
  z_ = CubicSpline::interpolate(s, zs);
}

Point ArcLengthCurve::position(double s) const {
  s = std::clamp(s, 0.0, length());
  const std::size_t i = y_.locate(s);
  const double u = s - y_.knots()[i];
  const auto& a = y_.coefficients(i);
  const auto& b = z_.coefficients(i);
  return {a[0] + u * (a[1] + u * (a[2] + u * a[3])), b[0] + u * (b[1] + u * (b[2] + u * b[3]))};
}

Point ArcLengthCurve::derivative(double s) const {
  s = std::clamp(s, 0.0, length());
  const std::size_t i = y_.locate(s);
  const double u = s - y_.knots()[i];
  const auto& a = y_.coefficients(i);
  const auto& b = z_.coefficients(i);
  return {a[1] + u * (2.0 * a[2] + 3.0 * u * a[3]), b[1] + u * (2.0 * b[2] + 3.0 * u * b[3])};
}

Point ArcLengthCurve::second_derivative(double s) const {
  s = std::clamp(s, 0.0, length());
  const std::size_t i = y_.locate(s);
  const double u = s - y_.knots()[i];
  const auto& a = y_.coefficients(i);
  const auto& b = z_.coefficients(i);
  return {2.0 * a[2] + 6.0 * u * a[3], 2.0 * b[2] + 6.0 * u * b[3]};
}

double ArcLengthCurve::signed_curvature(double s) const {
  const Point d1 = derivative(s);
  const Point d2 = second_derivative(s);
  const double v = d1.norm();
  return (d1[0] * d2[1] - d1[1] * d2[0]) / (v * v * v);
}

PointList ArcLengthCurve::knot_points() const {
  PointList points;
  points.reserve(y_.knots().size());
  for (std::size_t i = 0; i < y_.segment_count(); ++i)
    points.emplace_back(y_.coefficients(i)[0], z_.coefficients(i)[0]);
  points.push_back(position(length()));
  return points;
}

PointList ArcLengthCurve::sample(double spacing) const {
  require(std::isfinite(spacing) && spacing > 0.0, "sample spacing [m]", spacing,
          "must be finite and > 0");
  const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil(length() / spacing - 1e-9)));
  PointList points;
  points.reserve(count + 1);
  for (std::size_t k = 0; k <= count; ++k)
    points.push_back(position(length() * static_cast<double>(k) / static_cast<double>(count)));
  return points;
}

ArcLengthCurve ArcLengthCurve::translated(const Point& offset) const {
  ArcLengthCurve moved;
  moved.y_ = y_.shifted(offset[0]);
  moved.z_ = z_.shifted(offset[1]);
  return moved;
}

}  // namespace wheelwear::profiles
