#pragma once
/// Checks on profile points that turn bad input into clear errors naming file, line and problem.

#include <cstddef>
#include <optional>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Limits the checks apply.
struct ValidationOptions {
  /// Fewest points a profile may have (a fit through fewer says nothing about the shape).
  std::size_t min_points = 10;
  /// Largest distance between consecutive points [m]. MiniProf samples every 0.1 to 2 mm; 5 mm
  /// without a point means missing data.
  double max_gap = 5e-3;
  /// Smallest plausible lateral extent of a wheel or rail profile [m]: real ones span 0.03 to
  /// 0.2 m, so an extent outside [min_extent, max_extent] means wrong units (a factor 1000).
  double min_extent = 0.01;
  /// Largest plausible lateral extent [m].
  double max_extent = 0.5;
  /// Whether y must run monotonically (checked by validate_order). Unset: rails yes, wheels no.
  std::optional<bool> monotonic_y{};
  /// How far y may step back before the points count as out of order [m]; smaller steps are
  /// measurement noise on a steep face and are left to the cleaning (reversing_segments).
  double order_tolerance = 0.5e-3;

  /// Throws InputError naming the first value out of range.
  void validate() const;
};

/// Where a polyline crosses itself.
struct SelfIntersection {
  std::size_t first = 0;   ///< index of the first segment (points first, first + 1)
  std::size_t second = 0;  ///< index of the second segment, > first
  Point where;             ///< approximate crossing point [m]
};

/// The first crossing (smallest first index) of two segments of the polyline through `points`,
/// with exact predicates (CGAL, Exact_predicates_inexact_constructions_kernel; candidate pairs
/// from CGAL's box_self_intersection_d). Neighbouring segments count only when they overlap.
std::optional<SelfIntersection> find_self_intersection(const PointList& points);

/// Checks points as read: at least one point, every coordinate finite, at least min_points, and a
/// plausible lateral extent (measured between the 5th and 95th percentiles of y, so that stray
/// points do not count). Throws InputError "<file>[:<line>]: <problem>".
void validate_points(const RawProfile& raw, const ValidationOptions& options = {});

/// Checks that y does not step back by more than order_tolerance where it must be monotonic
/// (oriented points). Throws InputError naming both lines in file order with the values as the
/// file writes them (RawProfile::as_written), and for a rail, when both points lie deeper than
/// the gauge point (14 mm), the likely cause: a receding gauge face, which a crop removes.
void validate_order(const RawProfile& raw, Body body, const ValidationOptions& options = {});

/// Checks cleaned points: at least min_points, no gap above max_gap, no self-intersection.
/// Throws InputError naming the lines involved, in file order.
void validate_geometry(const RawProfile& raw, const ValidationOptions& options = {});

}  // namespace wheelwear::profiles
