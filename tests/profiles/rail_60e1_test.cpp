// Tests of the generated 60E1 rail head: arc geometry, curvature, EN 15302 rail A and CONTACT's
// UIC60 data file.

#include "wheelwear/profiles/rail_60e1.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::profiles {
namespace {

using testing::contact_rail_file;
using testing::data_path;
using testing::read_text;

// The rigid translation (dy, dz) [m] that best lays `profile` onto `points` in the least-squares
// sense of vertical residuals z_i - (z(y_i - dy) + dz), over the points `use` accepts
// (Gauss-Newton; the frames differ only in where their origins sit).
Point fit_translation(const Profile& profile, const PointList& points,
                      const std::function<bool(const Point&)>& use) {
  Point t(0.0, 0.0);
  for (int iteration = 0; iteration < 20; ++iteration) {
    Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
    Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
    for (const Point& p : points) {
      if (!use(p)) continue;
      const auto sample = profile.surface_at(p[0] - t[0]);
      if (!sample) continue;
      // Residual r = z_i - z(y_i - dy) - dz and its gradient (dr/d dy, dr/d dz) = (z', -1).
      const double r = p[1] - sample->z - t[1];
      const Eigen::Vector2d j(sample->dz_dy, -1.0);
      normal += j * j.transpose();
      rhs += j * r;
    }
    const Eigen::Vector2d step = normal.ldlt().solve(-rhs);  // Gauss-Newton step
    t += step;
    if (step.norm() < 1e-13) break;
  }
  return t;
}

double max_vertical_deviation(const Profile& profile, const PointList& points, const Point& t) {
  double worst = 0.0;
  for (const Point& p : points)
    if (const auto z = profile.z_at(p[0] - t[0]))
      worst = std::max(worst, std::abs(p[1] - *z - t[1]));
  return worst;
}

TEST(Rail60E1, ArcsAreTangentInSequence) {
  const auto arcs = rail_60e1_arcs();
  ASSERT_EQ(arcs.size(), 5u);
  for (std::size_t i = 0; i + 1 < arcs.size(); ++i) {
    // Internally tangent arcs: centres R_big - R_small apart, and the joint on both circles.
    const double d = (arcs[i].centre - arcs[i + 1].centre).norm();
    EXPECT_NEAR(d, std::abs(arcs[i].radius - arcs[i + 1].radius), 1e-13);
    EXPECT_NEAR(arcs[i].y_to, arcs[i + 1].y_from, 1e-15);
  }
  EXPECT_NEAR(arcs[2].radius, 0.300, 1e-15);
  EXPECT_NEAR(arcs[2].y_to, 0.0105, 1e-15);
  EXPECT_NEAR(arcs[4].y_to, 0.036, 1e-15);  // head width 72 mm where the 1:20 flanks start
  // The R13 centre as EN 15302 rail A puts it, rotated back upright (see rail_60e1.cpp).
  EXPECT_NEAR(arcs[4].centre[0], 23.01622e-3, 2e-8);
  EXPECT_NEAR(arcs[4].centre[1], 14.90893e-3, 2e-8);
}

TEST(Rail60E1, CurvatureOfTheArcsIsOneOverR) {
  const Profile rail = rail_60e1({.inclination = 0.0});
  for (const HeadArc& arc : rail_60e1_arcs()) {
    const double y = 0.5 * (arc.y_from + arc.y_to);
    const double s = rail.surface_at(y)->s;
    // Mid-arc, at least 5 mm from the joints, whose curvature jumps the C2 spline spreads over
    // about one 0.25 mm knot interval and damps by 2 - sqrt(3) per interval beyond it. What is
    // left is the spline's own (h/R)^2 / 12: 3e-5 on the R13.
    EXPECT_NEAR(rail.curvature(s) * arc.radius, 1.0, 1e-4) << "R = " << arc.radius;
  }
}

struct Deviation {
  double vertical = 0.0;  // largest |z_table - z| [m]
  double normal = 0.0;    // the same measured across the surface, |dz| / sqrt(1 + slope^2) [m]
};

// 60E1 inclined by `angle`, laid onto EN 15302 Table I.6 by a fitted translation (its frame puts
// y = 0 elsewhere), and its deviations from the table.
Deviation deviation_from_rail_a(double angle) {
  const RawProfile table =
      parse_columns(read_text(data_path("profiles/en15302_rail_a_table_i6.csv")), "table I.6");
  EXPECT_EQ(table.points.size(), 72u);
  const Profile rail = rail_60e1({.inclination = angle});
  const Point t = fit_translation(rail, table.points, [](const Point&) { return true; });
  Deviation d;
  for (const Point& p : table.points) {
    const auto sample = rail.surface_at(p[0] - t[0]);
    const double dz = std::abs(p[1] - sample->z - t[1]);
    d.vertical = std::max(d.vertical, dz);
    d.normal = std::max(d.normal, dz / std::hypot(1.0, sample->dz_dy));
  }
  std::printf(
      "60E1 inclined %.6f rad vs EN 15302 Table I.6: max deviation %.3g mm vertically, "
      "%.3g mm normal to the surface, after moving by (%.4f, %.4f) mm\n",
      angle, d.vertical * 1e3, d.normal * 1e3, t[0] * 1e3, t[1] * 1e3);
  return d;
}

TEST(Rail60E1, ReproducesEN15302RailATable) {
  // Rail A is this head inclined by exactly 0.05 rad. The table's 5 decimals and the rounded
  // arc centres behind it (5 decimals, asymmetric by 5e-5 mm between the two R13 arcs) leave
  // 1e-4 mm across the surface; on the steep R13 ends (slope 3) that is 2.5e-4 mm vertically.
  const Deviation exact = deviation_from_rail_a(0.05);
  EXPECT_LT(exact.normal, 1e-4 * 1e-3);
  EXPECT_LT(exact.vertical, 3e-4 * 1e-3);
  // The bound pins the angle: 1:20 read as atan(1/20) instead of 0.05 rad misses it.
  const Deviation atan = deviation_from_rail_a(std::atan(1.0 / 20.0));
  EXPECT_GT(atan.normal, 1e-4 * 1e-3);
}

TEST(Rail60E1, MatchesContactsUIC60FileWithin20Micrometres) {
  // MBench_UIC60_v3.prr is the UIC60 head inclined 1:40 with its origin on the top of rail.
  // Both put the origin on the top, but the top of a flat crown is ill-defined laterally, so the
  // translation is fitted over the running surface (down to the gauge measuring depth).
  const RawProfile file = read_profile_file(contact_rail_file());
  const Profile rail = rail_60e1();  // 1:40, flanks to 37.5 mm as in the file
  const Point t = fit_translation(rail, file.points, [](const Point& p) { return p[1] < 0.014; });
  const double worst = max_vertical_deviation(rail, file.points, t);
  PointList running_surface;
  for (const Point& p : file.points)
    if (p[1] < 0.014) running_surface.push_back(p);
  const double head = max_vertical_deviation(rail, running_surface, t);
  std::printf(
      "60E1 (1:40) vs MBench_UIC60_v3.prr: max vertical deviation %.3g mm over all %zu points, "
      "%.3g mm down to 14 mm, after moving by (%.4f, %.4f) mm\n",
      worst * 1e3, file.points.size(), head * 1e3, t[0] * 1e3, t[1] * 1e3);
  // Reached: 4.3e-3 mm, on the near-vertical flanks where 1 um laterally is 25 um vertically;
  // issue 3 sets 0.02 mm as the goal.
  EXPECT_LT(worst, 0.01e-3);
  EXPECT_LT(head, 0.5e-6);             // reached 1.4e-4 mm on the running surface
  EXPECT_LT(std::abs(t[0]), 0.05e-3);  // the origins agree to the crown's lateral uncertainty
  EXPECT_LT(std::abs(t[1]), 1e-6);
}

TEST(Rail60E1, InclinationTurnsTheCrownTowardsTheGaugeSide) {
  EXPECT_DOUBLE_EQ(inclination_angle(RailInclination::one_in_40), std::atan(1.0 / 40.0));
  EXPECT_DOUBLE_EQ(inclination_angle(RailInclination::one_in_20), std::atan(1.0 / 20.0));
  EXPECT_EQ(inclination_angle(RailInclination::none), 0.0);
  EXPECT_DOUBLE_EQ(Rail60E1Options{}.inclination, std::atan(1.0 / 40.0));
  for (double a : {0.0, std::atan(1.0 / 40.0), std::atan(1.0 / 20.0)}) {
    const Profile rail = rail_60e1({.inclination = a});
    // Origin on the top of rail: exactly in height; laterally only to 1 um, since the crown is
    // flat there (1 um across is 6e-12 m in height on the R80).
    const ProfilePoint top = top_of_rail(rail);
    EXPECT_NEAR(top.point[1], 0.0, 1e-10) << a;  // the fitted crown's top: interpolation error
    EXPECT_NEAR(top.point[0], 0.0, 1e-6) << a;
    // Turned inwards, the gauge-side flank bottom (upright at y = -37.162 mm, 37.5 mm deep)
    // sinks by 37.162 mm * sin(a) and the field-side one rises as much.
    const PointList points = rail_60e1_points({.inclination = a});
    const double bottom = 0.036 + (0.0375 - 0.0142597376) / 20.0;
    EXPECT_NEAR(points.front()[1] - points.back()[1], 2 * bottom * std::sin(a), 1e-9) << a;
  }
}

TEST(Rail60E1, RejectsBadOptions) {
  EXPECT_THROW(rail_60e1({.inclination = -0.01}), InputError);
  EXPECT_THROW(rail_60e1({.inclination = 0.2}), InputError);
  EXPECT_THROW(rail_60e1({.flank_depth = 0.01}), InputError);
  EXPECT_THROW(rail_60e1({.point_spacing = 1.0}), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
