#include "wheelwear/contactgeom/wheel_rail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "wheel_rail_gap.hpp"
#include "wheel_rail_solve.hpp"
#include "wheelwear/contactgeom/sdec_regularisation.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

namespace {

using detail::CoarseScan;
using detail::GapSamples;
using detail::WheelRailGap;

// One run of samples where the surfaces interpenetrate at the rigid approach.
struct Run {
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double y_O = 0.0, h_O = 0.0;      // gap minimum (parabola through the lowest sample)
};

Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last) {
  const detail::GapMinimum m = detail::refined_minimum(g, first, last);
  return Run{first, last, m.y, m.h};
}

// Runs of samples where the surfaces interpenetrate at the rigid approach. A run whose virtual
// interpenetration (Kik-Piotrowski: the gap below h_O + eps (approach - h_O)) falls apart into
// separate pieces is cut at the highest gap between them: each piece is a contact of its own,
// with its own initial contact point and contact angle (two-point contact of tread and flange).
std::vector<Run> interpenetration_runs(const GapSamples& g, double approach, double epsilon) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < g.h.size();) {
    if (!(g.h[i] < approach)) {
      ++i;
      continue;
    }
    std::size_t last = i;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[i] && g.h[last + 1] < approach)
      ++last;
    const Run whole = with_minimum(g, i, last);
    const double virtual_level = whole.h_O + epsilon * (approach - whole.h_O);
    std::size_t start = i;
    bool in_piece = false, seen_piece = false;
    std::size_t peak = i;  // highest sample since the last piece ended
    for (std::size_t j = i; j <= last; ++j) {
      const bool inside = g.h[j] < virtual_level;
      if (inside && !in_piece && seen_piece) {
        runs.push_back(with_minimum(g, start, peak));
        start = peak + 1;
      }
      if (!inside && (in_piece || g.h[j] > g.h[peak])) peak = j;
      if (inside) seen_piece = true;
      in_piece = inside;
    }
    runs.push_back(with_minimum(g, start, last));
    i = last + 1;
  }
  return runs;
}

// Patches and their total vertical force at one rigid approach.
struct Evaluation {
  std::vector<WheelRailPatch> patches;
  double vertical = 0.0;
  double lateral = 0.0;
  double steepest = 0.0;
};

// The details of one Kik-Piotrowski patch of the region whose gap minimum lies at rail-frame
// y_O, with contact angle `angle`; its strips' s is measured from y_O along the contact plane.
WheelRailPatch describe_patch(const WheelRailGap& geometry, const KpPatch& patch, double y_O_run,
                              double angle, double E_star) {
  const double c = std::cos(angle);
  WheelRailPatch p;
  p.kp = patch;
  p.contact_angle = angle;
  p.normal_force = patch.normal_force;
  p.pmax = patch.pmax;
  // O of the KP patch lies at s_O from the run's minimum, along the contact plane.
  const double y_O = y_O_run - patch.s_O * c;
  p.y_rail = -y_O;
  const auto w = geometry.wheel_at(y_O);
  const auto r = geometry.pair().rail.surface_at(y_O);
  // The wheel's material point at O (the unrolled profile's, which a roll does not move).
  p.y_wheel = w ? -w->y : -(y_O - geometry.shift());
  p.s_wheel = w ? w->s : 0.0;
  p.rolling_radius = geometry.rolling_radius(w ? w->z : geometry.z_tape());
  p.measures = measure_patch(patch);
  p.sdec = regularise_sdec(p.measures);
  const double lateral_curvature = 0.5 * ((w ? geometry.pair().wheel.curvature(w->s) : 0.0) +
                                          (r ? geometry.pair().rail.curvature(r->s) : 0.0));
  const double longitudinal = c / (2.0 * p.rolling_radius);
  if (lateral_curvature > 0.0) {
    p.hertz = hertz_from_load(longitudinal, lateral_curvature, E_star, patch.normal_force);
    p.hertz_valid = true;
  }
  return p;
}

// The strips of samples [first, last] for the Kik-Piotrowski solver, in increasing s (towards
// the gauge side, -y in the profile frame), s measured from y_O along the contact plane. The gap
// along the contact normal is the vertical gap times cos(angle), to second order.
GapStrips strips_of(const WheelRailGap& geometry, const GapSamples& g, std::size_t first,
                    std::size_t last, double y_O, double c, std::vector<double>& h,
                    std::vector<double>& ax) {
  const std::size_t n = last - first + 1;
  h.resize(n);
  ax.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = last - k;
    h[k] = g.h[j] * c;
    ax[k] = c / (2.0 * geometry.rolling_radius(g.z_wheel[j]));
  }
  GapStrips strips;
  strips.ds = g.dy / c;
  strips.s_first = -(g.y[last] - y_O) / c;
  strips.h = h;
  strips.ax = ax;
  return strips;
}

Evaluation evaluate(const WheelRailGap& geometry, const GapSamples& g, double approach,
                    double E_star, const WheelRailOptions& options, bool details) {
  Evaluation out;
  thread_local std::vector<double> h, ax;
  thread_local KpResult kp;
  for (const Run& run : interpenetration_runs(g, approach, options.kp.epsilon)) {
    const double angle = geometry.contact_angle(run.y_O);
    const double c = std::cos(angle);
    const GapStrips strips = strips_of(geometry, g, run.first, run.last, run.y_O, c, h, ax);
    solve_kp_approach(strips, E_star, approach * c, options.kp, kp);
    if (kp.status != KpStatus::converged) continue;
    for (const KpPatch& patch : kp.patches) {
      out.vertical += patch.normal_force * c;
      out.lateral += patch.normal_force * std::sin(angle);
      out.steepest = std::max(out.steepest, std::abs(angle));
      if (details) out.patches.push_back(describe_patch(geometry, patch, run.y_O, angle, E_star));
    }
  }
  return out;
}

}  // namespace

WheelRailPair::WheelRailPair(profiles::Profile wheel_profile, profiles::Profile rail_profile)
    : wheel(std::move(wheel_profile)), rail(std::move(rail_profile)) {
  flange_back_y = wheel.y_min();
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
  require(lateral_tolerance > 0.0 && lateral_tolerance < 0.1, "lateral_tolerance",
          lateral_tolerance, "must lie in (0, 0.1)");
  require(flange_angle > 0.0 && flange_angle < max_contact_angle, "flange_angle", flange_angle,
          "must lie between 0 and max_contact_angle (rad)");
  kp.validate();
}

const char* status_name(WheelRailStatus status) {
  switch (status) {
    case WheelRailStatus::ok:
      return "ok";
    case WheelRailStatus::no_contact:
      return "no contact";
    case WheelRailStatus::flange_climb:
      return "flange climb";
    case WheelRailStatus::not_converged:
      return "not converged";
    case WheelRailStatus::load_jump:
      return "load jump";
    case WheelRailStatus::profile_end:
      return "profile end";
  }
  return "unknown";
}

namespace detail {

namespace {

// The contact solved on one sampling of the gap.
WheelRailContact solve_on_samples(const WheelRailGap& geometry, const GapSamples& g,
                                  const WheelsetPose& pose, double vertical_force,
                                  const WheelRailOptions& options) {
  const WheelRailPair& pair = geometry.pair();
  WheelRailContact result;
  if (g.h.empty()) {
    result.message =
        "the wheel and rail profiles do not overlap laterally at dy = " + std::to_string(pose.dy) +
        " m";
    return result;
  }
  const double E_star = combined_modulus(pair.youngs_modulus, pair.poisson);

  // Fast path, the usual case: one contact region. The window around the gap's minimum goes
  // to the Kik-Piotrowski load solve at the normal load Fz/cos(angle); the answer stands if,
  // at its approach, the gap shows that one region only. Its patch is then the one evaluate()
  // would find at that approach (same strips, s from the same O), so it is described directly.
  double d = -1.0;
  bool at_jump = false;
  std::optional<Evaluation> fast;
  {
    std::size_t k = 0;
    for (std::size_t j = 0; j < g.h.size(); ++j)
      if (g.h[j] < g.h[k]) k = j;
    std::size_t first = k, last = k;
    while (first > 0 && g.window[first - 1] == g.window[k]) --first;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[k]) ++last;
    // The angle at the refined minimum, as evaluate() takes it for the region.
    const double y_O = with_minimum(g, first, last).y_O;
    const double angle = geometry.contact_angle(y_O);
    const double c = std::cos(angle);
    thread_local std::vector<double> h, ax;
    const GapStrips strips = strips_of(geometry, g, first, last, y_O, c, h, ax);
    thread_local KpResult kp;
    solve_kp_load(strips, E_star, vertical_force / c, options.kp, kp);
    if (kp.status == KpStatus::converged && kp.patches.size() == 1) {
      const double candidate = kp.approach / c - g.h_min;
      const auto runs = interpenetration_runs(g, g.h_min + candidate, options.kp.epsilon);
      if (runs.size() == 1 &&
          std::abs(geometry.contact_angle(runs[0].y_O) - angle) < 1e-3 * std::max(1.0, angle)) {
        d = candidate;
        Evaluation e;
        e.vertical = kp.patches[0].normal_force * c;
        e.lateral = kp.patches[0].normal_force * std::sin(angle);
        e.steepest = std::abs(angle);
        e.patches.push_back(describe_patch(geometry, kp.patches[0], y_O, angle, E_star));
        fast = std::move(e);
      }
    }
  }
  if (d < 0.0) {
    // Vertical force against approach beyond first touch: bracket, then Anderson-Bjorck
    // regula falsi on (F/Fz)^(2/3) - 1, nearly linear in the approach (Hertz: F ~ d^(3/2)).
    auto residual = [&](double beyond_touch) {
      const Evaluation e = evaluate(geometry, g, g.h_min + beyond_touch, E_star, options, false);
      return std::cbrt(std::pow(e.vertical / vertical_force, 2.0)) - 1.0;
    };
    double lo = 0.0, f_lo = -1.0;
    double hi = 20e-6, f_hi = residual(hi);
    for (int i = 0; f_hi < 0.0 && i < 12; ++i) {
      lo = hi;
      f_lo = f_hi;
      hi *= 2.0;
      f_hi = residual(hi);
    }
    if (f_hi < 0.0) {
      result.status = WheelRailStatus::not_converged;
      result.message = "the load is not carried within an approach of 80 mm";
      return result;
    }
    d = hi;
    for (int i = 0; i < 100; ++i) {
      d = lo - f_lo * (hi - lo) / (f_hi - f_lo);
      const double f = residual(d);
      if (std::abs(f) < options.load_tolerance) break;
      if (hi - lo < 1e-13) {
        // The force jumps across this approach: a further contact region joins the patch it
        // neighbours (Kik-Piotrowski's load is discontinuous where patches merge). Take the
        // side nearest the load.
        at_jump = true;
        d = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
        break;
      }
      if ((f < 0.0) == (f_lo < 0.0)) {
        lo = d;
        f_lo = f;
        f_hi *= 0.5;  // Illinois-style damping keeps the stale end moving
      } else {
        hi = d;
        f_hi = f;
        f_lo *= 0.5;
      }
    }
  }

  Evaluation e =
      fast ? std::move(*fast) : evaluate(geometry, g, g.h_min + d, E_star, options, true);
  std::sort(e.patches.begin(), e.patches.end(),
            [](const WheelRailPatch& a, const WheelRailPatch& b) { return a.y_rail < b.y_rail; });
  result.patches = std::move(e.patches);
  result.vertical_force = e.vertical;
  result.lateral_force = e.lateral;
  result.approach = d;
  result.status = WheelRailStatus::ok;
  bool at_profile_end = false;
  for (const Run& run : interpenetration_runs(g, g.h_min + d, options.kp.epsilon))
    for (std::size_t k : g.end_samples) at_profile_end |= (k == run.first || k == run.last);
  if (at_jump) {
    result.status = WheelRailStatus::load_jump;
    result.message = "the vertical force jumps at this approach (contact regions merge); it is " +
                     std::to_string(e.vertical) + " N";
  } else if (std::abs(e.vertical / vertical_force - 1.0) > 1e-6) {
    result.status = WheelRailStatus::not_converged;
    result.message = "the vertical force iteration stopped at " + std::to_string(e.vertical) + " N";
  } else if (at_profile_end) {
    result.status = WheelRailStatus::profile_end;
    result.message = "the contact reaches the end of a profile at dy = " + std::to_string(pose.dy) +
                     " m: the profiles do not cover this position";
  } else if (e.steepest > options.max_contact_angle) {
    result.status = WheelRailStatus::flange_climb;
    result.message = "contact angle " + std::to_string(e.steepest) +
                     " rad: the flange climbs the rail, no stable contact";
  }
  return result;
}

// The first sampling keeps only the windows where the gap lies within this of its minimum [m]:
// 0.3 mm, three times the approach of a 55 kN wheel on its flange root. The coarse scan misses
// nothing that deep: a dip of 0.1 mm between two coarse points 1 mm apart needs a gap curvature
// of 800 1/m (a 1.2 mm radius), far sharper than any wheel or rail. The answer stands when its
// approach stays 0.1 mm inside the margin; otherwise the gap is sampled to options.scan_margin.
constexpr double kFirstMargin = 0.3e-3;
constexpr double kMarginReserve = 0.1e-3;

}  // namespace

WheelRailContact solve_wheel_rail_at(const WheelRailPair& pair, const WheelsetPose& pose,
                                     double vertical_force, const WheelRailOptions& options,
                                     double gauge_y) {
  const WheelRailGap geometry(pair, pose, options, gauge_y);
  thread_local CoarseScan coarse;
  thread_local GapSamples g;
  geometry.scan(coarse);
  const double first_margin = std::min(options.scan_margin, kFirstMargin);
  geometry.sample(coarse, first_margin, g);
  WheelRailContact result = solve_on_samples(geometry, g, pose, vertical_force, options);
  const bool settled = result.status == WheelRailStatus::ok ||
                       result.status == WheelRailStatus::load_jump ||
                       result.status == WheelRailStatus::flange_climb ||
                       result.status == WheelRailStatus::profile_end;
  if (first_margin < options.scan_margin &&
      (!settled || result.approach + kMarginReserve > first_margin)) {
    geometry.sample(coarse, options.scan_margin, g);
    result = solve_on_samples(geometry, g, pose, vertical_force, options);
  }
  return result;
}

WheelRailTouch first_touch_at(const WheelRailPair& pair, const WheelsetPose& pose,
                              const WheelRailOptions& options, double gauge_y) {
  WheelRailTouch touch;
  const WheelRailGap geometry(pair, pose, options, gauge_y);
  thread_local CoarseScan coarse;
  thread_local GapSamples g;
  geometry.scan(coarse);
  // The gap's minimum lies within one coarse spacing of a coarse local minimum; those within
  // the first margin of the coarse minimum (the dip argument of kFirstMargin) are refined.
  geometry.sample(coarse, std::min(options.scan_margin, kFirstMargin), g, true);
  if (g.h.empty()) return touch;
  std::size_t k = 0;
  for (std::size_t j = 0; j < g.h.size(); ++j)
    if (g.h[j] < g.h[k]) k = j;
  const Run run = with_minimum(g, k, k);
  touch.found = true;
  touch.gap = run.h_O;
  touch.y_rail = -run.y_O;
  touch.contact_angle = geometry.contact_angle(run.y_O);
  const auto w = geometry.wheel_at(run.y_O);
  touch.y_wheel = w ? -w->y : -(run.y_O - geometry.shift());
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

}  // namespace wheelwear::contactgeom
