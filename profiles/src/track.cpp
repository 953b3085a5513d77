#include "wheelwear/profiles/track.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

// Minimum of f on [a, b] by golden-section search (f unimodal there); returns the argument.
double golden_minimum(const std::function<double(double)>& f, double a, double b) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 100 && b - a > 1e-15; ++i) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - r * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + r * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

void TrackGeometry::validate() const {
  require(std::isfinite(gauge) && gauge > 0.0, "track gauge [m]", gauge, "must be > 0");
  require(std::isfinite(gauge_measuring_depth) && gauge_measuring_depth > 0.0 &&
              gauge_measuring_depth < 0.05,
          "gauge measuring depth [m]", gauge_measuring_depth, "must be in (0, 0.05)");
}

ProfilePoint top_of_rail(const Profile& rail) {
  const double h = rail.curve().knot_spacing();
  const std::vector<double>& knots = rail.curve().knots();
  std::size_t best = 0;
  for (std::size_t k = 0; k < knots.size(); ++k)
    if (rail.position(knots[k])[1] < rail.position(knots[best])[1]) best = k;
  const double s_best = knots[best];
  const double s = golden_minimum([&](double t) { return rail.position(t)[1]; },
                                  std::max(0.0, s_best - h), std::min(rail.length(), s_best + h));
  return {rail.position(s), s};
}

ProfilePoint gauge_point(const Profile& rail, double measuring_depth) {
  require(std::isfinite(measuring_depth) && measuring_depth > 0.0, "gauge measuring depth [m]",
          measuring_depth, "must be > 0");
  const ProfilePoint top = top_of_rail(rail);
  const double level = top.point[1] + measuring_depth;
  const double h = rail.curve().knot_spacing();
  // Walk from the top towards the gauge side (s decreasing) until the surface is deeper than the
  // measuring level, then locate the crossing by bisection.
  double s_in = top.s, s_out = -1.0;
  for (double s = top.s - h; s >= -0.5 * h; s -= h) {
    const double t = std::max(s, 0.0);
    if (rail.position(t)[1] > level) {
      s_out = t;
      break;
    }
    s_in = t;
  }
  require(s_out >= 0.0, "rail profile depth on the gauge side [m]",
          rail.position(0.0)[1] - top.point[1],
          "must reach the gauge measuring depth below the top of rail");
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (s_in + s_out);
    if (rail.position(mid)[1] > level)
      s_out = mid;
    else
      s_in = mid;
  }
  // The point nearest the track centre between the crossing and the top: on a new head it is the
  // crossing itself; a worn, overhanging gauge corner can put it higher up.
  ProfilePoint best{rail.position(s_in), s_in};
  for (double s = s_in; s <= top.s; s += h)
    if (rail.position(s)[0] < best.point[0]) best = {rail.position(s), s};
  if (best.s > s_in) {
    const double s = golden_minimum([&](double t) { return rail.position(t)[0]; },
                                    std::max(s_in, best.s - h), std::min(top.s, best.s + h));
    best = {rail.position(s), s};
  }
  return best;
}

std::optional<InclinationEstimate> estimate_inclination(const Profile& rail, double axis_offset,
                                                        double half_width) {
  require(std::isfinite(axis_offset) && std::isfinite(half_width) && half_width > 0.0,
          "inclination chord half width [m]", half_width, "must be > 0");
  ProfilePoint gauge;
  try {
    gauge = gauge_point(rail);
  } catch (const InputError&) {
    return std::nullopt;
  }
  const double depth = gauge.point[1] - top_of_rail(rail).point[1];
  std::optional<InclinationEstimate> estimate;
  double slope = 0.0;
  for (int step = 0; step < 2; ++step) {
    const double axis = gauge.point[0] + axis_offset - depth * slope;
    const auto a = rail.z_at(axis - half_width);
    const auto b = rail.z_at(axis + half_width);
    if (!a || !b) return std::nullopt;
    slope = (*a - *b) / (2.0 * half_width);
    estimate = InclinationEstimate{std::atan(slope), Point(axis - half_width, *a),
                                   Point(axis + half_width, *b)};
  }
  return estimate;
}

Point RailPlacement::to_track(const Point& p) const {
  const double sign = side == Side::right ? 1.0 : -1.0;
  return {sign * (p[0] - gauge_point[0] + 0.5 * gauge), p[1] - top[1]};
}

Point RailPlacement::to_profile(const Point& q) const {
  const double sign = side == Side::right ? 1.0 : -1.0;
  return {sign * q[0] - 0.5 * gauge + gauge_point[0], q[1] + top[1]};
}

RailPlacement place_rail(const Profile& rail, const TrackGeometry& track) {
  track.validate();
  if (rail.body() != Body::rail)
    throw InputError("profile " + rail.info().name + " is a wheel profile: only rails are placed");
  RailPlacement placement;
  placement.side = rail.side();
  placement.top = top_of_rail(rail).point;
  placement.gauge_point = gauge_point(rail, track.gauge_measuring_depth).point;
  placement.gauge = track.gauge;
  return placement;
}

}  // namespace wheelwear::profiles
