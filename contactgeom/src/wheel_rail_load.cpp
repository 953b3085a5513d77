// The wheel/rail contact under a prescribed vertical force: the rigid approach that carries it,
// on a sampling of the gap that covers the loaded contact.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bracketed_root.hpp"
#include "load_residual.hpp"
#include "wheel_rail_gap.hpp"
#include "wheel_rail_patches.hpp"
#include "wheel_rail_solve.hpp"
#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom::detail {

namespace {

// The bracket of the approach narrower than this [m] is taken as a jump of the vertical force.
constexpr double kApproachResolution = 1e-13;
constexpr int kMaxLoadEvaluations = 100;

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
  const LoadTolerance load_met{options.load_tolerance};

  // Fast path, the usual case: one contact region. The window around the gap's minimum goes
  // to the Kik-Piotrowski load solve at the normal load Fz/cos(angle), to the same relative
  // tolerance as N cos(angle)/Fz = N/(Fz/cos(angle)); the answer stands if, at its approach,
  // the gap shows that one region only. Its patch is then the one patches_at() would find at
  // that approach (same strips, s from the same O), so it is described directly.
  double d = -1.0;
  bool at_jump = false;
  std::optional<PatchSet> fast;
  {
    std::size_t k = 0;
    for (std::size_t j = 0; j < g.h.size(); ++j)
      if (g.h[j] < g.h[k]) k = j;
    std::size_t first = k, last = k;
    while (first > 0 && g.window[first - 1] == g.window[k]) --first;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[k]) ++last;
    // The angle at the refined minimum, as patches_at() takes it for the region.
    const double y_O = with_minimum(g, first, last).y_O;
    const double angle = geometry.contact_angle(y_O);
    const double c = std::cos(angle);
    thread_local std::vector<double> h, ax;
    const GapStrips strips = strips_of(geometry, g, first, last, y_O, c, h, ax);
    KpOptions kp_options = options.kp;
    kp_options.load_tolerance = options.load_tolerance;
    thread_local KpResult kp;
    solve_kp_load(strips, E_star, vertical_force / c, kp_options, kp);
    if (kp.status == KpStatus::converged && kp.patches.size() == 1) {
      const double candidate = kp.approach / c - g.h_min;
      const auto runs = interpenetration_runs(g, g.h_min + candidate, options.kp.epsilon);
      if (runs.size() == 1 &&
          std::abs(geometry.contact_angle(runs[0].y_O) - angle) < 1e-3 * std::max(1.0, angle)) {
        d = candidate;
        PatchSet e;
        e.vertical = kp.patches[0].normal_force * c;
        e.lateral = kp.patches[0].normal_force * std::sin(angle);
        e.steepest = std::abs(angle);
        e.patches.push_back(describe_patch(geometry, kp.patches[0], y_O, angle, E_star));
        fast = std::move(e);
      }
    }
  }
  if (d < 0.0) {
    // Vertical force against approach beyond first touch: bracket, then the regula falsi of
    // bracketed_root.hpp on the load residual, nearly linear in the approach.
    auto residual = [&](double beyond_touch) {
      const PatchSet e = patches_at(geometry, g, g.h_min + beyond_touch, E_star, options, false);
      return load_residual(e.vertical, vertical_force);
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
    const RootResult root = find_root_bracketed_until(residual, lo, f_lo, hi, f_hi, load_met,
                                                      kApproachResolution, kMaxLoadEvaluations);
    d = root.x;
    // A bracket that collapsed without meeting the load: the force jumps across this approach,
    // where a further contact region joins the patch it neighbours (Kik-Piotrowski's load is
    // discontinuous where patches merge). root.x is then the side nearer the load.
    at_jump = !root.converged && std::abs(root.hi - root.lo) <= kApproachResolution;
  }

  PatchSet e =
      fast ? std::move(*fast) : patches_at(geometry, g, g.h_min + d, E_star, options, true);
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
  } else if (!load_met.met(e.vertical, vertical_force)) {
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

// The answer on the first sampling stands when its approach stays this far inside that
// sampling's margin [m].
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

}  // namespace wheelwear::contactgeom::detail
