#pragma once
// The depth at which a wheel rests on its rail where its gap has several minima of nearly the
// same depth (internal to contactgeom).
//
// The rigid wheelset's roll puts each wheel at its gap's lowest eligible minimum. Where a second
// minimum overtakes the first (a flank taking over from the tread), the roll then changes its
// law at once: on a flank as steep as the wheelset's lever allows (r tan(angle) near the
// distance between the wheels' taping points) the height of the new minimum hardly changes with
// the roll, and the roll ran away by 2e-5 rad within 20 nm of shift (a measured wheel on a
// measured rail, Car7216 on avg_HR), taking the flank's load with it: no balance lay on either
// side. An elastic wheel shares its load between the regions within its approach. So the wheel
// rests at the height H where the minima, taken as equal Hertzian springs, carry what one alone
// carries at `approach`: sum w_j (H - h_j)^(3/2) over the minima below H = approach^(3/2). A
// minimum's weight w is the product of two smooth steps:
// - by the roll's lever (lever_share): only where a minimum lies on such a flank does the rigid
//   roll need the elastic sharing; on the tread and the flange root it passes from one minimum
//   to the next with a kink only, and sharing there cost more Newton iterations on worn
//   profiles than it saved (measured over the built-in route on 16 worn wheels);
// - by its ridge: a minimum separated from a deeper one by a ridge lower than the approach lies
//   in the same region once loaded (a ripple of a worn tread): 0 behind no ridge (as where it
//   is born), 1 behind a ridge of `approach` or more.
// The wheel's touch has weight 1. The resting gap H - approach is the touch's gap while no other
// minimum with weight is within reach (the single-basin result is unchanged), and moves smoothly
// as another comes within reach and overtakes it (their weights swap as their depths cross, the
// sum unchanged).

#include <algorithm>
#include <cmath>
#include <vector>

namespace wheelwear::contactgeom::detail {

// The shared approach [m]: a tread contact's approach under a wheel load, 50 um at 30-40 kN
// (S1002 on 60E1: 79 um at 55 kN), so minima 50 um apart share the load.
constexpr double kSharedApproach = 50e-6;

// 0 at t <= 0, 1 at t >= 1, smooth (C1) between.
inline double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The share a minimum takes by the roll's lever at it and at the touch, the lesser of the two:
// lever = 1 - tan(angle) / tan(atan(D / r)), the share of the roll's lift of the wheel that a
// contact at that angle does not give back by moving the wheel into its rail. On the tread and
// flange root (lever 0.6 to 1) the rigid roll passes from one minimum to another with a kink
// only, and a minimum takes no share (the result is the rigid wheelset's); on a flank with a
// lever below 0.3 (1.16 rad for a 0.46 m wheel on standard gauge) a full one.
inline double lever_share(double lever) {
  return smoothstep((0.6 - lever) / 0.3);
}

struct RestingMinimum {
  double h = 0.0;      // gap [m]
  double ridge = 0.0;  // rise to the lowest ridge towards a deeper minimum [m] (inf: none)
  double share = 1.0;  // lever_share of it and the touch
};

// The weight of a minimum whose ridge towards a deeper one rises `ridge` [m].
inline double resting_weight(double ridge, double approach = kSharedApproach) {
  return smoothstep(ridge / approach);
}

// Its weight in the resting gap.
inline double resting_weight(const RestingMinimum& m, double approach = kSharedApproach) {
  return m.share * resting_weight(m.ridge, approach);
}

// The resting gap [m] of the touch `touch` [m] and the other minima `others`, at `approach`
// [m] > 0.
inline double resting_gap(double touch, const std::vector<RestingMinimum>& others,
                          double approach = kSharedApproach) {
  const auto reach = [&](const RestingMinimum& m) {
    return m.h < touch + approach && resting_weight(m, approach) > 0.0;
  };
  if (std::none_of(others.begin(), others.end(), reach)) return touch;
  const double target = approach * std::sqrt(approach);
  const auto carried = [&](double H) {
    double sum = H > touch ? (H - touch) * std::sqrt(H - touch) : 0.0;
    for (const RestingMinimum& m : others)
      if (H > m.h) sum += resting_weight(m, approach) * (H - m.h) * std::sqrt(H - m.h);
    return sum;
  };
  // The touch alone carries the target at touch + approach, so H lies below that; and above
  // the lowest minimum with weight (the sum vanishes below it). The sum rises monotonically
  // with H: bisection to 1e-12 of the approach.
  double lo = touch;
  for (const RestingMinimum& m : others)
    if (resting_weight(m, approach) > 0.0) lo = std::min(lo, m.h);
  double hi = touch + approach;
  while (hi - lo > 1e-12 * approach) {
    const double mid = 0.5 * (lo + hi);
    (carried(mid) > target ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi) - approach;
}

}  // namespace wheelwear::contactgeom::detail
