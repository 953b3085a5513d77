// Where a wheel of a wheelset rests when its gap has several minima (resting_gap.hpp): against
// the closed forms of equal Hertzian springs; a minimum on the tread, behind no ridge or steeper
// than the wheelset allows sharing nothing; and continuous as one minimum overtakes another, on
// sampled gaps as the roll's solve meets them.
#include "resting_gap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace wheelwear::contactgeom::detail {
namespace {

constexpr double a = kSharedApproach;
constexpr double none = std::numeric_limits<double>::infinity();  // no deeper minimum
// atan(D / r) of a 0.46 m wheel on standard gauge (D = 1.5 m between the taping points).
const double steepest = std::atan(1.5 / 0.46);

TEST(RestingGap, EqualMinimaShareTheLoadAsEqualSprings) {
  // n minima at the same depth: n (H - h)^(3/2) = a^(3/2), H - h = a n^(-2/3).
  int compared = 0;
  for (int n = 1; n <= 4; ++n) {
    const std::vector<RestingMinimum> minima(static_cast<std::size_t>(n), {-1e-4, none, 1.0});
    EXPECT_NEAR(resting_gap(minima), -1e-4 + a * (std::pow(n, -2.0 / 3.0) - 1.0), 1e-12) << n;
    ++compared;
  }
  // A second minimum d above the first with half a share: (H - h)^(3/2) + (H - h - d)^(3/2) / 2
  // = a^(3/2) at the answer.
  const double d = 0.3 * a;
  const double H = resting_gap({{0.0, none, 1.0}, {d, none, 0.5}}) + a;
  EXPECT_NEAR(std::pow(H, 1.5) + 0.5 * std::pow(H - d, 1.5), std::pow(a, 1.5),
              1e-10 * std::pow(a, 1.5));
  ++compared;
  // The lowest carries weight 1 whatever its own share and rise say.
  EXPECT_NEAR(resting_gap({{0.0, 0.0, 0.0}}), 0.0, 1e-12);
  ++compared;
  // Gaps far from the datum: the bisection ends (its bracket stops shrinking at rounding).
  EXPECT_NEAR(resting_gap({{0.3, none, 1.0}, {0.3 + 1e-6, none, 1.0}}), 0.3, a);
  ++compared;
  EXPECT_EQ(compared, 7);
}

TEST(RestingGap, TheRollsLeverAndTheRidgeSetAMinimumsShare) {
  // lever = 1 - tan(angle) / tan(steepest): no share from 0.6 (0.92 rad here), all below 0.3
  // (1.16 rad); a minimum's own taper over the last 0.05 before the steepest contact.
  EXPECT_NEAR(roll_lever(0.0, steepest), 1.0, 1e-15);
  EXPECT_NEAR(roll_lever(steepest, steepest), 0.0, 1e-12);
  EXPECT_EQ(lever_share(1.0), 0.0);
  EXPECT_EQ(lever_share(0.6), 0.0);
  EXPECT_NEAR(lever_share(0.45), 0.5, 1e-15);
  EXPECT_EQ(lever_share(0.3), 1.0);
  EXPECT_EQ(steep_taper(0.05), 1.0);
  EXPECT_NEAR(steep_taper(0.025), 0.5, 1e-15);
  EXPECT_EQ(steep_taper(0.0), 0.0);
  // By the ridge: none behind no ridge, all behind one of the approach, the smoothstep between.
  EXPECT_EQ(resting_weight({0.0, 0.0, 1.0}), 0.0);
  EXPECT_EQ(resting_weight({0.0, 0.5 * a, 1.0}), 0.5);
  EXPECT_EQ(resting_weight({0.0, a, 1.0}), 1.0);
  EXPECT_EQ(resting_weight({0.0, a, 0.5}), 0.5);
}

// How a sampled gap's samples fall into windows.
enum class Windows { one, touching, apart };

// A sampled gap every 0.1 mm over 4 mm: a tread's basin (curvature 100 1/m, floor 0 at 1.03 mm)
// and a flank's (curvature `curvature`, floor `flank` at `centre`), the floors between samples
// (refined by the parabola through three, as the roll's solve does); one window, two that touch
// at 2 mm (the boundary sample in both, as the first touch samples them) or two apart (three
// samples missing there). Optionally a ripple at 0.2 mm, 20 um above the tread's floor behind a
// ridge of 4.5 um towards it.
struct SampledGap {
  GapSamples g;
  std::vector<double> angle;  // contact angle at each sample [rad]
  SampledGap(double flank, double flank_angle, Windows windows, bool ripple = false,
             double centre = 3.07e-3, double curvature = 300.0) {
    g.dy = 0.1e-3;
    const auto sample = [&](double y, int window) {
      const double tread = 50.0 * (y - 1.03e-3) * (y - 1.03e-3);
      const double flank_basin = 0.5 * curvature * (y - centre) * (y - centre) + flank;
      const double ripple_basin = ripple ? 20e-6 + 2000.0 * (y - 0.2e-3) * (y - 0.2e-3) : none;
      g.y.push_back(y);
      g.h.push_back(std::min({tread, flank_basin, ripple_basin}));
      g.window.push_back(window);
      angle.push_back(y > 2e-3 ? flank_angle : 0.05);
    };
    for (int i = 0; i <= 40; ++i) {
      const double y = i * 1e-4;
      if (windows == Windows::apart && i >= 19 && i <= 21) continue;
      sample(y, windows != Windows::one && i > 20 ? 1 : 0);
      if (windows == Windows::touching && i == 20) sample(y, 1);  // the boundary sample again
    }
  }
  // The touch as the roll's solve finds it: the lowest sample, refined.
  std::size_t touch() const {
    return static_cast<std::size_t>(std::min_element(g.h.begin(), g.h.end()) - g.h.begin());
  }
  double touch_gap() const { return refined_minimum(g, touch(), touch()).h; }
  double resting() const {
    return resting_gap(
        g, touch(), steepest, [&](std::size_t j) { return angle[j]; },
        [&](std::size_t j) { return refined_minimum(g, j, j).h; });
  }
};

TEST(RestingGap, OnTheTreadOrTooSteepTheTouchRestsAlone) {
  // Alone, bit for bit: a second basin 10 um up at the flange root (0.5 rad, lever 0.83), in
  // one window or two; steeper than the wheelset allows (1.3 rad > atan(D/r) = 1.273); out of
  // reach (60 um up); a ripple 20 um up on the tread (lever 0.98).
  for (const SampledGap& alone :
       {SampledGap(10e-6, 0.5, Windows::one), SampledGap(10e-6, 0.5, Windows::touching),
        SampledGap(10e-6, 1.3, Windows::one), SampledGap(60e-6, 1.2, Windows::one),
        SampledGap(60e-6, 1.2, Windows::one, true)})
    EXPECT_EQ(alone.resting(), alone.touch_gap());
}

TEST(RestingGap, AFlankBehindAHighRidgeSharesAsAnEqualSpring) {
  // On a flank of 1.2 rad (lever 0.21: a full share), its floor d = 10 um above the tread's
  // behind a ridge 74 um above it (standing 1): H^(3/2) + (H - d)^(3/2) = a^(3/2) above the
  // tread's floor (both floors are parabolas, which the refinement finds exactly), the wheel
  // sinking less than into one. The same whether the samples fall into one window, two that
  // touch or two apart (the ridge is higher than the approach either way).
  const double d = 10e-6;
  EXPECT_EQ(lever_share(roll_lever(1.2, steepest)), 1.0);
  for (const Windows windows : {Windows::one, Windows::touching, Windows::apart}) {
    const SampledGap shared(d, 1.2, windows);
    EXPECT_NEAR(shared.touch_gap(), 0.0, 1e-15);
    const double H = shared.resting() + a;
    EXPECT_NEAR(std::pow(H, 1.5) + std::pow(H - d, 1.5), std::pow(a, 1.5), 1e-9 * std::pow(a, 1.5))
        << static_cast<int>(windows);
  }
}

TEST(RestingGap, ALowRidgeSharesInPartAcrossTouchingWindowsOnly) {
  // The flank's basin nearer the tread (centre 2.35 mm, curvature 1000 1/m): the ridge between
  // them rises less than the approach above the flank's floor, which then shares in part, alike
  // in one window and across two that touch; across samples missing between two windows the
  // ridge is unknown, taken as high, and the flank shares whole: the wheel sinks less.
  const auto resting = [](Windows w) {
    return SampledGap(10e-6, 1.2, w, false, 2.35e-3, 1000.0).resting();
  };
  const double one = resting(Windows::one);
  EXPECT_EQ(resting(Windows::touching), one);
  EXPECT_LT(resting(Windows::apart), one - 0.01 * a);
  EXPECT_LT(one, SampledGap(10e-6, 1.2, Windows::one, false, 2.35e-3, 1000.0).touch_gap());
}

TEST(RestingGap, MovesContinuouslyAsTheFlankOvertakesTheTread) {
  // The flank's floor descends from 60 um above the tread's to 60 um below it, in steps of
  // 0.05 um, on a flank of 1.2 rad; in one window, two that touch and two apart, and with a
  // ripple on the tread's side (a third minimum, whose share follows the pair's lever whichever
  // of the two is the touch). The resting gap never rises and ends at the flank's floor (the
  // tread then 60 um up, out of reach). With the pair's weights fixed it moves at most as fast as
  // the floor (a slope in [0, 1]), and smoothly: its slope changes by at most 0.02 per step
  // (bound 0.05), where a jump of a tenth of the step would change it by 0.1 twice.
  int compared = 0;
  for (const Windows windows : {Windows::one, Windows::touching, Windows::apart})
    for (const bool ripple : {false, true}) {
      double previous = 0.0, previous_slope = 0.0, steepest_slope = 0.0, kink = 0.0;
      double last_touch = 0.0;
      const double step = 0.05e-6;
      for (int k = 0; k <= 2400; ++k) {
        const SampledGap gap(60e-6 - k * step, 1.2, windows, ripple);
        const double rest = gap.resting();
        last_touch = gap.touch_gap();
        if (k == 0) EXPECT_EQ(rest, last_touch);  // the tread's floor, alone
        if (k > 0) {
          EXPECT_LE(rest, previous + 1e-15) << k;
          const double slope = (previous - rest) / step;
          steepest_slope = std::max(steepest_slope, slope);
          if (k > 1) kink = std::max(kink, std::abs(slope - previous_slope));
          previous_slope = slope;
        }
        previous = rest;
      }
      RecordProperty("slope_" + std::to_string(static_cast<int>(windows)) + std::to_string(ripple),
                     std::to_string(steepest_slope) + " kink " + std::to_string(kink));
      EXPECT_LE(steepest_slope, 1.0 + 1e-6) << static_cast<int>(windows) << ripple;
      EXPECT_LT(kink, 0.05) << static_cast<int>(windows) << ripple;
      EXPECT_EQ(previous, last_touch) << static_cast<int>(windows) << ripple;
      compared += 3;
    }
  EXPECT_EQ(compared, 18);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
