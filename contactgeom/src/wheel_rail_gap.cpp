#include "wheel_rail_gap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "parabola_vertex.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::contactgeom::detail {

namespace {

// Where the tangents of the gap at two coarse points `spacing` apart cross, if their slopes
// point into a dip between them (falling at the first, rising at the second); +inf otherwise.
// Below the gap wherever it is convex between them. A vertical tangent crosses at its own point.
double dip_floor(double h0, double s0, double h1, double s1, double spacing) {
  if (!(s0 < 0.0 && s1 > 0.0) || !std::isfinite(h0) || !std::isfinite(h1))
    return std::numeric_limits<double>::infinity();
  if (std::isinf(s0) && std::isinf(s1)) return std::min(h0, h1);
  if (std::isinf(s0)) return h1 - s1 * spacing;
  if (std::isinf(s1)) return h0 + s0 * spacing;
  const double t = std::clamp((h1 - h0 - s1 * spacing) / (s0 - s1), 0.0, spacing);
  return h0 + s0 * t;
}

constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

namespace {

// A rail profile's curve, compared bit for bit: equal curves have equal gauge points.
struct CurveCopy {
  std::vector<double> knots;
  std::vector<std::array<double, 4>> y, z;

  bool same(const profiles::ArcLengthCurve& c) const {
    const std::size_t n = c.segment_count();
    if (knots.size() != n + 1 || y.size() != n) return false;
    // The coefficients of a spline are one contiguous vector (CubicSpline), compared whole.
    const std::size_t bytes = n * sizeof(std::array<double, 4>);
    return std::memcmp(knots.data(), c.knots().data(), (n + 1) * sizeof(double)) == 0 &&
           std::memcmp(y.data(), &c.y_spline().coefficients(0), bytes) == 0 &&
           std::memcmp(z.data(), &c.z_spline().coefficients(0), bytes) == 0;
  }
  void assign(const profiles::ArcLengthCurve& c) {
    const std::size_t n = c.segment_count();
    knots = c.knots();
    y.assign(&c.y_spline().coefficients(0), &c.y_spline().coefficients(0) + n);
    z.assign(&c.z_spline().coefficients(0), &c.z_spline().coefficients(0) + n);
  }
};

}  // namespace

RailDatum rail_datum(const WheelRailPair& pair) {
  // profiles::gauge_point and top_of_rail walk the whole rail (a fifth of a contact solve);
  // the last two rails seen on this thread (a wheelset's left and right) keep their answers,
  // found again by comparing the curve itself, which costs a twentieth of that.
  struct Entry {
    CurveCopy curve;
    double depth = -1.0;
    RailDatum datum;
  };
  thread_local std::array<Entry, 2> cache;
  thread_local std::size_t next = 0;
  auto compute = [&] {
    return RailDatum{profiles::gauge_point(pair.rail, pair.gauge_depth).point.x(),
                     profiles::top_of_rail(pair.rail).point.y()};
  };
  const profiles::ArcLengthCurve& curve = pair.rail.curve();
  if (curve.segment_count() == 0) return compute();
  for (const Entry& e : cache)
    if (e.depth == pair.gauge_depth && e.curve.same(curve)) return e.datum;
  Entry& e = cache[next];
  next = (next + 1) % cache.size();
  e.datum = compute();
  e.depth = pair.gauge_depth;
  e.curve.assign(curve);
  return e.datum;
}

double rail_gauge_y(const WheelRailPair& pair) {
  return rail_datum(pair).gauge_y;
}

namespace {

// The flank is scanned this finely [m]: a tenth of the 0.5 mm a flange face turns 0.025 rad in
// (R20), so the steepest sample lies within 1e-4 rad of the steepest point.
constexpr double kFlankSampling = 0.05e-3;

// Slope angle atan(-dz/dy) of the wheel surface at arc length s [rad]: + where it rises
// (z falls) towards the field side, as the active flank does; pi/2 on a vertical tangent.
double slope_angle(const profiles::Profile& wheel, double s) {
  const profiles::Point t = wheel.tangent(s);
  return std::atan2(-t[1], t[0]);
}

FlangeDatum compute_flange_datum(const profiles::Profile& wheel) {
  FlangeDatum d;
  const auto tape = wheel.surface_at(0.0);
  if (!tape) return d;
  // The tip: the largest z from the flange-side end to the taping line.
  double z_tip = -std::numeric_limits<double>::infinity();
  for (double s = 0.0; s <= tape->s; s += kFlankSampling) {
    const double z = wheel.position(s)[1];
    if (z > z_tip) {
      z_tip = z;
      d.s_tip = s;
    }
  }
  // The active flank runs from the tip to the taping line; the back face beyond the tip is not
  // part of it.
  const auto n = static_cast<std::size_t>(std::floor((tape->s - d.s_tip) / kFlankSampling)) + 1;
  if (n < 3) return d;
  thread_local std::vector<double> angle;
  angle.resize(n);
  std::size_t k_max = 0;
  for (std::size_t k = 0; k < n; ++k) {
    angle[k] = slope_angle(wheel, d.s_tip + static_cast<double>(k) * kFlankSampling);
    if (angle[k] > angle[k_max]) k_max = k;
  }
  d.found = true;
  d.s_steepest = d.s_tip + static_cast<double>(k_max) * kFlankSampling;
  d.steepest_angle = angle[k_max];
  // The sample nearest the tip within the tolerance, then the crossing of the tolerance's level
  // between it and its tip-side neighbour, by bisection to 1e-9 m.
  const double level = d.steepest_angle - kFlangeSlopeTolerance;
  std::size_t k = 0;
  while (angle[k] < level) ++k;
  d.s_limit = d.s_tip + static_cast<double>(k) * kFlankSampling;
  if (k > 0) {
    double lo = d.s_limit - kFlankSampling, hi = d.s_limit;
    while (hi - lo > 1e-9) {
      const double mid = 0.5 * (lo + hi);
      (slope_angle(wheel, mid) < level ? lo : hi) = mid;
    }
    d.s_limit = hi;
  }
  return d;
}

}  // namespace

FlangeDatum flange_datum(const profiles::Profile& wheel) {
  // A scan of the flank costs about a contact solve; the last two wheels seen on this thread (a
  // wheelset's left and right) keep theirs, found again by comparing the curve itself.
  struct Entry {
    CurveCopy curve;
    bool used = false;
    FlangeDatum datum;
  };
  thread_local std::array<Entry, 2> cache;
  thread_local std::size_t next = 0;
  const profiles::ArcLengthCurve& curve = wheel.curve();
  if (curve.segment_count() == 0) return compute_flange_datum(wheel);
  for (const Entry& e : cache)
    if (e.used && e.curve.same(curve)) return e.datum;
  Entry& e = cache[next];
  next = (next + 1) % cache.size();
  e.datum = compute_flange_datum(wheel);
  e.used = true;
  e.curve.assign(curve);
  return e.datum;
}

WheelRailGap::WheelRailGap(const WheelRailPair& pair, const WheelsetPose& pose,
                           const WheelRailOptions& options, double gauge_y)
    : pair_(pair), options_(options) {
  // The flange back lies (gauge - back_to_back)/2 on the gauge side (-y) of the gauge point.
  shift_ = gauge_y - 0.5 * (pair.gauge - pair.back_to_back) - pair.flange_back_y + pose.dy;
  const auto tape = pair.wheel.surface_at(0.0);
  z_tape_ = tape ? tape->z : 0.0;
  s_tape_ = tape ? tape->s : 0.0;
  cos_roll_ = std::cos(pose.roll);
  sin_roll_ = std::sin(pose.roll);
  rail_walk_.reset(pair.rail, 0.0, 0.0);
  wheel_walk_.reset(pair.wheel, pose.roll, z_tape_);
}

void WheelRailGap::close_rail_walk() const {
  if (!rail_walk_.open()) return;
  const auto looked_up = pair_.rail.surface_at(rail_walk_.last_y());
  if (!rail_walk_.close(looked_up ? std::optional<double>(looked_up->s) : std::nullopt))
    walk_failed_ = true;
}

void WheelRailGap::close_wheel_walk() const {
  if (!wheel_walk_.open()) return;
  const auto looked_up = wheel_at(wheel_walk_.last_y() + shift_);
  if (!wheel_walk_.close(looked_up ? std::optional<double>(looked_up->s) : std::nullopt))
    walk_failed_ = true;
}

bool WheelRailGap::close_walks() const {
  close_rail_walk();
  close_wheel_walk();
  const bool ok = !walk_failed_;
  walk_failed_ = false;
  return ok;
}

std::optional<GapPoint> WheelRailGap::walked_gap(double y) const {
  auto r = rail_walk_.at(y);
  if (!r) {
    // The walk stopped (or never started): check what it walked, look up, start again here.
    close_rail_walk();
    const auto looked_up = pair_.rail.surface_at(y);
    if (!looked_up) return std::nullopt;
    rail_walk_.seed(y, looked_up->s);
    r = WalkPoint{looked_up->z, y, looked_up->z, looked_up->s};
  }
  const double y_wheel = y - shift_;
  const auto w = wheel_walk_.at(y_wheel);
  WheelPoint wp;
  if (w) {
    wp = WheelPoint{w->z_rolled, w->z, w->y, w->s};
  } else {
    close_wheel_walk();
    const auto looked_up = wheel_at(y);
    if (!looked_up) return std::nullopt;
    wheel_walk_.seed(y_wheel, looked_up->s);
    wp = *looked_up;
  }
  return GapPoint{r->z_rolled - wp.z_rolled, wp, r->s};
}

std::optional<WheelPoint> WheelRailGap::wheel_at(double y) const {
  const double y_rolled = y - shift_;
  auto w = pair_.wheel.surface_at(y_rolled);
  if (!w) return std::nullopt;
  if (sin_roll_ == 0.0) return WheelPoint{w->z, w->z, y_rolled, w->s};
  // Newton on g(u) = cos u - sin (z(u) - z_tape) - y_rolled from u = y_rolled. The first step
  // moves u by about roll (z - z_tape): 0.2 mm at a wheelset's 7 mrad on a 28 mm flange, 3 mm at
  // the largest roll allowed (0.1 rad); the next ones converge quadratically. A vertical tangent
  // (the flange back, never in contact) keeps the first point.
  double u = y_rolled;
  for (int iteration = 0; iteration < 6; ++iteration) {
    const double g = cos_roll_ * u - sin_roll_ * (w->z - z_tape_) - y_rolled;
    if (std::abs(g) <= 1e-13) break;
    const double dg = cos_roll_ - sin_roll_ * w->dz_dy;
    if (!std::isfinite(dg) || dg < 0.1) break;
    const double next = u - g / dg;
    auto wn = pair_.wheel.surface_at(next);
    if (!wn) return std::nullopt;
    u = next;
    w = wn;
  }
  const double z_rolled = sin_roll_ * u + cos_roll_ * (w->z - z_tape_) + z_tape_;
  return WheelPoint{z_rolled, w->z, u, w->s};
}

std::optional<CoarseGap> WheelRailGap::coarse_gap(double y) const {
  const auto r = pair_.rail.surface_at(y);
  if (!r) return std::nullopt;
  const double y_rolled = y - shift_;
  const auto w = pair_.wheel.surface_at(y_rolled);
  if (!w) return std::nullopt;
  // The rolled wheel surface's slope, (sin + cos z') / (cos - sin z') of the unrolled one's z' at
  // the material point (-cot(roll) on a vertical tangent). A vertical rail tangent gives no
  // finite slope (NaN or infinite): no dip is found next to it.
  const auto gap_slope = [&](double wheel_slope) {
    double rolled = wheel_slope;
    if (sin_roll_ != 0.0)
      rolled = std::isinf(wheel_slope)
                   ? -cos_roll_ / sin_roll_
                   : (sin_roll_ + cos_roll_ * wheel_slope) / (cos_roll_ - sin_roll_ * wheel_slope);
    return r->dz_dy - rolled;
  };
  if (sin_roll_ == 0.0) return CoarseGap{r->z - w->z, gap_slope(w->dz_dy)};
  // One lookup and the first Newton step of wheel_at(), its z to first order: off by
  // z''(u) du^2 / 2, below 4e-7 m for du <= 20 um on any profile (|z''| < 2000 1/m on a
  // 70 deg flank of 13 mm radius); a longer step takes the full iteration.
  const double g = cos_roll_ * y_rolled - sin_roll_ * (w->z - z_tape_) - y_rolled;
  const double dg = cos_roll_ - sin_roll_ * w->dz_dy;
  const double du = -g / dg;
  if (std::isfinite(du) && dg >= 0.1 && std::abs(du) <= 20e-6) {
    const double u = y_rolled + du, z = w->z + w->dz_dy * du;
    // The slope at y_rolled, 20 um from the material point at most.
    return CoarseGap{r->z - (sin_roll_ * u + cos_roll_ * (z - z_tape_) + z_tape_),
                     gap_slope(w->dz_dy)};
  }
  const auto full = wheel_at(y);
  if (!full) return std::nullopt;
  const auto at_point = pair_.wheel.surface_at(full->y);
  return CoarseGap{r->z - full->z_rolled, gap_slope(at_point ? at_point->dz_dy : w->dz_dy)};
}

std::optional<GapPoint> WheelRailGap::gap(double y) const {
  const auto r = pair_.rail.surface_at(y);
  if (!r) return std::nullopt;
  const auto w = wheel_at(y);
  if (!w) return std::nullopt;
  return GapPoint{r->z - w->z_rolled, *w, r->s};
}

void WheelRailGap::scan(CoarseScan& coarse) const {
  // The rolled wheel covers about the unrolled profile's lateral range; wheel_at() reports
  // the points beyond it.
  coarse.lo = std::max(pair_.rail.y_min(), pair_.wheel.y_min() + shift_);
  coarse.hi = std::min(pair_.rail.y_max(), pair_.wheel.y_max() + shift_);
  coarse.h.clear();
  coarse.dip.clear();
  coarse.h_min = kInf;
  if (!(coarse.hi > coarse.lo)) return;
  const int n = static_cast<int>(std::floor((coarse.hi - coarse.lo) / options_.scan_spacing)) + 1;
  coarse.h.assign(static_cast<std::size_t>(n), kInf);
  coarse.dip.assign(static_cast<std::size_t>(n), kInf);
  thread_local std::vector<double> slope;
  slope.assign(static_cast<std::size_t>(n), 0.0);
  // Lookups: a walk would pass every knot interval of both curves at this spacing.
  for (int i = 0; i < n; ++i) {
    if (const auto v = coarse_gap(coarse.lo + i * options_.scan_spacing)) {
      coarse.h[i] = v->h;
      slope[i] = v->slope;
    }
    coarse.h_min = std::min(coarse.h_min, coarse.h[i]);
  }
  for (int i = 0; i + 1 < n; ++i)
    coarse.dip[i] =
        dip_floor(coarse.h[i], slope[i], coarse.h[i + 1], slope[i + 1], options_.scan_spacing);
}

void WheelRailGap::sample(const CoarseScan& coarse, double margin, GapSamples& g,
                          bool minima_only) const {
  g.dy = options_.strip_width;
  g.y.clear();
  g.h.clear();
  g.z_wheel.clear();
  g.s_rail.clear();
  g.window.clear();
  g.end_samples.clear();
  g.h_min = kInf;
  if (!std::isfinite(coarse.h_min)) return;
  const int n = static_cast<int>(coarse.h.size());
  const double lo = coarse.lo, hi = coarse.hi, spacing = options_.scan_spacing;
  const double level = coarse.h_min + margin;
  thread_local std::vector<unsigned char> keep;
  keep.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    keep[i] = coarse.h[i] < level;
    if (minima_only && keep[i])
      keep[i] = (i == 0 || coarse.h[i] <= coarse.h[i - 1]) &&
                (i == n - 1 || coarse.h[i] <= coarse.h[i + 1]);
  }
  // A dip below the level between two points neither of which is kept (CoarseScan::dip): with
  // minima_only also one whose lower point is not the coarse scan's local minimum.
  for (int i = 0; i + 1 < n; ++i)
    if (coarse.dip[i] < level && !keep[i] && !keep[i + 1]) keep[i] = keep[i + 1] = 1;
  int window = -1;
  for (int i = 0; i < n;) {
    if (!keep[i]) {
      ++i;
      continue;
    }
    int end = i;
    while (end + 1 < n && keep[end + 1]) ++end;
    const double from = std::max(lo, lo + (i - 1) * spacing);
    const double to = std::min(hi, lo + (end + 1) * spacing);
    const bool low_end = i == 0, high_end = end == n - 1;
    ++window;
    const std::size_t first = g.h.size();
    // The window's samples, each gap found by `gap_at` (walking from the last, or afresh).
    const auto sample = [&](auto gap_at) {
      for (double y = from; y <= to; y += g.dy) {
        const auto v = gap_at(y);
        if (!v) continue;
        g.y.push_back(y);
        g.h.push_back(v->h);
        g.z_wheel.push_back(v->wheel.z);
        g.s_rail.push_back(v->s_rail);
        g.window.push_back(window);
      }
    };
    sample([&](double y) { return walked_gap(y); });
    if (!close_walks()) {
      // A walked stretch did not stand: this window again, point by point.
      g.y.resize(first);
      g.h.resize(first);
      g.z_wheel.resize(first);
      g.s_rail.resize(first);
      g.window.resize(first);
      sample([&](double y) { return gap(y); });
    }
    for (std::size_t j = first; j < g.h.size(); ++j) g.h_min = std::min(g.h_min, g.h[j]);
    // A contact that reaches these samples is cut off by the end of a profile.
    if (low_end && g.h.size() > first) g.end_samples.push_back(first);
    if (high_end && g.h.size() > first) g.end_samples.push_back(g.h.size() - 1);
    i = end + 1;
  }
}

double WheelRailGap::contact_angle(double y) const {
  const auto r = pair_.rail.surface_at(y);
  return r ? std::atan(-r->dz_dy) : 0.0;
}

ContactDirection WheelRailGap::rail_direction(double s) const {
  // The tangent (dy, dz) towards increasing s; contact_angle = atan(-dz/dy) lies in
  // [-pi/2, pi/2], so its cosine is |dy| / |t|.
  const profiles::Point t = pair_.rail.curve().derivative(s);
  const double inverse = 1.0 / std::sqrt(t[0] * t[0] + t[1] * t[1]);
  return {std::abs(t[0]) * inverse, -std::copysign(inverse, t[0]) * t[1]};
}

ContactDirection WheelRailGap::contact_direction(double y) const {
  const auto r = pair_.rail.surface_at(y);
  if (!r) return {};
  const double t = -r->dz_dy;  // tan(contact angle)
  if (!std::isfinite(t)) return {0.0, std::copysign(1.0, t)};
  const double c = 1.0 / std::sqrt(1.0 + t * t);
  return {c, t * c};
}

GapMinimum refined_minimum(const GapSamples& g, std::size_t first, std::size_t last) {
  std::size_t k = first;
  for (std::size_t j = first; j <= last; ++j)
    if (g.h[j] < g.h[k]) k = j;
  GapMinimum m{g.y[k], g.h[k]};
  if (k > 0 && k + 1 < g.h.size() && g.window[k - 1] == g.window[k] &&
      g.window[k + 1] == g.window[k]) {
    if (const auto vertex = parabola_vertex(g.h[k - 1], g.h[k], g.h[k + 1])) {
      m.y = g.y[k] + vertex->offset * g.dy;
      m.h = vertex->h;
    }
  }
  return m;
}

}  // namespace wheelwear::contactgeom::detail
