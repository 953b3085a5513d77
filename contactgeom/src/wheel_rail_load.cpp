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
// Steps from a guess of the approach (a Hertz step, then secant steps) before the bracketed solve.
constexpr int kMaxGuessSteps = 6;
// The largest approach beyond first touch the load solve tries [m]: 20 um doubled 12 times.
constexpr double kLargestApproach = 20e-6 * 4096.0;

// Evaluations of the approach the fast path spends on correcting it to the strip-wise vertical
// force before it leaves the contact to the bracketed solve (which takes ten or more): two or
// three on the tread, up to five where the flank's angle spread makes N cos(angle) miss by 30 %.
constexpr int kMaxFastCorrections = 6;
// The fast path's first Kik-Piotrowski load solve stops at this relative tolerance on N (or the
// looser load_tolerance): its N cos(angle) misses the strip-wise vertical force by the spread of
// the angle over the patch anyway (3e-5 to 8e-4 on S1002's tread), which the corrections remove;
// solving N closer only adds evaluations (one or two per solve).
constexpr double kFirstGuessTolerance = 1e-4;

// The samples of `window` about its minimum where the gap lies below the approach `a`: the run
// patches_at() takes there (interpenetration_runs, where the window has no rise to cut), with
// the window's minimum.
Run below(const GapSamples& g, const Run& window, double a) {
  const auto k =
      static_cast<std::size_t>(std::clamp(std::llround((window.y_O - g.y[window.first]) / g.dy),
                                          0LL, static_cast<long long>(window.last - window.first)));
  Run run = window;
  run.first = window.first + k;
  run.last = run.first;
  while (run.first > window.first && g.h[run.first - 1] < a) --run.first;
  while (run.last < window.last && g.h[run.last + 1] < a) ++run.last;
  return run;
}

// The fast path's single patch of the gap's one region `window` under the vertical force Fz:
// its strips, approach (vertical, the datum of g.h), patch and forces into strips, approach, kp
// and forces; false unless the solve ends with one converged patch whose strip-wise vertical
// force meets options.load_tolerance. The first guess is the Kik-Piotrowski load solve at
// N = Fz/c on the strips in O's plane (no cut bounds the window: they do not depend on the
// approach), which misses Fz by the spread of the contact angle over the patch; the approach is
// then corrected on the load residual of load_residual.hpp, nearly linear in the approach: first
// a step that takes it as linear in the local approach (Hertz, Fz ~ delta^(3/2)), then secant
// steps. The effective cosine Fz/N hardly depends on the load, so two or three evaluations of
// the approach meet 1e-9. In CONTACT's weighted plane (`weighted`) every evaluation takes the
// strips at its own approach, the plane following the interpenetration.
bool fast_path_approach(const WheelRailGap& geometry, const GapSamples& g,
                        SampleDirections& directions, const Run& window, bool weighted,
                        double E_star, double Fz, const WheelRailOptions& options,
                        StripBuffers& buffers, RunStrips& strips, double& approach, KpResult& kp,
                        PatchForces& forces) {
  const LoadTolerance load_met{options.load_tolerance};
  KpOptions kp_options = options.kp;
  kp_options.load_tolerance = std::max(options.load_tolerance, kFirstGuessTolerance);
  strips = strips_of(geometry, g, directions, window, 0.0, false, buffers);
  const double c = strips.plane.cos;
  solve_kp_load(strips.strips, E_star, Fz / c, kp_options, kp);
  const auto single = [&] { return kp.status == KpStatus::converged && kp.patches.size() == 1; };
  if (!single()) return false;
  const auto evaluate = [&](double a) {
    // The window's samples below the approach (the strips of a longer run are the same where
    // they overlap: both start from O, strips_of).
    if (weighted)
      strips = strips_of(geometry, g, directions, below(g, window, a), a, true, buffers);
    solve_kp_approach(strips.strips, E_star, a * strips.plane.cos, options.kp, kp);
    return single();
  };
  approach = kp.approach / c;
  if (weighted && !evaluate(approach)) return false;
  forces = strip_forces(geometry, g, directions, strips, kp.patches[0]);
  double f = load_residual(forces.vertical, Fz);
  if (load_met(f)) return true;
  double next = window.h_O + (approach - window.h_O) / (1.0 + f);
  for (int i = 0; i < kMaxFastCorrections; ++i) {
    const double previous = approach, f_previous = f;
    approach = next;
    if (!evaluate(approach)) return false;
    forces = strip_forces(geometry, g, directions, strips, kp.patches[0]);
    f = load_residual(forces.vertical, Fz);
    if (load_met(f)) return true;
    if (f == f_previous) return false;
    next = approach - f * (approach - previous) / (f - f_previous);
  }
  return false;
}

// The approach beyond first touch that carries the load, from the load residual's root.
struct LoadRoot {
  double beyond_touch = 0.0;  // [m]
  bool carried = false;       // a bracket was found (the load is carried within 80 mm)
  bool at_jump = false;       // the bracket collapsed without meeting the load: a jump
};

// The root of `residual` (of the approach beyond first touch, -1 at 0): from `guess` [m] a Hertz
// step (the approach beyond first touch as Fz^(2/3), so the step to the root is x / (1 + f)),
// then secant steps while they stay inside what is bracketed; else, or without a guess (0), the
// regula falsi of bracketed_root.hpp on the bracket found, or on one from 20 um up, doubling.
template <class Residual>
LoadRoot carry_load(Residual&& residual, double guess, const LoadTolerance& load_met) {
  LoadRoot out;
  double lo = 0.0, f_lo = -1.0;
  double hi = -1.0, f_hi = 0.0;
  if (guess > 0.0) {
    double x = guess, x_previous = 0.0, f_previous = 0.0;
    for (int i = 0; i < kMaxGuessSteps; ++i) {
      const double f = residual(x);
      if (load_met(f)) {
        out.carried = true;
        out.beyond_touch = x;
        return out;
      }
      if (f < 0.0 && x > lo) {
        lo = x;
        f_lo = f;
      }
      if (f > 0.0 && (hi < 0.0 || x < hi)) {
        hi = x;
        f_hi = f;
      }
      double next = f > -0.5 ? x / (1.0 + f) : 2.0 * x;  // far below the load: no Hertz step
      if (i > 0 && f != f_previous) next = x - f * (x - x_previous) / (f - f_previous);
      // Unbracketed above, a step at most doubles the approach (a nearly flat secant).
      if (hi < 0.0 && !(next <= 2.0 * x)) next = 2.0 * x;
      // Steps that leave the bracket found so far go to the regula falsi instead.
      if ((hi > 0.0 && next >= hi) || next <= lo) break;
      x_previous = x;
      f_previous = f;
      x = next;
    }
  }
  if (hi < 0.0) {
    // Every approach tried carries too little: doubling from the largest, up to the last.
    for (double x = lo > 0.0 ? std::min(2.0 * lo, kLargestApproach) : 20e-6; lo < kLargestApproach;
         x = std::min(2.0 * x, kLargestApproach)) {
      const double f = residual(x);
      if (f >= 0.0) {
        hi = x;
        f_hi = f;
        break;
      }
      lo = x;
      f_lo = f;
    }
    if (hi < 0.0) return out;
  }
  const RootResult root = find_root_bracketed_until(residual, lo, f_lo, hi, f_hi, load_met,
                                                    kApproachResolution, kMaxLoadEvaluations);
  out.carried = true;
  out.beyond_touch = root.x;
  // A bracket that collapsed without meeting the load: the force jumps across this approach.
  // Regions that join keep their loads and cuts move continuously (interpenetration_runs), so
  // this is a jump no description removes; root.x is then the side nearer the load.
  out.at_jump = !root.converged && std::abs(root.hi - root.lo) <= kApproachResolution;
  return out;
}

// The load solve of a contact whose gap has rises to cut, and where the fast path's merged
// answer is not the whole story.
struct BlendRoot {
  LoadRoot root;
  double reference = kEveryRise;  // of the blend's shares (interpenetration_runs)
  bool merged = false;            // the merged answer (at `merged_approach`) is the blend's
};

// First every rise of the gap cut (two contacts wherever there are two basins), then, where a
// rise is a partial cut at that approach, the blend with its shares taken there: each solve's
// load rises with the approach (interpenetration_runs), and the shares follow the all-cut
// approach, continuous in the profiles' positions. `residual(beyond_touch, reference)` is the
// load residual of the description with shares at `reference`; `merged_approach` the approach
// beyond first touch of the fast path's merged answer, < 0 where there is none.
template <class Residual>
BlendRoot solve_blend(Residual&& residual, const GapSamples& g, double merged_approach,
                      const LoadTolerance& load_met) {
  BlendRoot out;
  const auto all_cut = [&](double beyond_touch) { return residual(beyond_touch, kEveryRise); };
  if (merged_approach > 0.0) {
    // The merged answer is the blend's when the all-cut approach lies between where every rise
    // is merged and the merged answer's own approach: the all-cut load rises with the
    // approach, so two evaluations decide it (usually a ripple in one tread patch).
    const double threshold = merged_from(g, g.h_min + merged_approach) - g.h_min;
    if (threshold <= merged_approach && all_cut(merged_approach) >= 0.0 &&
        (threshold <= 0.0 || all_cut(threshold) <= 0.0)) {
      out.root = LoadRoot{merged_approach, true, false};
      out.merged = true;
      return out;
    }
  }
  out.root = carry_load(all_cut, std::max(merged_approach, 0.0), load_met);
  if (!out.root.carried || splits_at_every_rise(g, g.h_min + out.root.beyond_touch)) return out;
  out.reference = g.h_min + out.root.beyond_touch;
  // Where the shares leave the one region merged, its load rises with the approach, so the
  // merged answer is the root.
  if (merged_approach > 0.0) {
    const std::vector<Run> runs =
        interpenetration_runs(g, g.h_min + merged_approach, out.reference);
    if (runs.size() == 1 && runs[0].share == 1.0) {
      out.root = LoadRoot{merged_approach, true, false};
      out.merged = true;
      return out;
    }
  }
  out.root = carry_load([&](double beyond_touch) { return residual(beyond_touch, out.reference); },
                        out.root.beyond_touch, load_met);
  return out;
}

// Why the contact has passed the flange (WheelRailStatus::past_flange), or "" when no loaded
// patch has its O beyond the flank's steepest point towards the tip.
std::string past_flange_reason(const WheelRailGap& geometry,
                               const std::vector<WheelRailPatch>& patches) {
  // O on the tread side of the taping line has not reached the flange: no datum needed.
  const bool on_flange_side =
      std::any_of(patches.begin(), patches.end(), [&](const WheelRailPatch& p) {
        return p.normal_force > 0.0 && p.s_wheel < geometry.s_tape();
      });
  if (!on_flange_side) return "";
  const FlangeDatum flange = flange_datum(geometry.pair().wheel);
  if (!flange.found) return "";
  for (const WheelRailPatch& p : patches) {
    if (!(p.normal_force > 0.0 && p.s_wheel < flange.s_limit)) continue;
    const double y_steepest = geometry.pair().wheel.position(flange.s_steepest)[0];
    return "O lies on the flange " + std::to_string((flange.s_limit - p.s_wheel) * 1e3) +
           " mm (along the profile) towards its tip from the end of its steepest stretch (slope " +
           std::to_string(flange.steepest_angle) +
           " rad at y = " + std::to_string(y_steepest * 1e3) + " mm of the wheel profile, less " +
           std::to_string(kFlangeSlopeTolerance) + " rad), at a contact angle of " +
           std::to_string(p.contact_angle) + " rad carrying " + std::to_string(p.normal_force) +
           " N: the flange climbs its rail or has passed it";
  }
  return "";
}

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
  thread_local SampleDirections directions;
  directions.reset(g.h.size());

  // Fast path, the usual case: one contact region. The window around the gap's minimum goes
  // to the Kik-Piotrowski load solve at the normal load Fz/cos(angle); the strip-wise vertical
  // force of that patch differs from Fz by the spread of the angle over the patch, so the
  // approach is then corrected (fast_path_approach). The answer is the merged description's
  // (one patch over the whole region) if, at its approach, the gap shows one region only. Its
  // patch is then the one patches_at() would find at that approach (same strips, s from the
  // same O), so it is described directly. It stands where the region has no rise to cut, or
  // where the blend's shares, taken at the all-cut approach, leave it merged.
  double d = -1.0;
  bool at_jump = false;
  std::optional<PatchSet> fast;
  double fast_approach = -1.0;  // beyond touch, where the merged answer exists
  {
    std::size_t k = 0;
    for (std::size_t j = 0; j < g.h.size(); ++j)
      if (g.h[j] < g.h[k]) k = j;
    std::size_t first = k, last = k;
    while (first > 0 && g.window[first - 1] == g.window[k]) --first;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[k]) ++last;
    // The angle at the refined minimum, as patches_at() takes it for the region.
    const Run window = with_minimum(g, first, last);
    const double angle = geometry.contact_angle(window.y_O);
    const bool weighted = options.contact_plane == ContactPlane::weighted;
    thread_local StripBuffers buffers;
    thread_local KpResult kp;
    RunStrips strips;
    PatchForces forces;
    double approach = 0.0;
    if (fast_path_approach(geometry, g, directions, window, weighted, E_star, vertical_force,
                           options, buffers, strips, approach, kp, forces)) {
      const double candidate = approach - g.h_min;
      const std::vector<Run> regions = interpenetration_regions(g, g.h_min + candidate);
      if (regions.size() == 1 &&
          std::abs(geometry.contact_angle(regions[0].y_O) - angle) < 1e-3 * std::max(1.0, angle)) {
        fast_approach = candidate;
        // O's plane and its strips do not depend on the approach (no cut bounds the window),
        // but the angle CONTACT reports does.
        if (!weighted)
          strips.plane.weighted_angle =
              weighted_plane_angle(geometry, g, directions, window, approach, strips.plane.angle);
        PatchSet e;
        e.vertical = forces.vertical;
        e.lateral = forces.lateral;
        e.steepest = std::abs(patch_contact_angle(geometry, g, strips, kp.patches[0]));
        e.patches.push_back(
            describe_patch(geometry, g, kp.patches[0], strips, approach, forces, E_star));
        fast = std::move(e);
        if (interpenetration_runs(g, g.h_min + candidate, kEveryRise).size() == 1) d = candidate;
      }
    }
  }
  double reference = kEveryRise;
  if (d < 0.0) {
    const BlendRoot blend = solve_blend(
        [&](double beyond_touch, double reference_approach) {
          return load_residual(patches_at(geometry, g, directions, g.h_min + beyond_touch,
                                          reference_approach, E_star, options, false)
                                   .vertical,
                               vertical_force);
        },
        g, fast ? fast_approach : -1.0, load_met);
    if (!blend.root.carried) {
      result.status = WheelRailStatus::not_converged;
      result.message = "the load is not carried within an approach of 80 mm";
      return result;
    }
    d = blend.root.beyond_touch;
    at_jump = blend.root.at_jump;
    reference = blend.reference;
    if (!blend.merged) fast.reset();
  }

  PatchSet e =
      fast ? std::move(*fast)
           : patches_at(geometry, g, directions, g.h_min + d, reference, E_star, options, true);
  std::sort(e.patches.begin(), e.patches.end(),
            [](const WheelRailPatch& a, const WheelRailPatch& b) { return a.y_rail < b.y_rail; });
  result.patches = std::move(e.patches);
  result.vertical_force = e.vertical;
  result.lateral_force = e.lateral;
  result.approach = d;
  result.status = WheelRailStatus::ok;
  bool at_profile_end = false;
  // The regions in contact at the approach (a blend's runs may reach beyond them).
  for (const Run& run : interpenetration_regions(g, g.h_min + d))
    for (std::size_t k : g.end_samples) at_profile_end |= (k == run.first || k == run.last);
  const std::string past = past_flange_reason(geometry, result.patches);
  if (at_jump) {
    // The jump is reported first, with the flange's state when that is past.
    result.status = WheelRailStatus::load_jump;
    result.message = "the vertical force jumps at this approach (contact regions merge); it is " +
                     std::to_string(e.vertical) + " N";
    if (!past.empty()) result.message += "; " + past;
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
  } else if (!past.empty()) {
    result.status = WheelRailStatus::past_flange;
    result.message = past;
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
                       result.status == WheelRailStatus::past_flange ||
                       result.status == WheelRailStatus::profile_end;
  if (first_margin < options.scan_margin &&
      (!settled || result.approach + kMarginReserve > first_margin)) {
    geometry.sample(coarse, options.scan_margin, g);
    result = solve_on_samples(geometry, g, pose, vertical_force, options);
  }
  return result;
}

}  // namespace wheelwear::contactgeom::detail
