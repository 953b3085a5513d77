#include "wheelwear/contactgeom/wheel_rail.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "resting_gap.hpp"
#include "wheel_rail_gap.hpp"
#include "wheel_rail_solve.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/internal_face.hpp"

namespace wheelwear::contactgeom {

WheelRailPair::WheelRailPair(profiles::Profile wheel_profile, profiles::Profile rail_profile)
    : wheel(std::move(wheel_profile)), rail(std::move(rail_profile)) {
  flange_back_y = profiles::internal_face(wheel).y;
  if (wheel.info().nominal_radius > 0.0) wheel_radius = wheel.info().nominal_radius;
}

void WheelRailPair::validate() const {
  require_finite("gauge", gauge);
  require(gauge > 0.5 && gauge < 2.5, "gauge", gauge, "the track gauge must lie in 0.5 ... 2.5 m");
  require(back_to_back > 0.4 && back_to_back < gauge, "back_to_back", back_to_back,
          "the back-to-back distance must be positive and smaller than the gauge (m)");
  require(wheel_radius > 0.1 && wheel_radius < 2.0, "wheel_radius", wheel_radius,
          "the wheel radius must lie in 0.1 ... 2 m");
  require(youngs_modulus > 0.0, "E", youngs_modulus, "Young's modulus must be positive (Pa)");
  require(poisson >= 0.0 && poisson < 0.5, "nu", poisson, "Poisson's ratio must lie in [0, 0.5)");
  require_finite("flange_back_y", flange_back_y);
  require(wheel.surface_at(0.0).has_value(), "wheel profile", wheel.y_min(),
          "the wheel profile must contain its taping line y = 0, where the rolling radius is "
          "wheel_radius (the value is its smallest y)");
}

void WheelRailOptions::validate() const {
  require(strip_width > 1e-6 && strip_width <= 2e-3, "strip_width", strip_width,
          "the strip width must lie in 1 um ... 2 mm");
  require(scan_spacing >= strip_width && scan_spacing <= 5e-3, "scan_spacing", scan_spacing,
          "the scan spacing must lie between the strip width and 5 mm");
  require(scan_margin > 0.0, "scan_margin", scan_margin, "must be positive");
  require_finite("load_tolerance", load_tolerance);
  require(load_tolerance > 0.0 && load_tolerance <= 1e-2, "load_tolerance", load_tolerance,
          "the relative tolerance on the vertical force must lie in (0, 0.01]");
  require(lateral_tolerance > 0.0 && lateral_tolerance < 0.1, "lateral_tolerance",
          lateral_tolerance, "must lie in (0, 0.1)");
  require(flange_angle > 0.0 && flange_angle < max_contact_angle, "flange_angle", flange_angle,
          "must lie between 0 and max_contact_angle (rad)");
  kp.validate();
}

namespace {
// As the command line, the messages and docs/results.md name them.
constexpr core::NameTable<WheelRailStatus, 7> kStatusNames = {{
    {WheelRailStatus::ok, "ok"},
    {WheelRailStatus::no_contact, "no contact"},
    {WheelRailStatus::flange_climb, "flange climb"},
    {WheelRailStatus::not_converged, "not converged"},
    {WheelRailStatus::load_jump, "load jump"},
    {WheelRailStatus::profile_end, "profile end"},
    {WheelRailStatus::past_flange, "past flange"},
}};
}  // namespace

// The table's names are string literals: data() is null-terminated.
const char* status_name(WheelRailStatus status) {
  return core::name_of(kStatusNames, status).data();
}

namespace detail {

namespace {

// How far a flank steeper than the touch's limit may overlap its rail, along its normal, before
// the wheel is taken to touch there after all [m]: at 0.5 mm of approach a Hertzian flank contact
// (relative radius 10-100 mm) carries 150-500 kN, beyond any curve's lateral force.
constexpr double kSteepOverlap = 0.5e-3;

// The lowest local minimum of the sampled gap whose contact angle is below `steepest`, unless the
// lowest sample overlaps it by more than kSteepOverlap; the lowest sample otherwise.
std::size_t lowest_touch(const WheelRailGap& geometry, const GapSamples& g, double steepest) {
  std::size_t k = 0;
  for (std::size_t j = 0; j < g.h.size(); ++j)
    if (g.h[j] < g.h[k]) k = j;
  if (std::isinf(steepest)) return k;
  const double angle = geometry.contact_angle(g.y[k]);
  if (angle < steepest) return k;
  const auto neighbour = [&g](std::size_t j, std::size_t i) {
    return i < g.h.size() && g.window[i] == g.window[j] ? g.h[i]
                                                        : std::numeric_limits<double>::infinity();
  };
  std::size_t best = g.h.size();
  for (std::size_t j = 0; j < g.h.size(); ++j) {
    if (best < g.h.size() && !(g.h[j] < g.h[best])) continue;
    const bool minimum = (j == 0 || neighbour(j, j - 1) > g.h[j]) && neighbour(j, j + 1) >= g.h[j];
    if (minimum && geometry.contact_angle(g.y[j]) < steepest) best = j;
  }
  if (best == g.h.size() || (g.h[best] - g.h[k]) * std::cos(angle) > kSteepOverlap) return k;
  return best;
}

}  // namespace

WheelRailTouch first_touch_at(const WheelRailPair& pair, const WheelsetPose& pose,
                              const WheelRailOptions& options, double gauge_y, double steepest) {
  WheelRailTouch touch;
  const WheelRailGap geometry(pair, pose, options, gauge_y);
  thread_local CoarseScan coarse;
  thread_local GapSamples g;
  geometry.scan(coarse);
  // The gap's minimum lies within one coarse spacing of a coarse local minimum; those within
  // the first margin of the coarse minimum (the dip argument of kFirstMargin) are refined.
  geometry.sample(coarse, std::min(options.scan_margin, kFirstMargin), g, true);
  if (g.h.empty()) return touch;
  const std::size_t k = lowest_touch(geometry, g, steepest);
  const GapMinimum m = refined_minimum(g, k, k);
  touch.found = true;
  touch.gap = m.h;
  // Without a wheelset (steepest = inf) there is no roll to share a load for.
  touch.resting_gap =
      std::isfinite(steepest)
          ? resting_gap(
                g, k, steepest, [&](std::size_t j) { return geometry.contact_angle(g.y[j]); },
                [&](std::size_t j) { return refined_minimum(g, j, j).h; })
          : m.h;
  touch.y_rail = -m.y;
  touch.contact_angle = geometry.contact_angle(m.y);
  const auto w = geometry.wheel_at(m.y);
  touch.y_wheel = w ? -w->y : -(m.y - geometry.shift());
  touch.rolling_radius = geometry.rolling_radius(w ? w->z : geometry.z_tape());
  return touch;
}

void validate_pose(const WheelsetPose& pose) {
  require_finite("dy", pose.dy);
  require_finite("roll", pose.roll);
  require_finite("yaw", pose.yaw);
  require(std::abs(pose.roll) < 0.1, "roll", pose.roll, "the roll angle must be small (< 0.1 rad)");
}

void validate_loaded_contact(const WheelRailPair& pair, const WheelsetPose& pose,
                             double vertical_force, const WheelRailOptions& options) {
  pair.validate();
  options.validate();
  validate_pose(pose);
  require_finite("load", vertical_force);
  require(vertical_force > 0.0, "load", vertical_force,
          "the vertical wheel load must be positive (newtons)");
}

}  // namespace detail

WheelRailContact solve_wheel_rail(const WheelRailPair& pair, const WheelsetPose& pose,
                                  double vertical_force, const WheelRailOptions& options) {
  detail::validate_loaded_contact(pair, pose, vertical_force, options);
  return detail::solve_wheel_rail_at(pair, pose, vertical_force, options,
                                     detail::rail_gauge_y(pair));
}

WheelRailTouch first_touch(const WheelRailPair& pair, const WheelsetPose& pose,
                           const WheelRailOptions& options) {
  pair.validate();
  options.validate();
  detail::validate_pose(pose);
  return detail::first_touch_at(pair, pose, options, detail::rail_gauge_y(pair));
}

bool carries_load(WheelRailStatus status) {
  return status == WheelRailStatus::ok || status == WheelRailStatus::load_jump ||
         status == WheelRailStatus::flange_climb || status == WheelRailStatus::past_flange;
}

}  // namespace wheelwear::contactgeom
