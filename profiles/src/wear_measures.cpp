#include "wheelwear/profiles/wear_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelwear::profiles {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// How far the worn surface is looked for along the normal; wear of a whole service life stays
// within it (a flange loses a few millimetres).
constexpr double kReach = 10e-3;

// Parameter t of the line p + t n where it crosses the segment a-b; none if it does not.
std::optional<double> crossing(const Point& p, const Point& n, const Point& a, const Point& b) {
  const Point e = b - a;
  const double det = n.x() * (-e.y()) - n.y() * (-e.x());
  if (std::abs(det) < 1e-300) return std::nullopt;
  const Point r = a - p;
  const double t = (r.x() * (-e.y()) - r.y() * (-e.x())) / det;
  const double u = (n.x() * r.y() - n.y() * r.x()) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  return t;
}

}  // namespace

NormalWear normal_wear(const Profile& original, const Profile& worn, double spacing) {
  // The worn surface as a polyline four times finer than the grid; a point of the original is
  // looked for on the worn stretch near the same arc length (wear shortens the curve little).
  const PointList polyline = worn.resample(0.25 * spacing);
  const double worn_step = worn.length() / static_cast<double>(polyline.size() - 1);
  const auto window = static_cast<long>(std::ceil(2.0 * kReach / worn_step));
  NormalWear out;
  const auto n = static_cast<std::size_t>(std::floor(original.length() / spacing + 1e-9)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) * spacing;
    const Point p = original.position(s);
    const Point inward = -original.normal(s);
    const auto centre = static_cast<long>(
        std::lround(s / original.length() * static_cast<double>(polyline.size() - 1)));
    const long lo = std::max(0L, centre - window);
    const long hi = std::min(static_cast<long>(polyline.size()) - 1, centre + window);
    double best = kNaN;
    for (long k = lo; k < hi; ++k) {
      const auto t = crossing(p, inward, polyline[static_cast<std::size_t>(k)],
                              polyline[static_cast<std::size_t>(k + 1)]);
      if (t && std::abs(*t) <= kReach && !(std::abs(*t) >= std::abs(best))) best = *t;
    }
    out.s.push_back(s);
    out.depth.push_back(best);
  }
  return out;
}

RadiusChange radius_change(const Profile& original, const Profile& worn, double spacing) {
  RadiusChange out;
  const auto first = static_cast<long>(std::ceil(original.y_min() / spacing - 1e-9));
  const auto last = static_cast<long>(std::floor(original.y_max() / spacing + 1e-9));
  for (long k = first; k <= last; ++k) {
    const double y = static_cast<double>(k) * spacing;
    const auto z0 = original.z_at(y), z = worn.z_at(y);
    out.y.push_back(y);
    out.delta.push_back(z0 && z ? *z - *z0 : kNaN);
  }
  return out;
}

}  // namespace wheelwear::profiles
