// Klingel's kinematic oscillation: a conical wheelset without suspension, with linear creep at
// low speed, started 1 mm off centre, oscillates with the wavelength 2 pi sqrt(r0 e0 / lambda)
// (Klingel 1883; e.g. Wickens 2003, Fundamentals of Rail Vehicle Dynamics, ch. 2). A free
// wheelset is unstable at every speed: its amplitude grows, which is expected.

#include "wheelwear/vehicle/free_wheelset_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "conical_wheelset.hpp"

namespace wheelwear::vehicle {
namespace {

using testing::conical_wheelset;

// The distances at which dy changes sign, interpolated linearly between samples.
std::vector<double> zero_crossings(const std::vector<WheelsetSample>& samples) {
  std::vector<double> at;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double a = samples[i - 1].state.dy, b = samples[i].state.dy;
    if ((a < 0.0) != (b < 0.0) && a != b)
      at.push_back(samples[i - 1].distance +
                   (samples[i].distance - samples[i - 1].distance) * a / (a - b));
  }
  return at;
}

TEST(FreeWheelsetMotion, KlingelWavelength) {
  int compared = 0;
  for (double conicity : {0.1, 0.2}) {
    const WheelsetModel model = conical_wheelset(conicity);
    const RunningConditions running{10.0, 0.0, 0.3};
    // The wheelset's own r0 and lambda (conical_wheelset.hpp says why lambda_e differs from
    // the cone's slope).
    const testing::ConeGeometry g = testing::cone_geometry(model, 1e-3);
    const double r0 = g.centred_radius, lambda = g.conicity;
    const double wavelength = 2.0 * std::numbers::pi * std::sqrt(r0 * model.lateral_arm / lambda);
    WheelsetMotionState start;
    start.dy = 1e-3;
    MotionOptions options;
    options.duration = 3.4 * wavelength / running.speed;
    options.time_step = 1e-3;  // within RK4's stability: 2.8 times the creep's 1 ms at 10 m/s
    const WheelsetMotion motion =
        simulate_free_wheelset(model, FreeWheelsetBody{}, running, start, options);
    ASSERT_TRUE(motion.completed) << motion.message;
    const std::vector<double> zeros = zero_crossings(motion.samples);
    ASSERT_GE(zeros.size(), 7u) << conicity;
    // Three cycles: from the first crossing to the seventh.
    const double measured = (zeros[6] - zeros[0]) / 3.0;
    // 1 %: the wheelset's inertia at 10 m/s shifts the wavelength by (m V^2 / f22)-order terms
    // below 0.1 %, and the crossings are interpolated between samples 10 mm apart.
    EXPECT_NEAR(measured, wavelength, 0.01 * wavelength) << conicity;
    std::printf("lambda %.2f (effective %.4f): wavelength %.3f m, Klingel %.3f m\n", conicity,
                lambda, measured, wavelength);
    ++compared;
  }
  EXPECT_EQ(compared, 2);
}

}  // namespace
}  // namespace wheelwear::vehicle
