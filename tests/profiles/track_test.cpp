// Tests of rail placement: top of rail, gauge point and the track frame.

#include "wheelwear/profiles/track.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

TEST(Track, GaugePointOfTheUprightHeadIsOnItsR13Arc) {
  // Closed form: 14 mm below the crown the gauge side is on the R13 arc centred at
  // (-23.01622, 14.90893) mm, so y = -(23.01622 + sqrt(13^2 - 0.90893^2)) mm.
  const Profile rail = rail_60e1({.inclination = 0.0});
  const auto arcs = rail_60e1_arcs();
  const Point c = arcs.front().centre;
  const double expected = c[0] - std::sqrt(0.013 * 0.013 - (c[1] - 0.014) * (c[1] - 0.014));
  const ProfilePoint g = gauge_point(rail, 0.014);
  // 14 mm is 0.26 mm above the R13/flank joint, where the curvature jumps by 1/13 mm: the C2
  // spline on 0.25 mm knots errs by about h^2 * 77 1/m / 100 = 5e-8 m there.
  EXPECT_NEAR(g.point[0], expected, 1e-7);
  EXPECT_NEAR(g.point[1], 0.014, 1e-12);
  EXPECT_NEAR(expected, -35.984e-3, 1e-6);
}

TEST(Track, PlacesBothRailsAtHalfTheGauge) {
  const TrackGeometry track;  // 1435 mm, 14 mm
  for (Side side : {Side::left, Side::right}) {
    const Profile rail = rail_60e1({.side = side});
    const RailPlacement placement = place_rail(rail, track);
    const Point g = placement.to_track(placement.gauge_point);
    EXPECT_NEAR(g[0], side == Side::right ? 0.7175 : -0.7175, 1e-15);
    EXPECT_NEAR(g[1], 0.014, 1e-12);
    EXPECT_NEAR(placement.to_track(placement.top)[1], 0.0, 1e-15);
    // The field side lies outside the gauge point, away from the track centre.
    const Point field = placement.to_track(rail.position(rail.length()));
    EXPECT_GT(std::abs(field[0]), 0.7175 + 0.060);
    const Point back = placement.to_profile(placement.to_track(Point(0.01, 0.02)));
    EXPECT_NEAR((back - Point(0.01, 0.02)).norm(), 0.0, 1e-15);
  }
}

TEST(Track, RejectsWheelsAndShallowProfiles) {
  EXPECT_THROW(place_rail(s1002()), InputError);
  const Profile rail = rail_60e1({.inclination = 0.0, .flank_depth = 0.0145});
  EXPECT_THROW(gauge_point(rail, 0.020), InputError);
  EXPECT_THROW(place_rail(rail, {1.435, 0.0}), InputError);
  EXPECT_THROW(place_rail(rail, {-1.0, 0.014}), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
