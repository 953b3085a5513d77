#pragma once
// The depth at which a wheel of a wheelset rests on its rail where its gap has several minima of
// nearly the same depth (internal to contactgeom).
//
// The rigid wheelset's roll puts each wheel at its gap's lowest eligible minimum. Where a second
// minimum overtakes the first (a flank taking over from the tread), the roll then changes its
// law at once: on a flank as steep as the wheelset's lever allows (r tan(angle) near the
// distance D between the wheels' taping points) the height of the new minimum hardly changes
// with the roll, and the roll ran away by 2.3e-5 rad within 5 nm of shift (a measured wheel on a
// measured rail, Car7216 on avg_HR), taking the flank's load with it: no balance lay on either
// side. An elastic wheel shares its load between the regions within its approach. So the wheel
// rests at the height H where the minima, taken as equal Hertzian springs, carry what one alone
// carries at `approach`: sum w_j (H - h_j)^(3/2) over the minima below H = approach^(3/2), the
// lowest minimum with weight 1. The others' weights are the product of smooth steps:
// - by the roll's lever (lever_share): only where a minimum lies on such a flank does the rigid
//   roll need the sharing; on the tread and the flange root it passes from one minimum to the
//   next with a kink only, and sharing there cost more Newton iterations on worn profiles than
//   it saved (measured over the built-in route on 16 worn wheels). A minimum's lever is the
//   lesser of its own and the one that pairs all minima within reach: the least of theirs, each
//   raised by its depth above the lowest and by what it lacks in standing (below), so that a
//   minimum entering reach, born or leaving as too steep changes it continuously;
// - by its own standing: its rise to the ridge towards a deeper minimum (one behind a ridge
//   lower than the approach lies in the same region once loaded, a ripple of a worn tread; none
//   behind no ridge, where a minimum is born), and its distance from the steepest contact.
// The resting gap H - approach is the touch's gap while no other minimum has weight (the
// single-basin result is unchanged, bit for bit), and is continuous as a flank's minimum comes
// within reach and overtakes the tread's: the weights depend on the minima's depths, angles and
// ridges, not on which one is the touch, and the two swap their weights as their depths cross.
// Two small steps remain: where two minima that are both above the lowest cross (their rises
// swap, a step where their own levers or tapers differ: three minima within 50 um, one of them
// on such a flank), and where sharing starts while the touch, chosen by its sample, is not the
// lowest refined minimum (their difference, below 0.03 um on the measured pairs swept).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "wheel_rail_gap.hpp"

namespace wheelwear::contactgeom::detail {

// The shared approach [m]: a tread contact's approach under a wheel load (S1002 on 60E1: 79 um
// at 55 kN, about 50 um at 27 kN), so minima 50 um apart share the load.
constexpr double kSharedApproach = 50e-6;

// 0 at t <= 0, 1 at t >= 1, smooth (C1) between.
inline double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The roll's lever at a contact angle: 1 - tan(angle) / tan(steepest) with steepest = atan(D/r),
// the share of the roll's lift of the wheel that a contact there does not give back by moving
// the wheel into its rail (1 on the tread, 0 at steepest).
inline double roll_lever(double angle, double steepest) {
  return 1.0 - std::tan(angle) / std::tan(steepest);
}

// The share a minimum takes by the roll's lever (its own or the one that pairs it, below): none
// from 0.6 up (tread and flange root, up to 0.92 rad for a 0.46 m wheel on standard gauge), all
// below 0.3 (from 1.16 rad).
inline double lever_share(double lever) {
  return smoothstep((0.6 - lever) / 0.3);
}

// A minimum's own fade as its lever nears 0, over the last 0.05 (from 1.26 rad here): a minimum
// steeper than atan(D/r) is not eligible as the touch (rigid contact there has no roll), and
// leaves the sharing with no weight.
inline double steep_taper(double lever) {
  return smoothstep(lever / 0.05);
}

struct RestingMinimum {
  double h = 0.0;      // gap [m]
  double rise = 0.0;   // from it to the lowest ridge towards a deeper minimum [m] (inf: none)
  double share = 0.0;  // by the roll's levers: lever_share of its lever times its steep_taper
};

// A minimum's weight in the resting gap (the lowest's is 1 whatever this says).
inline double resting_weight(const RestingMinimum& m, double approach = kSharedApproach) {
  return m.share * smoothstep(m.rise / approach);
}

// The resting gap [m] of minima `minima` (not empty), at `approach` [m] > 0: the lowest with
// weight 1, the others with resting_weight.
inline double resting_gap(const std::vector<RestingMinimum>& minima,
                          double approach = kSharedApproach) {
  std::size_t low = 0;
  for (std::size_t j = 1; j < minima.size(); ++j)
    if (minima[j].h < minima[low].h) low = j;
  const double lowest = minima[low].h;
  const auto weight = [&](std::size_t j) { return j == low ? 1.0 : resting_weight(minima[j]); };
  const double target = approach * std::sqrt(approach);
  const auto carried = [&](double H) {
    double sum = 0.0;
    for (std::size_t j = 0; j < minima.size(); ++j)
      if (H > minima[j].h) sum += weight(j) * (H - minima[j].h) * std::sqrt(H - minima[j].h);
    return sum;
  };
  // The lowest alone carries the target at lowest + approach, so H lies between it and that.
  // The sum rises monotonically with H: bisection until the bracket stops shrinking.
  double lo = lowest, hi = lowest + approach;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (carried(mid) > target ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi) - approach;
}

// The resting gap [m] of the sampled gap `g` whose touch is sample `k`, on a wheelset whose
// steepest touching contact is `steepest` (atan(D/r)) [rad]. `angle(j)` gives the contact angle
// at sample j, `refined(j)` the gap of the local minimum at sample j refined by its neighbours
// (the touch's gap is refined(k)). The candidates are the local minima (the touch and those less
// steep than `steepest` whose refined gap lies within reach of the touch's); a ridge is the
// highest sample between two minima, across windows that touch (a gap in the samples is a
// ridge of +inf).
template <class Angle, class Refined>
double resting_gap(const GapSamples& g, std::size_t k, double steepest, const Angle& angle,
                   const Refined& refined, double approach = kSharedApproach) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double touch_gap = refined(k);
  const std::size_t n = g.h.size();
  // Whether samples i - 1 and i are neighbours: the same window, or windows that touch.
  const auto joined = [&](std::size_t i) {
    return g.window[i] == g.window[i - 1] || g.y[i] - g.y[i - 1] <= 1.5 * g.dy;
  };
  struct Candidate {
    std::size_t sample;
    double lever;
    RestingMinimum m;
  };
  thread_local std::vector<Candidate> candidates;
  candidates.clear();
  for (std::size_t j = 0; j < n; ++j) {
    const double left = j > 0 && joined(j) ? g.h[j - 1] : inf;
    const double right = j + 1 < n && joined(j + 1) ? g.h[j + 1] : inf;
    const bool minimum = j == k || (left > g.h[j] && right >= g.h[j]);
    if (!minimum) continue;
    const double h = j == k ? touch_gap : refined(j);
    if (j != k && !(h < touch_gap + approach)) continue;
    const double a = angle(j);
    if (j != k && !(a < steepest)) continue;
    candidates.push_back({j, roll_lever(a, steepest), {h, inf, 0.0}});
  }
  // Tread and flange root alone: no lever pairs them (the common case, at once).
  if (std::all_of(candidates.begin(), candidates.end(),
                  [](const Candidate& c) { return lever_share(c.lever) == 0.0; }))
    return touch_gap;
  // Each candidate's rise to the lowest ridge towards a deeper one (ties: the earlier sample is
  // the deeper), on either side.
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    Candidate& c = candidates[i];
    const auto deeper = [&](std::size_t m) {
      return candidates[m].m.h < c.m.h || (candidates[m].m.h == c.m.h && m < i);
    };
    const auto rise_towards = [&](std::ptrdiff_t step) {
      double ridge = -inf;
      std::size_t s = c.sample;
      for (std::ptrdiff_t m = static_cast<std::ptrdiff_t>(i) + step;
           m >= 0 && m < static_cast<std::ptrdiff_t>(candidates.size()); m += step) {
        const std::size_t other = candidates[static_cast<std::size_t>(m)].sample;
        while (s != other) {
          const std::size_t next = step > 0 ? s + 1 : s - 1;
          if (!joined(std::max(s, next))) return inf;
          s = next;
          ridge = std::max(ridge, g.h[s]);
        }
        if (deeper(static_cast<std::size_t>(m))) return ridge - c.m.h;
      }
      return inf;
    };
    c.m.rise = std::min(rise_towards(-1), rise_towards(+1));
  }
  double lowest = inf;
  for (const Candidate& c : candidates) lowest = std::min(lowest, c.m.h);
  // A candidate's own standing: its rise and its distance from the steepest contact.
  const auto own = [&](const Candidate& c) {
    return steep_taper(c.lever) * smoothstep(c.m.rise / approach);
  };
  // The lever that pairs share: the least over the candidates, each raised by its depth above
  // the lowest in approaches and by what it lacks in standing, so that it changes continuously
  // as minima come within reach, are born or cross, whichever one is the touch.
  double paired = inf;
  for (const Candidate& c : candidates)
    paired = std::min(paired, c.lever + (c.m.h - lowest) / approach + 0.6 * (1.0 - own(c)));
  for (Candidate& c : candidates)
    c.m.share = lever_share(std::min(c.lever, paired)) * steep_taper(c.lever);
  // Bit for bit the touch's gap where no other minimum shares (the tread's).
  if (std::none_of(candidates.begin(), candidates.end(), [&](const Candidate& c) {
        return c.sample != k && resting_weight(c.m, approach) > 0.0;
      }))
    return touch_gap;
  thread_local std::vector<RestingMinimum> minima;
  minima.clear();
  for (const Candidate& c : candidates) minima.push_back(c.m);
  return resting_gap(minima, approach);
}

}  // namespace wheelwear::contactgeom::detail
