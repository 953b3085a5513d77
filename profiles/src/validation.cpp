#include "wheelwear/profiles/validation.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Segment2 = Kernel::Segment_2;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

std::string mm(double metres) {
  std::ostringstream out;
  out.precision(6);
  out << metres * 1e3 << " mm";
  return out.str();
}

std::string line_of(const RawProfile& raw, std::size_t i) {
  return i < raw.lines.size() && raw.lines[i] > 0 ? std::to_string(raw.lines[i]) : "?";
}

int line_number(const RawProfile& raw, std::size_t i) {
  return i < raw.lines.size() ? raw.lines[i] : 0;
}

// The lines of points i and j, the smaller first (orientation may have reversed the order).
std::pair<std::string, std::string> in_file_order(const RawProfile& raw, std::size_t i,
                                                  std::size_t j) {
  const int a = line_number(raw, i), b = line_number(raw, j);
  if (a > 0 && b > 0 && b < a) return {line_of(raw, j), line_of(raw, i)};
  return {line_of(raw, i), line_of(raw, j)};
}

}  // namespace

void ValidationOptions::validate() const {
  require(min_points >= 4, "minimum point count", static_cast<double>(min_points),
          "must be at least 4 (a cubic spline needs 4)");
  require(std::isfinite(max_gap) && max_gap > 0.0, "maximum gap [m]", max_gap, "must be > 0");
  require(std::isfinite(min_extent) && min_extent > 0.0 && max_extent > min_extent &&
              std::isfinite(max_extent),
          "plausible extent [m]", min_extent, "needs 0 < min_extent < max_extent");
  require(std::isfinite(order_tolerance) && order_tolerance >= 0.0, "order tolerance [m]",
          order_tolerance, "must be >= 0");
}

std::optional<SelfIntersection> find_self_intersection(const PointList& points) {
  if (points.size() < 3) return std::nullopt;
  const std::size_t segments = points.size() - 1;
  std::vector<Segment2> segs;
  std::vector<Box> boxes;
  segs.reserve(segments);
  boxes.reserve(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    segs.emplace_back(Point2(points[i][0], points[i][1]),
                      Point2(points[i + 1][0], points[i + 1][1]));
    boxes.emplace_back(segs.back().bbox(), i);
  }
  std::optional<SelfIntersection> found;
  auto consider = [&](std::size_t a, std::size_t b) {
    if (a > b) std::swap(a, b);
    if (found && (a > found->first || (a == found->first && b >= found->second))) return;
    bool crosses = false;
    if (b == a + 1) {
      // Neighbours share a point; they cross only if they run back over each other.
      const Point2& p = segs[a].source();
      const Point2& q = segs[a].target();
      const Point2& r = segs[b].target();
      crosses = CGAL::orientation(p, q, r) == CGAL::COLLINEAR && (q - p) * (r - q) < 0.0;
    } else if (a == 0 && b == segments - 1 && segs[a].source() == segs[b].target()) {
      crosses = false;  // a closed polyline's first and last segments share their end point
    } else {
      crosses = CGAL::do_intersect(segs[a], segs[b]);
    }
    if (!crosses) return;
    Point where((points[b][0] + points[b + 1][0]) / 2.0, (points[b][1] + points[b + 1][1]) / 2.0);
    if (b != a + 1) {
      const auto result = CGAL::intersection(segs[a], segs[b]);
      if (result) {
        // CGAL 5.5 returns boost::optional<boost::variant<Point_2, Segment_2>>.
        if (const Point2* p = boost::get<Point2>(&*result))
          where = Point(p->x(), p->y());
        else if (const Segment2* s = boost::get<Segment2>(&*result))
          where = Point(s->source().x(), s->source().y());
      }
    }
    found = SelfIntersection{a, b, where};
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(),
                                [&](const Box& a, const Box& b) { consider(a.info(), b.info()); });
  return found;
}

void validate_points(const RawProfile& raw, const ValidationOptions& options) {
  options.validate();
  if (raw.points.empty())
    throw InputError(raw.source + ": no profile points found (expected rows of two numbers)");
  for (std::size_t i = 0; i < raw.points.size(); ++i)
    for (int c = 0; c < 2; ++c)
      if (!std::isfinite(raw.points[i][c])) {
        std::ostringstream message;
        message << raw.where(i) << ": " << (c == 0 ? "y" : "z") << " = " << raw.points[i][c]
                << ": not a finite number";
        throw InputError(message.str());
      }
  if (raw.points.size() < options.min_points)
    throw InputError(raw.source + ": only " + std::to_string(raw.points.size()) +
                     (raw.points.size() == 1 ? " profile point" : " profile points") +
                     "; at least " + std::to_string(options.min_points) + " are needed");
  // The extent between the 5th and 95th percentiles of y: a factor 1000 scales it like every
  // other length, while a few stray points (left to the cleaning's bounding box) do not move it.
  std::vector<double> ys;
  ys.reserve(raw.points.size());
  for (const Point& p : raw.points) ys.push_back(p[0]);
  std::sort(ys.begin(), ys.end());
  const std::size_t cut = ys.size() / 20;
  const double extent = ys[ys.size() - 1 - cut] - ys[cut];
  if (extent < options.min_extent || extent > options.max_extent) {
    std::ostringstream message;
    message << raw.source << ": lateral extent " << extent
            << " m (5th to 95th percentile of y) is implausible for a wheel or rail profile "
            << "(expected " << options.min_extent << " to " << options.max_extent << " m)";
    if (extent > options.max_extent && extent / 1000.0 >= options.min_extent &&
        extent / 1000.0 <= options.max_extent)
      message << ": the coordinates look 1000 times too large (millimetres read as metres?)";
    else if (extent < options.min_extent && extent * 1000.0 >= options.min_extent &&
             extent * 1000.0 <= options.max_extent)
      message << ": the coordinates look 1000 times too small (metres read as millimetres?)";
    throw InputError(message.str());
  }
}

void validate_order(const RawProfile& raw, Body body, const ValidationOptions& options) {
  options.validate();
  if (!options.monotonic_y.value_or(body == Body::rail) || raw.points.empty()) return;
  std::size_t furthest = 0;
  for (std::size_t i = 1; i < raw.points.size(); ++i) {
    if (raw.points[i][0] >= raw.points[furthest][0]) {
      furthest = i;
      continue;
    }
    const double back = raw.points[furthest][0] - raw.points[i][0];
    if (back <= options.order_tolerance) continue;
    // Named in file order, with the values as the file writes them: orientation may have
    // mirrored and reversed the points.
    std::size_t later = i, earlier = furthest;
    if (i < raw.lines.size() && furthest < raw.lines.size() && raw.lines[i] > 0 &&
        raw.lines[furthest] > raw.lines[i])
      std::swap(later, earlier);
    std::string message = raw.where(later) + ": " + raw.as_written(later) + " after " +
                          raw.as_written(earlier) + " at line " + line_of(raw, earlier) +
                          ": the points go back " + mm(back) + " across the profile" +
                          raw.written_note() + "; a " + std::string(to_string(body)) +
                          " profile must run monotonically in y (points out of order?)";
    if (body == Body::rail) {
      // Deep below the top, the likely cause is a gauge face that recedes (an undercut).
      double top = raw.points.front()[1];
      for (const Point& p : raw.points) top = std::min(top, p[1]);
      const double depth = std::min(raw.points[i][1], raw.points[furthest][1]) - top;
      if (depth > 0.014)
        message += ". Both points lie " + mm(depth) +
                   " or more below the top of rail, deeper than the gauge point: a gauge face "
                   "that recedes there (an undercut) is cut off by cropping the rail at a "
                   "smaller depth (LoadOptions::crop_depth, profile --crop-depth)";
    }
    throw InputError(message);
  }
}

void validate_geometry(const RawProfile& raw, const ValidationOptions& options) {
  options.validate();
  if (raw.points.size() < options.min_points)
    throw InputError(raw.source + ": only " + std::to_string(raw.points.size()) +
                     " profile points left after cleaning; at least " +
                     std::to_string(options.min_points) + " are needed");
  for (std::size_t i = 0; i + 1 < raw.points.size(); ++i) {
    const double gap = (raw.points[i + 1] - raw.points[i]).norm();
    if (gap > options.max_gap) {
      const auto [first, second] = in_file_order(raw, i, i + 1);
      throw InputError(raw.source + ": gap of " + mm(gap) + " between the points of lines " +
                       first + " and " + second + " exceeds the " + mm(options.max_gap) +
                       " limit (missing data?)");
    }
  }
  if (const auto crossing = find_self_intersection(raw.points)) {
    auto first = in_file_order(raw, crossing->first, crossing->first + 1);
    auto second = in_file_order(raw, crossing->second, crossing->second + 1);
    if (line_number(raw, crossing->second) < line_number(raw, crossing->first) &&
        line_number(raw, crossing->second) > 0)
      std::swap(first, second);
    throw InputError(raw.source + ": the profile crosses itself: the segment between lines " +
                     first.first + " and " + first.second + " meets the segment " +
                     "between lines " + second.first + " and " + second.second +
                     " near (y, z) = (" + mm(crossing->where[0]) + ", " + mm(crossing->where[1]) +
                     ") in the profile frame");
  }
}

}  // namespace wheelwear::profiles
