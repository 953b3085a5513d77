#include "wheelwear/contactgeom/wheel_rail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "wheelwear/contactgeom/sdec_regularisation.hpp"
#include "wheelwear/input_error.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::contactgeom {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The wheel profile rotated by `roll` about its point at y = 0 (small angles are the use).
profiles::Profile rolled(const profiles::Profile& wheel, double roll) {
  const auto pivot = wheel.surface_at(0.0);
  const double z0 = pivot ? pivot->z : 0.0;
  const double c = std::cos(roll), s = std::sin(roll);
  profiles::PointList points = wheel.resample(0.1e-3);
  for (auto& p : points) {
    const double y = p.x(), z = p.y() - z0;  // a Point holds (y, z)
    p = profiles::Point(c * y - s * z, s * y + c * z + z0);
  }
  // The points are already smooth: interpolate them, do not smooth a second time.
  profiles::CurveOptions curve = wheel.curve_options();
  curve.smoothing_length = 0.0;
  return profiles::Profile(points, wheel.info(), curve);
}

// The gap sampled on uniform lateral windows of the rail frame where contact is possible.
struct GapSamples {
  double dy = 0.0;
  std::vector<double> y;        // rail-frame lateral coordinate [m]
  std::vector<double> h;        // vertical gap z_rail - z_wheel [m]
  std::vector<double> z_wheel;  // wheel surface height (wheel frame) [m]
  std::vector<int> window;      // index of the window a sample belongs to
  double h_min = kInf;
  std::vector<std::size_t> end_samples;  // samples that lie at the end of a profile
};

class Geometry {
 public:
  Geometry(const WheelRailPair& pair, const WheelsetPose& pose, const WheelRailOptions& options)
      : pair_(pair), options_(options) {
    if (pose.roll != 0.0) rolled_wheel_.emplace(rolled(pair.wheel, pose.roll));
    const profiles::ProfilePoint gauge = profiles::gauge_point(pair.rail, pair.gauge_depth);
    // The flange back lies (gauge - back_to_back)/2 on the gauge side (-y) of the gauge point.
    shift_ =
        gauge.point.x() - 0.5 * (pair.gauge - pair.back_to_back) - pair.flange_back_y + pose.dy;
    const auto tape = pair.wheel.surface_at(0.0);
    z_tape_ = tape ? tape->z : 0.0;
  }

  const profiles::Profile& wheel() const { return rolled_wheel_ ? *rolled_wheel_ : pair_.wheel; }
  double shift() const { return shift_; }
  double z_tape() const { return z_tape_; }

  // Vertical gap at rail-frame y, and the wheel height there; nullopt outside either profile.
  std::optional<std::pair<double, double>> gap(double y) const {
    const auto r = pair_.rail.surface_at(y);
    const auto w = wheel().surface_at(y - shift_);
    if (!r || !w) return std::nullopt;
    return std::make_pair(r->z - w->z, w->z);
  }

  void sample(GapSamples& g) const {
    const double lo = std::max(pair_.rail.y_min(), wheel().y_min() + shift_);
    const double hi = std::min(pair_.rail.y_max(), wheel().y_max() + shift_);
    g = GapSamples{};
    g.dy = options_.strip_width;
    if (!(hi > lo)) return;
    // Coarse scan, then fine samples only where the gap is within the margin of its minimum.
    const int coarse = static_cast<int>(std::floor((hi - lo) / options_.scan_spacing)) + 1;
    std::vector<double> hc(static_cast<std::size_t>(coarse), kInf);
    double hc_min = kInf;
    for (int i = 0; i < coarse; ++i) {
      if (const auto v = gap(lo + i * options_.scan_spacing)) hc[i] = v->first;
      hc_min = std::min(hc_min, hc[i]);
    }
    if (!std::isfinite(hc_min)) return;
    int window = -1;
    for (int i = 0; i < coarse;) {
      if (!(hc[i] < hc_min + options_.scan_margin)) {
        ++i;
        continue;
      }
      int end = i;
      while (end + 1 < coarse && hc[end + 1] < hc_min + options_.scan_margin) ++end;
      const double from = std::max(lo, lo + (i - 1) * options_.scan_spacing);
      const double to = std::min(hi, lo + (end + 1) * options_.scan_spacing);
      const bool low_end = i == 0, high_end = end == coarse - 1;
      ++window;
      const std::size_t first = g.h.size();
      for (double y = from; y <= to; y += g.dy) {
        const auto v = gap(y);
        if (!v) continue;
        g.y.push_back(y);
        g.h.push_back(v->first);
        g.z_wheel.push_back(v->second);
        g.window.push_back(window);
        g.h_min = std::min(g.h_min, v->first);
      }
      // A contact that reaches these samples is cut off by the end of a profile.
      if (low_end && g.h.size() > first) g.end_samples.push_back(first);
      if (high_end && g.h.size() > first) g.end_samples.push_back(g.h.size() - 1);
      i = end + 1;
    }
  }

  // Contact angle at rail-frame y: the rail surface's slope, + where it falls towards -y
  // (the gauge side), as on the gauge corner and flange contact.
  double contact_angle(double y) const {
    const auto r = pair_.rail.surface_at(y);
    return r ? std::atan(-r->dz_dy) : 0.0;
  }

  const WheelRailPair& pair() const { return pair_; }

 private:
  const WheelRailPair& pair_;
  const WheelRailOptions& options_;
  std::optional<profiles::Profile> rolled_wheel_;
  double shift_ = 0.0;
  double z_tape_ = 0.0;
};

// One run of samples where the surfaces interpenetrate at the rigid approach.
struct Run {
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double y_O = 0.0, h_O = 0.0;      // gap minimum (parabola through the lowest sample)
};

// The gap minimum of samples [first, last], refined by a parabola through its neighbours.
Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last) {
  Run run{first, last};
  std::size_t k = first;
  for (std::size_t j = first; j <= last; ++j)
    if (g.h[j] < g.h[k]) k = j;
  run.y_O = g.y[k];
  run.h_O = g.h[k];
  if (k > 0 && k + 1 < g.h.size() && g.window[k - 1] == g.window[k] &&
      g.window[k + 1] == g.window[k]) {
    const double hm = g.h[k - 1], h0 = g.h[k], hp = g.h[k + 1];
    const double curvature = hm - 2.0 * h0 + hp;
    if (curvature > 0.0) {
      const double offset = 0.5 * (hm - hp) / curvature;  // in samples, |offset| <= 1/2
      run.y_O = g.y[k] + offset * g.dy;
      run.h_O = h0 - 0.25 * (hm - hp) * offset;
    }
  }
  return run;
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

Evaluation evaluate(const Geometry& geometry, const GapSamples& g, double approach, double E_star,
                    const WheelRailOptions& options, bool details) {
  Evaluation out;
  std::vector<double> h, ax;
  for (const Run& run : interpenetration_runs(g, approach, options.kp.epsilon)) {
    const double angle = geometry.contact_angle(run.y_O);
    const double c = std::cos(angle);
    // Strips in increasing s, i.e. towards the gauge side (-y in the profile frame); the gap
    // measured along the contact normal is the vertical gap times cos(angle), to second order.
    const std::size_t n = run.last - run.first + 1;
    h.resize(n);
    ax.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = run.last - k;
      h[k] = g.h[j] * c;
      const double radius = geometry.pair().wheel_radius + g.z_wheel[j] - geometry.z_tape();
      ax[k] = c / (2.0 * radius);
    }
    GapStrips strips;
    strips.ds = g.dy / c;
    strips.s_first = -(g.y[run.last] - run.y_O) / c;
    strips.h = h;
    strips.ax = ax;
    thread_local KpResult kp;
    solve_kp_approach(strips, E_star, approach * c, options.kp, kp);
    if (kp.status != KpStatus::converged) continue;
    for (const KpPatch& patch : kp.patches) {
      out.vertical += patch.normal_force * c;
      out.lateral += patch.normal_force * std::sin(angle);
      out.steepest = std::max(out.steepest, std::abs(angle));
      if (!details) continue;
      WheelRailPatch p;
      p.kp = patch;
      p.contact_angle = angle;
      p.normal_force = patch.normal_force;
      p.pmax = patch.pmax;
      // O of the KP patch lies at s_O from the run's minimum, along the contact plane.
      const double y_O = run.y_O - patch.s_O * c;
      p.y_rail = -y_O;
      p.y_wheel = -(y_O - geometry.shift());
      const auto w = geometry.wheel().surface_at(y_O - geometry.shift());
      const auto r = geometry.pair().rail.surface_at(y_O);
      p.s_wheel = w ? w->s : 0.0;
      p.rolling_radius = geometry.pair().wheel_radius + (w ? w->z : 0.0) - geometry.z_tape();
      p.measures = measure_patch(patch);
      p.sdec = regularise_sdec(p.measures);
      const double lateral_curvature = 0.5 * ((w ? geometry.wheel().curvature(w->s) : 0.0) +
                                              (r ? geometry.pair().rail.curvature(r->s) : 0.0));
      const double longitudinal = c / (2.0 * p.rolling_radius);
      if (lateral_curvature > 0.0) {
        p.hertz = hertz_from_load(longitudinal, lateral_curvature, E_star, patch.normal_force);
        p.hertz_valid = true;
      }
      out.patches.push_back(std::move(p));
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

WheelRailContact solve_wheel_rail(const WheelRailPair& pair, const WheelsetPose& pose,
                                  double vertical_force, const WheelRailOptions& options) {
  pair.validate();
  options.validate();
  require_finite("dy", pose.dy);
  require_finite("roll", pose.roll);
  require_finite("yaw", pose.yaw);
  require_finite("load", vertical_force);
  require(vertical_force > 0.0, "load", vertical_force,
          "the vertical wheel load must be positive (newtons)");
  require(std::abs(pose.roll) < 0.1, "roll", pose.roll, "the roll angle must be small (< 0.1 rad)");

  WheelRailContact result;
  const Geometry geometry(pair, pose, options);
  thread_local GapSamples g;
  geometry.sample(g);
  if (g.h.empty()) {
    result.message =
        "the wheel and rail profiles do not overlap laterally at dy = " + std::to_string(pose.dy) +
        " m";
    return result;
  }
  const double E_star = combined_modulus(pair.youngs_modulus, pair.poisson);

  // Fast path, the usual case: one contact region. The window around the gap's minimum goes
  // to the Kik-Piotrowski load solve at the normal load Fz/cos(angle); the answer stands if,
  // at its approach, the gap shows that one region only.
  double d = -1.0;
  bool at_jump = false;
  {
    std::size_t k = 0;
    for (std::size_t j = 0; j < g.h.size(); ++j)
      if (g.h[j] < g.h[k]) k = j;
    std::size_t first = k, last = k;
    while (first > 0 && g.window[first - 1] == g.window[k]) --first;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[k]) ++last;
    // The angle at the refined minimum, as evaluate() takes it for the region.
    const double angle = geometry.contact_angle(with_minimum(g, first, last).y_O);
    const double c = std::cos(angle);
    thread_local std::vector<double> h, ax;
    h.resize(last - first + 1);
    ax.resize(last - first + 1);
    for (std::size_t i = 0; i < h.size(); ++i) {
      const std::size_t j = last - i;
      h[i] = g.h[j] * c;
      ax[i] = c / (2.0 * (pair.wheel_radius + g.z_wheel[j] - geometry.z_tape()));
    }
    GapStrips strips;
    strips.ds = g.dy / c;
    strips.s_first = -(g.y[last] - g.y[k]) / c;
    strips.h = h;
    strips.ax = ax;
    const KpResult kp = solve_kp_load(strips, E_star, vertical_force / c, options.kp);
    if (kp.status == KpStatus::converged && kp.patches.size() == 1) {
      const double candidate = kp.approach / c - g.h_min;
      const auto runs = interpenetration_runs(g, g.h_min + candidate, options.kp.epsilon);
      if (runs.size() == 1 &&
          std::abs(geometry.contact_angle(runs[0].y_O) - angle) < 1e-3 * std::max(1.0, angle)) {
        d = candidate;
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

  Evaluation e = evaluate(geometry, g, g.h_min + d, E_star, options, true);
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

}  // namespace wheelwear::contactgeom
