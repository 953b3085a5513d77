#include "wheelwear/contactgeom/patch_measures.hpp"

#include <algorithm>
#include <cmath>
// Boost 1.74's robustness policy (used by is_valid) trips GCC's -Wmaybe-uninitialized on
// members it always sets before use; silence it for these headers only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#pragma GCC diagnostic pop
#include <string>
#include <utility>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
// Counter-clockwise, open rings, as PatchRing documents; bg::correct fixes other orientations.
using Polygon = bg::model::polygon<Point, /*ClockWise=*/false, /*Closed=*/false>;
using MultiPolygon = bg::model::multi_polygon<Polygon>;

MultiPolygon to_boost(const std::vector<PatchRing>& rings) {
  MultiPolygon multi;
  multi.reserve(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const PatchRing& ring = rings[r];
    require(ring.size() >= 3, "rings[" + std::to_string(r) + "].size",
            static_cast<double>(ring.size()), "a patch outline needs at least 3 vertices");
    Polygon polygon;
    polygon.outer().reserve(ring.size());
    for (const Eigen::Vector2d& v : ring) {
      require_finite("ring vertex x", v.x());
      require_finite("ring vertex y", v.y());
      polygon.outer().emplace_back(v.x(), v.y());
    }
    multi.push_back(std::move(polygon));
  }
  bg::correct(multi);
  return multi;
}

}  // namespace

PatchMeasures measure_polygons(const std::vector<PatchRing>& rings, double y_O) {
  require(!rings.empty(), "rings.size", 0.0, "a patch needs at least one outline ring");
  require_finite("y_O", y_O);
  const MultiPolygon multi = to_boost(rings);
  std::string reason;
  if (!bg::is_valid(multi, reason)) {
    throw InputError("patch outline: not a set of disjoint simple polygons (" + reason + ")");
  }
  PatchMeasures m;
  m.area = bg::area(multi);
  require(m.area > 0.0, "area", m.area, "the patch outline encloses no area");
  Point centroid(0.0, 0.0);
  bg::centroid(multi, centroid);
  m.centroid_x = centroid.x();
  m.centroid_y = centroid.y();
  bg::model::box<Point> box;
  bg::envelope(multi, box);
  m.length = box.max_corner().x() - box.min_corner().x();
  m.width = box.max_corner().y() - box.min_corner().y();
  m.y_O = y_O;
  m.W1 = box.max_corner().y() - y_O;
  m.W2 = y_O - box.min_corner().y();
  return m;
}

namespace {

// How far the patch reaches beyond the centre of its outermost strip in contact `edge`, towards
// the next one [m], between 0 and one strip width: where x_lead^2 (the strip's penetration over
// its curvature), taken linear from `edge` to the strip beyond it, which lacks `outside` of it
// (KpStrip::opening), falls to zero. The patch's edges then move continuously as a strip comes
// into contact or leaves it (the reach falls to 0 as the strip leaves, and the next strip's
// reaches a whole strip as the one beyond it is just out), so the patch's width and its SDEC are
// continuous in the wheelset's position (a quasi-static solver converges on them). Where the
// strip beyond is not known (NaN, or 0: strips built without their openings), x_lead^2 is
// extrapolated linearly from `inner` (the strip next to it inside); half a strip, as a
// staircase outline gives, when there is no inner strip in contact or x_lead^2 does not fall
// towards the edge.
double edge_reach(const KpStrip& edge, const KpStrip* inner, double outside, double ds) {
  const double outer2 = edge.x_lead * edge.x_lead;
  if (outside > 0.0) return ds * outer2 / (outer2 + outside);
  if (inner == nullptr || !(inner->x_lead > 0.0)) return 0.5 * ds;
  const double fall = inner->x_lead * inner->x_lead - outer2;
  if (!(fall > 0.0)) return 0.5 * ds;
  return std::min(ds, ds * outer2 / fall);
}

bool touches(const KpStrip& strip) {
  return strip.x_lead > 0.0;
}

// The piece of the patch (a run of strips in contact) that holds O, or the one nearest to it
// (O blended between two bands may lie between them; where it crosses the middle of the strips
// between, the piece changes and the edges move by the bands' unshared reach).
std::pair<std::size_t, std::size_t> piece_at_O(const KpPatch& patch, std::size_t first,
                                               std::size_t last) {
  const std::vector<KpStrip>& strips = patch.strips;
  std::size_t best = first;
  for (std::size_t k = first; k <= last; ++k)
    if (touches(strips[k]) &&
        std::abs(strips[k].s - patch.s_O) < std::abs(strips[best].s - patch.s_O))
      best = k;
  std::size_t lo = best, hi = best;
  while (lo > first && touches(strips[lo - 1])) --lo;
  while (hi < last && touches(strips[hi + 1])) ++hi;
  return {lo, hi};
}

// The patch's edge on the side `dir` (+1: +s, -1: -s) [m]. The piece that holds O reaches to its
// outermost strip's edge (edge_reach). A piece beyond strips out of contact moves the edge
// outwards by the share d / (d + r) of its own reach, with d its deepest x_lead^2 and r the
// largest opening of the strips between it and the piece of O: a piece that appears or vanishes
// (d = 0) adds nothing and one that is about to join (r = 0) adds all of its reach, so the edge,
// the SDEC and the creep forces stay continuous as a worn tread's separate bands come into
// contact and leave it.
double lateral_edge(const KpPatch& patch, std::size_t first, std::size_t last, int dir) {
  const std::vector<KpStrip>& strips = patch.strips;
  const auto [lo, hi] = piece_at_O(patch, first, last);
  const auto step = [dir](std::size_t k) { return dir > 0 ? k + 1 : k - 1; };
  const std::size_t end = dir > 0 ? last : first;
  const auto outer_edge = [&](std::size_t from, std::size_t to) {  // `to`: the outermost strip
    const KpStrip* inner = from != to ? &strips[dir > 0 ? to - 1 : to + 1] : nullptr;
    // Beyond `to`: a strip of the list out of contact, or the one beyond the list's end.
    const bool listed = dir > 0 ? to + 1 < strips.size() : to > 0;
    const double outside =
        listed ? strips[step(to)].opening : (dir > 0 ? patch.opening_after : patch.opening_before);
    return strips[to].s + dir * edge_reach(strips[to], inner, outside, patch.ds);
  };
  double edge = dir > 0 ? outer_edge(lo, hi) : outer_edge(hi, lo);
  std::size_t k = dir > 0 ? hi : lo;
  double opening = 0.0;
  while (k != end) {
    k = step(k);
    if (!touches(strips[k])) {
      opening = std::max(opening, strips[k].opening);
      continue;
    }
    const std::size_t from = k;
    double deepest = strips[k].x_lead * strips[k].x_lead;
    while (k != end && touches(strips[step(k)])) {
      k = step(k);
      deepest = std::max(deepest, strips[k].x_lead * strips[k].x_lead);
    }
    const double share = deepest / (deepest + opening);
    edge += share * (outer_edge(from, k) - edge);
  }
  return edge;
}

}  // namespace

PatchMeasures measure_patch(const KpPatch& patch) {
  // Direct sums over the strips: the same numbers as Boost.Geometry on the staircase outline,
  // without building it (this runs once per patch and position in the wear loop).
  double area_over_2ds = 0.0;
  double moment_y = 0.0;
  double max_xl = 0.0;
  std::size_t first = patch.strips.size(), last = 0;
  for (std::size_t k = 0; k < patch.strips.size(); ++k) {
    const KpStrip& strip = patch.strips[k];
    if (!(strip.x_lead > 0.0)) continue;
    area_over_2ds += strip.x_lead;
    moment_y += strip.x_lead * strip.s;
    max_xl = std::max(max_xl, strip.x_lead);
    first = std::min(first, k);
    last = k;
  }
  require(first < patch.strips.size(), "patch.strips", static_cast<double>(patch.strips.size()),
          "no strip of the patch is in contact");
  // O blended between two bands can lie in the strips between them (blended_minimum.hpp): the
  // extent reaches half a strip beyond it at least, so that O stays inside the SDEC.
  const double y_min = std::min(lateral_edge(patch, first, last, -1), patch.s_O - 0.5 * patch.ds);
  const double y_max = std::max(lateral_edge(patch, first, last, +1), patch.s_O + 0.5 * patch.ds);
  PatchMeasures m;
  m.area = 2.0 * patch.ds * area_over_2ds;
  m.centroid_x = 0.0;
  m.centroid_y = moment_y / area_over_2ds;
  m.length = 2.0 * max_xl;
  m.width = y_max - y_min;
  m.y_O = patch.s_O;
  m.W1 = y_max - patch.s_O;
  m.W2 = patch.s_O - y_min;
  return m;
}

std::vector<PatchRing> patch_outline(const KpPatch& patch) {
  std::vector<PatchRing> rings;
  const std::size_t n = patch.strips.size();
  const double half = 0.5 * patch.ds;
  std::size_t j = 0;
  while (j < n) {
    if (!(patch.strips[j].x_lead > 0.0)) {
      ++j;
      continue;
    }
    std::size_t last = j;
    while (last + 1 < n && patch.strips[last + 1].x_lead > 0.0) ++last;
    PatchRing ring;
    ring.reserve(4 * (last - j + 1));
    // Neighbouring strips of equal x_lead would repeat a vertex; skip the repeat.
    auto add = [&ring](double x, double y) {
      if (ring.empty() || ring.back().x() != x || ring.back().y() != y) ring.emplace_back(x, y);
    };
    // Up the leading side (x > 0), then down the trailing side: counter-clockwise.
    for (std::size_t k = j; k <= last; ++k) {
      const KpStrip& s = patch.strips[k];
      add(s.x_lead, s.s - half);
      add(s.x_lead, s.s + half);
    }
    for (std::size_t k = last + 1; k-- > j;) {
      const KpStrip& s = patch.strips[k];
      add(-s.x_lead, s.s + half);
      add(-s.x_lead, s.s - half);
    }
    rings.push_back(std::move(ring));
    j = last + 1;
  }
  return rings;
}

}  // namespace wheelwear::contactgeom
