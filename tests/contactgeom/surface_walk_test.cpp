// Walking a profile's surface along increasing y: the same points as the lookup, on the rolled
// curve where it is rolled, and a walked stretch that does not face the mating body is refused.

#include "surface_walk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::contactgeom::detail {
namespace {

// Walks `walk` over [from, to] every `step` (m) the way the gap sampling does: a lookup starts a
// walk and closes it where it stops. Returns the largest |z_walk - z_lookup| and counts the
// stretches that did not stand.
double walk_against_lookup(const profiles::Profile& p, double from, double to, double step,
                           int& refused) {
  SurfaceWalk walk;
  walk.reset(p, 0.0, 0.0);
  double worst = 0.0;
  auto close = [&] {
    if (!walk.open()) return;
    const auto l = p.surface_at(walk.last_y());
    refused += !walk.close(l ? std::optional<double>(l->s) : std::nullopt);
  };
  for (double y = from; y <= to; y += step) {
    const auto lookup = p.surface_at(y);
    auto w = walk.at(y);
    if (!w) {
      close();
      if (!lookup) continue;
      walk.seed(y, lookup->s);
      continue;
    }
    if (!lookup) return 1.0;  // the walk answered where the curve is not
    worst = std::max(worst, std::abs(w->z - lookup->z));
  }
  close();
  return worst;
}

TEST(SurfaceWalk, MatchesTheLookupOnWheelAndRail) {
  // Both solve y(t) = y on the same cubic to round-off: 1e-15 m.
  int refused = 0;
  const profiles::Profile wheel = profiles::s1002();
  const profiles::Profile rail = profiles::rail_60e1();
  EXPECT_LT(walk_against_lookup(wheel, -0.06, 0.06, 0.1e-3, refused), 1e-15);
  EXPECT_LT(walk_against_lookup(rail, rail.y_min(), rail.y_max(), 0.1e-3, refused), 1e-15);
  EXPECT_EQ(refused, 0);
}

TEST(SurfaceWalk, FollowsTheRolledCurve) {
  const profiles::Profile wheel = profiles::s1002();
  const double roll = -4e-3, z_pivot = wheel.surface_at(0.0)->z;
  SurfaceWalk walk;
  walk.reset(wheel, roll, z_pivot);
  const double c = std::cos(roll), s = std::sin(roll);
  bool seeded = false;
  int walked = 0;
  for (double y = -0.045; y <= 0.04; y += 0.1e-3) {
    const auto w = walk.at(y);
    if (!w) {
      ASSERT_FALSE(seeded) << "the walk stopped on a rising stretch at " << y;
      // Start on the curve point whose rotated y is this y: y itself moved back by the
      // rotation, found by fixed-point steps (contraction |roll slope| < 0.02).
      double t = y;
      for (int i = 0; i < 50; ++i) t = (y + s * (wheel.surface_at(t)->z - z_pivot)) / c;
      walk.seed(y, wheel.surface_at(t)->s);
      seeded = true;
      continue;
    }
    ++walked;
    // The point is on the unrolled curve (its own position at s), and rotated it lies at y.
    const profiles::Point on_curve = wheel.position(w->s);
    EXPECT_NEAR(on_curve[0], w->y, 1e-15);
    EXPECT_NEAR(on_curve[1], w->z, 1e-15);
    EXPECT_NEAR(c * w->y - s * (w->z - z_pivot), y, 1e-15);
    EXPECT_NEAR(w->z_rolled, s * w->y + c * (w->z - z_pivot) + z_pivot, 1e-15);
  }
  EXPECT_GT(walked, 800);
}

// A wheel-like curve that folds back over itself: a lower branch z = 0 for y in [0, 12] mm, a
// turn up and back to y = 3 mm, and an upper branch z = 8 mm from there on. Facing the rail
// (largest z) the upper branch wins wherever both exist.
profiles::Profile folded() {
  profiles::PointList points;
  auto add = [&](double y_mm, double z_mm) { points.emplace_back(y_mm * 1e-3, z_mm * 1e-3); };
  for (double y = 0.0; y < 10.0; y += 0.5) add(y, 0.0);
  for (int k = 0; k <= 16; ++k) {  // up and back round (10, 2) mm
    const double a = -0.5 * std::numbers::pi + std::numbers::pi * k / 16.0;
    add(10.0 + 2.0 * std::cos(a), 2.0 + 2.0 * std::sin(a));
  }
  for (double y = 9.5; y > 5.0; y -= 0.5) add(y, 4.0);
  for (int k = 0; k <= 16; ++k) {  // down and forward round (5, 6) mm
    const double a = -0.5 * std::numbers::pi - std::numbers::pi * k / 16.0;
    add(5.0 + 2.0 * std::cos(a), 6.0 + 2.0 * std::sin(a));
  }
  for (double y = 5.5; y <= 20.0; y += 0.5) add(y, 8.0);
  profiles::ProfileInfo info;
  info.body = profiles::Body::wheel;
  return profiles::Profile(points, info);
}

TEST(SurfaceWalk, RefusesAStretchThatDoesNotFaceTheMatingBody) {
  const profiles::Profile p = folded();
  SurfaceWalk walk;
  walk.reset(p, 0.0, 0.0);
  auto walk_lower = [&](double to) {
    walk.seed(0.5e-3, p.surface_at(0.5e-3)->s);
    for (double y = 0.6e-3; y <= to; y += 0.1e-3) EXPECT_TRUE(walk.at(y).has_value()) << y;
    const auto l = p.surface_at(walk.last_y());
    return walk.close(l->s);
  };
  // Up to 2 mm the lower branch is the surface; at 9 mm the upper one covers it.
  EXPECT_TRUE(walk_lower(2e-3));
  EXPECT_FALSE(walk_lower(9e-3));
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
