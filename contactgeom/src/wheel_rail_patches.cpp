#include "wheel_rail_patches.hpp"

#include <algorithm>
#include <cmath>

#include "wheelwear/contactgeom/sdec_regularisation.hpp"

namespace wheelwear::contactgeom::detail {

Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last) {
  const GapMinimum m = refined_minimum(g, first, last);
  return Run{first, last, m.y, m.h};
}

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

PatchForces strip_forces(const WheelRailGap& geometry, const GapSamples& g,
                         SampleDirections& directions, const GapStrips& strips, std::size_t last,
                         const KpPatch& patch) {
  PatchForces f;
  for (const KpStrip& strip : patch.strips) {
    const double load = strip.line_load() * patch.ds;
    const auto k = static_cast<std::size_t>(std::llround((strip.s - strips.s_first) / strips.ds));
    const ContactDirection n = directions.at(geometry, g, last - k);
    f.vertical += load * n.cos;
    f.lateral += load * n.sin;
  }
  return f;
}

WheelRailPatch describe_patch(const WheelRailGap& geometry, const KpPatch& patch, double y_O_run,
                              double angle, PatchForces forces, double E_star) {
  const double c = std::cos(angle);
  WheelRailPatch p;
  p.kp = patch;
  p.contact_angle = angle;
  p.normal_force = patch.normal_force;
  p.vertical_force = forces.vertical;
  p.lateral_force = forces.lateral;
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
  }
  return p;
}

// The gap along the contact normal is the vertical gap times cos(angle), to second order.
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

PatchSet patches_at(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    double approach, double E_star, const WheelRailOptions& options,
                    bool describe) {
  PatchSet out;
  thread_local std::vector<double> h, ax;
  thread_local KpResult kp;
  for (const Run& run : interpenetration_runs(g, approach, options.kp.epsilon)) {
    const double angle = geometry.contact_angle(run.y_O);
    const double c = std::cos(angle);
    const GapStrips strips = strips_of(geometry, g, run.first, run.last, run.y_O, c, h, ax);
    solve_kp_approach(strips, E_star, approach * c, options.kp, kp);
    if (kp.status != KpStatus::converged) continue;
    for (const KpPatch& patch : kp.patches) {
      const PatchForces f = strip_forces(geometry, g, directions, strips, run.last, patch);
      out.vertical += f.vertical;
      out.lateral += f.lateral;
      out.steepest = std::max(out.steepest, std::abs(angle));
      if (describe)
        out.patches.push_back(describe_patch(geometry, patch, run.y_O, angle, f, E_star));
    }
  }
  return out;
}

}  // namespace wheelwear::contactgeom::detail
