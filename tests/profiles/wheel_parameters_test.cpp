// Tests of the EN 15313 wheel parameters Sh, Sd and qR.

#include "wheelwear/profiles/wheel_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

TEST(WheelParameters, S1002HasItsNominalValues) {
  const WheelParameters p = wheel_parameters(s1002());
  // Closed forms from the section arcs of the definition (s1002.cpp, sections D and F, mm):
  // Sd point where the R13 root reaches z = 10: y = -CD - sqrt(BD^2 - (AD - 10)^2);
  // qR point where the R20 face reaches z = 28 - 2: y = -CF + sqrt(BF^2 - (26 - AF)^2).
  const double y_sd = -26.210665 - std::sqrt(13.0 * 13.0 - 6.446 * 6.446);
  const double y_qr =
      -58.558326413 + std::sqrt(20.0 * 20.0 - (26.0 - 8.834924130) * (26.0 - 8.834924130));
  // The measurement runs on the fitted curve (0.25 mm knots). Its largest error is at the internal
  // face: where the vertical face meets the back arc (curvature jump 1/20.5 mm) the spline
  // bulges 1e-8 m beyond y = -70 mm, and Sd inherits that; 5e-8 m covers it.
  EXPECT_NEAR(p.Sh, 0.028, 5e-8);
  EXPECT_NEAR(p.Sd, (y_sd + 70.0) * 1e-3, 5e-8);
  EXPECT_NEAR(p.qR, (y_sd - y_qr) * 1e-3, 5e-8);
  // The standard's nominal values (EN 13715 / EN 15313): Sh = 28, Sd = 32.5, qR about 10.8 mm.
  EXPECT_NEAR(p.Sh, 0.028, 1e-6);
  EXPECT_NEAR(p.Sd, 0.0325, 1e-6);
  EXPECT_NEAR(p.qR, 0.0108, 0.05e-3);
  EXPECT_NEAR(p.internal_face[0], -0.070, 5e-8);
  EXPECT_NEAR(p.running_circle[0], 0.0, 5e-8);
  EXPECT_NEAR(p.flange_tip[0], -0.055, 1e-6);  // the R12 tip arc's centre is at y = -55 mm
}

TEST(WheelParameters, DoNotDependOnWhereTheOriginIs) {
  const WheelParameters a = wheel_parameters(s1002());
  const WheelParameters b = wheel_parameters(s1002().translated(0.005, -0.003));
  EXPECT_NEAR(a.Sh, b.Sh, 1e-12);
  EXPECT_NEAR(a.Sd, b.Sd, 1e-12);
  EXPECT_NEAR(a.qR, b.qR, 1e-12);
}

TEST(WheelParameters, AgreeWithAPolylineMeasurementOnTheMeasuredWheel) {
  // Independent estimate: the same definitions measured on the cleaned points, joined by straight
  // lines. The fitted curve smooths the zigzag at the tip (lines 222-229) by about 0.1 mm.
  const LoadedProfile wheel = load_profile(testing::measured_wheel_file());
  const PointList& pts = wheel.points.points;
  double back = 1.0;
  std::size_t tip = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    back = std::min(back, pts[i][0]);
    if (pts[i][1] > pts[tip][1]) tip = i;
  }
  auto crossing = [&](int axis, double value) -> Point {
    for (std::size_t i = tip; i + 1 < pts.size(); ++i) {
      const double a = pts[i][axis] - value, b = pts[i + 1][axis] - value;
      if ((a <= 0) != (b <= 0)) return pts[i] + (pts[i + 1] - pts[i]) * (a / (a - b));
    }
    return Point(NAN, NAN);
  };
  const Point tape = crossing(0, back + 0.070);
  const double sd_y = crossing(1, tape[1] + 0.010)[0];
  const double qr_y = crossing(1, pts[tip][1] - 0.002)[0];
  const WheelParameters p = wheel_parameters(wheel.profile);
  EXPECT_NEAR(p.Sh, pts[tip][1] - tape[1], 0.15e-3);
  EXPECT_NEAR(p.Sd, sd_y - back, 0.15e-3);
  EXPECT_NEAR(p.qR, sd_y - qr_y, 0.25e-3);
  std::printf("Car7216_0001r.whl: Sh %.2f Sd %.2f qR %.2f mm (polyline %.2f %.2f %.2f)\n",
              p.Sh * 1e3, p.Sd * 1e3, p.qR * 1e3, (pts[tip][1] - tape[1]) * 1e3,
              (sd_y - back) * 1e3, (sd_y - qr_y) * 1e3);
}

TEST(WheelParameters, RejectRailsAndFlangelessProfiles) {
  EXPECT_THROW(wheel_parameters(rail_60e1()), InputError);
  // A "wheel" that is only a tread has no flange to measure.
  PointList tread;
  for (int i = 0; i <= 100; ++i) tread.emplace_back(-0.01 + 0.001 * i, 0.0);
  EXPECT_THROW(wheel_parameters(Profile(tread, {"tread", Body::wheel, Side::right, 0.46})),
               InputError);
  EXPECT_THROW(wheel_parameters(s1002(), {.taping_line_offset = -1.0}), InputError);
}

// EN 15313's in-service limits by nominal diameter (the TSI LOC&PAS, Regulation (EU)
// No 1302/2014, 4.2.3.5.2.2, gives the same figures): the Sd bound steps at 760 and 840 mm.
TEST(WheelLimits, FollowTheStandardsDiameterBands) {
  struct Band {
    double diameter, Sd_min;
  };
  for (const Band& band : {Band{0.920, 22e-3}, Band{0.840, 22e-3}, Band{0.839, 25e-3},
                           Band{0.761, 25e-3}, Band{0.760, 27.5e-3}, Band{0.330, 27.5e-3}}) {
    const WheelLimits limits = in_service_limits(band.diameter);
    EXPECT_EQ(limits.Sd_min, band.Sd_min) << band.diameter;
    EXPECT_EQ(limits.Sh_max, 36e-3) << band.diameter;
    EXPECT_EQ(limits.qR_min, 6.5e-3) << band.diameter;
  }
  EXPECT_THROW(in_service_limits(0.329), InputError);
  EXPECT_THROW(in_service_limits(std::nan("")), InputError);
}

TEST(WheelLimits, NameWhatIsReachedAndCountUnmeasurableParameters) {
  const WheelLimits limits = in_service_limits(0.92);
  // The new S1002 (Sh 28, Sd 32.5, qR 10.8 mm) is far inside every limit.
  EXPECT_TRUE(limits_reached(wheel_parameters(s1002()), limits).empty());
  WheelParameters worn;
  worn.Sd = 21.9e-3;
  worn.Sh = 36e-3;  // on the limit counts as reached
  worn.qR = 7e-3;
  const std::vector<std::string> reached = limits_reached(worn, limits);
  ASSERT_EQ(reached.size(), 2u);
  EXPECT_EQ(reached[0], "Sd 21.900 mm <= 22.000 mm");
  EXPECT_EQ(reached[1], "Sh 36.000 mm >= 36.000 mm");
  // A profile worn past its reference points is past every watched limit; a NaN limit is not
  // watched.
  WheelParameters unmeasured;
  unmeasured.Sd = unmeasured.Sh = unmeasured.qR = std::nan("");
  EXPECT_EQ(limits_reached(unmeasured, limits).size(), 3u);
  EXPECT_EQ(limits_reached(unmeasured, limits)[0],
            "Sd not measurable (worn past its reference points)");
  WheelLimits unwatched = limits;
  unwatched.Sd_min = unwatched.qR_min = std::nan("");
  EXPECT_EQ(limits_reached(unmeasured, unwatched).size(), 1u);
  EXPECT_TRUE(limits_reached(worn, unwatched).size() == 1u);  // Sh only
}

}  // namespace
}  // namespace wheelwear::profiles
