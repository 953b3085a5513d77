#pragma once
/// A plane curve (y(s), z(s)) parametrised by arc length: C2 cubic splines on uniform knots.

#include <cstddef>

#include "wheelwear/profiles/cubic_spline.hpp"
#include "wheelwear/profiles/types.hpp"

namespace wheelwear::profiles {

/// How a curve is built from points.
struct CurveOptions {
  /// Smoothing length scale L [m], >= 0: the fit attenuates features of wavelength 2 pi L by half
  /// and passes much longer ones (smoothing_spline.hpp). 0 interpolates the points.
  double smoothing_length = 0.0;
  /// Spacing of the arc-length knots [m], > 0: knots sit at s = 0, h, 2h, ... exactly, and the
  /// last interval takes the remainder (0.5 h to 1.5 h). Exact multiples keep the knots of an
  /// unchanged stretch in place when a profile is rebuilt (wear_update.hpp). Position errors of
  /// the representation scale with h^2 at curvature jumps (about 5e-8 m where the 60E1 R13 meets
  /// its flank, 1/13 mm of jump).
  double knot_spacing = 0.25e-3;

  /// Throws InputError unless both values are finite and in range.
  void validate() const;
};

/// A parametric C2 curve in arc length s in [0, length()] [m]. Built by (optional) Reinsch
/// smoothing of the points in chord length, a not-a-knot interpolating spline through them,
/// Gauss-Legendre arc length, and re-interpolation at equally spaced arc lengths. The knots are
/// uniform, so finding the interval of any s is O(1). |dc/ds| = 1 up to the interpolation error.
/// Where the points' curvature jumps (joints of arcs), the C2 curve spreads the jump over about one
/// knot interval, overshooting by up to a quarter of it and damping by 2 - sqrt(3) per interval.
class ArcLengthCurve {
 public:
  /// An empty curve; assign a built one before use.
  ArcLengthCurve() = default;

  /// Curve through (or, with smoothing, near) the points in their order. Needs at least 4 points
  /// and no two consecutive points at the same place; throws InputError otherwise.
  explicit ArcLengthCurve(const PointList& points, const CurveOptions& options = {});

  /// Total arc length [m].
  double length() const { return y_.knots().back(); }
  /// Spacing of the knots [m] (all intervals but the last).
  double knot_spacing() const { return y_.knots()[1] - y_.knots()[0]; }
  /// The knots s_i [m]: 0, h, 2h, ..., length().
  const std::vector<double>& knots() const { return y_.knots(); }
  /// Number of knot intervals.
  std::size_t segment_count() const { return y_.segment_count(); }
  /// The spline y(s) [m].
  const CubicSpline& y_spline() const { return y_; }
  /// The spline z(s) [m].
  const CubicSpline& z_spline() const { return z_; }

  /// Position c(s) [m]; s is clamped to [0, length()].
  Point position(double s) const;
  /// First derivative dc/ds [-], close to the unit tangent.
  Point derivative(double s) const;
  /// Second derivative d2c/ds2 [1/m].
  Point second_derivative(double s) const;
  /// Signed curvature (y' z'' - z' y'') / |c'|^3 [1/m]: positive where the curve turns from +y
  /// towards +z as s increases.
  double signed_curvature(double s) const;

  /// The curve at the knots [m].
  PointList knot_points() const;
  /// Points at equal arc-length steps no longer than `spacing` [m], both ends included.
  PointList sample(double spacing) const;

  /// This curve moved by `offset` [m], same parametrisation.
  ArcLengthCurve translated(const Point& offset) const;

 private:
  CubicSpline y_;
  CubicSpline z_;
};

}  // namespace wheelwear::profiles
