#include "wheel_rail_patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "blended_minimum.hpp"
#include "parabola_vertex.hpp"
#include "wheelwear/contactgeom/sdec_regularisation.hpp"

namespace wheelwear::contactgeom::detail {

Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last) {
  // Neighbours only from the same window: windows are sampled apart.
  const auto gap = [&g, window = g.window[first]](std::ptrdiff_t j) {
    const auto k = static_cast<std::size_t>(j);
    return j < 0 || k >= g.h.size() || g.window[k] != window
               ? std::numeric_limits<double>::infinity()
               : g.h[k];
  };
  const BlendedMinimum m =
      blended_minimum(gap, static_cast<std::ptrdiff_t>(first), static_cast<std::ptrdiff_t>(last));
  return Run{first, last, g.y[first] + (m.index - static_cast<double>(first)) * g.dy, m.h};
}

namespace {

// A rise of the gap between two basins of one interpenetration run.
struct Cut {
  std::size_t at;     // the highest sample between the basins
  double separation;  // 0: the basins are one contact ... 1: two contacts
  double position;    // Run::cut_before / cut_after of the pieces it bounds, within at +- 1/2
};

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The rises of the gap in samples [first, last] by kBasinRipple or more between two minima:
// a minimum is confirmed once the gap has risen that much after it, the rise once the gap has
// fallen that much after it.
std::vector<std::size_t> rises(const GapSamples& g, std::size_t first, std::size_t last) {
  std::vector<std::size_t> at;
  std::size_t lowest = first, highest = first;
  bool rising = false;
  for (std::size_t j = first + 1; j <= last; ++j) {
    if (!rising) {
      if (g.h[j] < g.h[lowest]) lowest = j;
      if (g.h[j] > g.h[lowest] + kBasinRipple) {
        rising = true;
        highest = j;
      }
    } else {
      if (g.h[j] > g.h[highest]) highest = j;
      if (g.h[j] < g.h[highest] - kBasinRipple) {
        at.push_back(highest);
        lowest = j;
        rising = false;
      }
    }
  }
  return at;
}

double lowest_gap(const GapSamples& g, std::size_t first, std::size_t last) {
  return *std::min_element(g.h.begin() + static_cast<std::ptrdiff_t>(first),
                           g.h.begin() + static_cast<std::ptrdiff_t>(last) + 1);
}

// The shallower of the two minima beside rise k of `at` (the rises of run [first, last]) [m].
double shallower_minimum(const GapSamples& g, std::size_t first, std::size_t last,
                         const std::vector<std::size_t>& at, std::size_t k) {
  const std::size_t left_first = k == 0 ? first : at[k - 1] + 1;
  const std::size_t right_last = k + 1 == at.size() ? last : at[k + 1];
  return std::max(lowest_gap(g, left_first, at[k]), lowest_gap(g, at[k] + 1, right_last));
}

// The separation of a rise: 0 where its basins are one contact ... 1 where they are two.
// `prominence`: the rise above the shallower basin's minimum `shallower`, both [m].
double separation(double prominence, double shallower, double reference) {
  // A rise is found once it reaches kBasinRipple, where a shallow basin's r may already lie
  // above kMergedBelow: the cut fades in over the next ripple of rise, so that the contact does
  // not jump as the rise is found (it did, by 15 % of a wheel's Fx, on a banded worn tread).
  const double found = smoothstep(prominence / kBasinRipple - 1.0);
  const double depth = reference - shallower;  // the shallower basin's local approach
  if (!(depth > 0.0)) return found;            // not reached at the reference: its own contact
  const double r = prominence / depth;
  return found * smoothstep((r - kMergedBelow) / (kSeparateAbove - kMergedBelow));
}

// Where the rise whose highest sample is `at` lies between samples: the vertex of the parabola
// through it and its neighbours, which moves continuously as the highest sample passes to a
// neighbour (at two equal highest samples it lies half-way between them, seen from either);
// a top that moves to a hump further away, past a dip shallower than kBasinRipple, still jumps.
double cut_position(const GapSamples& g, std::size_t at) {
  double offset = 0.0;
  if (const auto vertex = parabola_vertex(-g.h[at - 1], -g.h[at], -g.h[at + 1]))
    offset = std::clamp(vertex->offset, -0.5, 0.5);
  return static_cast<double>(at) + offset;
}

// The cuts of run [first, last] with their separations at `reference`.
std::vector<Cut> cuts_of(const GapSamples& g, std::size_t first, std::size_t last,
                         double reference) {
  const std::vector<std::size_t> at = rises(g, first, last);
  std::vector<Cut> cuts;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const double shallower = shallower_minimum(g, first, last, at, k);
    cuts.push_back(
        {at[k], separation(g.h[at[k]] - shallower, shallower, reference), cut_position(g, at[k])});
  }
  return cuts;
}

// The piece of run [first, last] between the cuts `before` and `after` (nullptr: the run's own
// end), with its share of a blend: the samples less than half a sample beyond each cut.
Run piece_of(const GapSamples& g, std::size_t first, std::size_t last, const Cut* before,
             const Cut* after, double share) {
  std::size_t from = first, to = last;
  if (before) from = std::max(first, static_cast<std::size_t>(std::floor(before->position + 0.5)));
  if (after) to = std::min(last, static_cast<std::size_t>(std::ceil(after->position - 0.5)));
  Run run = with_minimum(g, from, to);
  if (before) run.cut_before = before->position;
  if (after) run.cut_after = after->position;
  run.share = share;
  return run;
}

// The runs of samples below `level`, each as [first, last].
template <class Visit>
void for_each_run_below(const GapSamples& g, double level, Visit&& visit) {
  for (std::size_t i = 0; i < g.h.size();) {
    if (!(g.h[i] < level)) {
      ++i;
      continue;
    }
    std::size_t last = i;
    while (last + 1 < g.h.size() && g.window[last + 1] == g.window[i] && g.h[last + 1] < level)
      ++last;
    visit(i, last);
    i = last + 1;
  }
}

}  // namespace

std::vector<Run> interpenetration_runs(const GapSamples& g, double approach, double reference) {
  std::vector<Run> runs;
  for_each_run_below(g, std::max(approach, reference), [&](std::size_t i, std::size_t last) {
    // Firm cuts separate contacts; between two firm cuts, the piece is blended from itself cut at
    // its partial cuts (share: their least separation) and itself uncut (the rest).
    const std::vector<Cut> cuts = cuts_of(g, i, last, reference);
    const Cut* firm_before = nullptr;
    std::size_t k = 0;
    while (true) {
      std::vector<const Cut*> partial;
      double split_share = 1.0;
      const Cut* firm_after = nullptr;
      for (; k < cuts.size(); ++k) {
        if (cuts[k].separation >= 1.0) {
          firm_after = &cuts[k++];
          break;
        }
        if (cuts[k].separation > 0.0) {
          partial.push_back(&cuts[k]);
          split_share = std::min(split_share, cuts[k].separation);
        }
      }
      if (partial.empty()) {
        runs.push_back(piece_of(g, i, last, firm_before, firm_after, 1.0));
      } else {
        const Cut* from = firm_before;
        for (const Cut* cut : partial) {
          runs.push_back(piece_of(g, i, last, from, cut, split_share));
          from = cut;
        }
        runs.push_back(piece_of(g, i, last, from, firm_after, split_share));
        runs.push_back(piece_of(g, i, last, firm_before, firm_after, 1.0 - split_share));
      }
      if (!firm_after) break;
      firm_before = firm_after;
    }
  });
  return runs;
}

std::vector<Run> interpenetration_regions(const GapSamples& g, double approach) {
  std::vector<Run> regions;
  for_each_run_below(g, approach, [&](std::size_t first, std::size_t last) {
    regions.push_back(with_minimum(g, first, last));
  });
  return regions;
}

double merged_from(const GapSamples& g, double approach) {
  double least = -std::numeric_limits<double>::infinity();
  for_each_run_below(g, approach, [&](std::size_t first, std::size_t last) {
    const std::vector<std::size_t> at = rises(g, first, last);
    for (std::size_t k = 0; k < at.size(); ++k) {
      const double shallower = shallower_minimum(g, first, last, at, k);
      least = std::max(least, shallower + (g.h[at[k]] - shallower) / kMergedBelow);
    }
  });
  return least;
}

bool splits_at_every_rise(const GapSamples& g, double approach) {
  bool same = true;
  for_each_run_below(g, approach, [&](std::size_t first, std::size_t last) {
    const std::vector<Cut> at = cuts_of(g, first, last, approach);
    const std::vector<Cut> every = cuts_of(g, first, last, kEveryRise);
    for (std::size_t k = 0; k < at.size(); ++k) same &= at[k].separation == every[k].separation;
  });
  return same;
}

void scale_loads(KpPatch& patch, double share) {
  for (KpStrip& strip : patch.strips) strip.p_peak *= share;
  patch.normal_force *= share;
  patch.p_O *= share;
  patch.pmax *= share;
}

PatchForces strip_forces(const WheelRailGap& geometry, const GapSamples& g,
                         SampleDirections& directions, const RunStrips& strips,
                         const KpPatch& patch) {
  PatchForces f;
  const std::size_t last = strips.plane.sample.size() - 1;
  for (const KpStrip& strip : patch.strips) {
    const double load = strip.line_load() * patch.ds;
    const auto k = static_cast<std::size_t>(
        std::clamp<long long>(std::llround((strip.s - strips.strips.s_first) / strips.strips.ds), 0,
                              static_cast<long long>(last)));
    // Between the samples about the strip's centre: the strips move with the plane as the
    // approach changes, and the nearest sample's direction would make the load jump.
    const double at = strips.plane.sample[k];
    const auto j = static_cast<std::size_t>(at);
    const double u = at - static_cast<double>(j);
    const ContactDirection n0 = directions.at(geometry, g, j);
    const ContactDirection n1 = u > 0.0 ? directions.at(geometry, g, j + 1) : n0;
    f.vertical += load * (n0.cos + u * (n1.cos - n0.cos));
    f.lateral += load * (n0.sin + u * (n1.sin - n0.sin));
  }
  return f;
}

double patch_contact_angle(const WheelRailGap& geometry, const GapSamples& g,
                           const RunStrips& strips, const KpPatch& patch) {
  // Kik & Piotrowski's reduction keeps the run's angle (O lies within a strip of its minimum).
  return strips.plane.weighted ? geometry.contact_angle(strips.plane.y_at(g, patch.s_O))
                               : strips.plane.angle;
}

WheelRailPatch describe_patch(const WheelRailGap& geometry, const GapSamples& g,
                              const KpPatch& patch, const RunStrips& strips, double approach,
                              PatchForces forces, double E_star, double share) {
  const double angle = patch_contact_angle(geometry, g, strips, patch);
  const double c = std::cos(angle);
  WheelRailPatch p;
  p.kp = patch;
  p.share = share;
  p.contact_angle = angle;
  p.plane_angle = strips.plane.angle;
  p.contact_angle_centre = strips.plane.weighted_angle;
  p.normal_force = patch.normal_force;
  p.vertical_force = forces.vertical;
  p.lateral_force = forces.lateral;
  p.pmax = patch.pmax;
  const double y_O = strips.plane.y_at(g, patch.s_O);
  p.y_rail = -y_O;
  {
    // The vertical gap at O, between the samples about it.
    const double j = strips.plane.sample_at(patch.s_O);
    const auto i = static_cast<std::size_t>(j);
    const std::size_t i1 = std::min(i + 1, g.y.size() - 1);
    p.rigid_penetration = approach - (g.h[i] + (j - static_cast<double>(i)) * (g.h[i1] - g.h[i]));
  }
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
    // The description's ellipse, at its whole load; its pressure scaled by the share as the
    // patch's are.
    p.hertz = hertz_from_load(longitudinal, lateral_curvature, E_star, patch.normal_force / share);
    p.hertz->p0 *= share;
    p.hertz->normal_force *= share;
  }
  return p;
}

PatchSet patches_at(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    double approach, double reference, double E_star,
                    const WheelRailOptions& options, bool describe) {
  PatchSet out;
  thread_local StripBuffers buffers;
  thread_local KpResult kp;
  const bool weighted = options.contact_plane == ContactPlane::weighted;
  for (const Run& run : interpenetration_runs(g, approach, reference)) {
    const RunStrips strips = strips_of(geometry, g, directions, run, approach, weighted, buffers);
    solve_kp_approach(strips.strips, E_star, approach * strips.plane.cos, options.kp, kp);
    if (kp.status != KpStatus::converged) continue;
    for (KpPatch& patch : kp.patches) {
      if (run.share < 1.0) scale_loads(patch, run.share);
      const PatchForces f = strip_forces(geometry, g, directions, strips, patch);
      out.vertical += f.vertical;
      out.lateral += f.lateral;
      out.steepest =
          std::max(out.steepest, std::abs(patch_contact_angle(geometry, g, strips, patch)));
      if (describe)
        out.patches.push_back(
            describe_patch(geometry, g, patch, strips, approach, f, E_star, run.share));
    }
  }
  return out;
}

}  // namespace wheelwear::contactgeom::detail
