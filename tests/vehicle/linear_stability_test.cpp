// The linear stability of a wheelset held by its primary springs in a frame that does not move:
// the eigenvalues of the linearised model against Klingel's kinematic frequency, and its
// linear critical speed against the time-domain motion with the project's own contact forces,
// which decays below that speed and grows above it.

#include "wheelwear/vehicle/linear_stability.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "conical_wheelset.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/free_wheelset_motion.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::vehicle {
namespace {

using testing::cone_geometry;
using testing::conical_wheelset;

constexpr double kWheelLoad = 55e3;  // [N]

// The linear model of `model`'s wheelset: creep coefficients of its centred patch
// (testing::creep_coefficients), its effective conicity and rolling radius, the default
// vehicle's wheelset inertia and, with `springs`, a soft primary suspension (1 MN/m, 1 MN m/rad)
// that puts the critical speed near 50 m/s; the Manchester coach's own primary yaw stiffness holds
// a lone wheelset stable beyond 150 m/s.
LinearWheelset linear_model(const WheelsetModel& model, bool springs) {
  const testing::CreepCoefficients f = testing::creep_coefficients(model, kWheelLoad);
  const testing::ConeGeometry cone = cone_geometry(model, 1e-3);
  const Vehicle v = default_vehicle();
  LinearWheelset w;
  w.mass = v.wheelset.body.mass;
  w.yaw_inertia = v.wheelset.body.yaw_inertia;
  if (springs) {
    w.lateral_stiffness = 1e6;
    w.yaw_stiffness = 1e6;
  }
  w.f11 = f.f11;
  w.f22 = f.f22;
  w.conicity = cone.conicity;
  w.rolling_radius = cone.centred_radius;
  w.lateral_arm = model.lateral_arm;
  return w;
}

TEST(LinearStability, FreeWheelsetOscillatesAtKlingelsFrequencyAndIsUnstable) {
  const LinearWheelset w = linear_model(conical_wheelset(0.1), false);
  int compared = 0;
  for (double V : {2.0, 5.0, 10.0}) {
    const auto e = eigenvalues(w, V);
    double omega = 0.0, growth = -INFINITY;
    for (const auto& [re, im] : e) {
      omega = std::max(omega, std::abs(im));
      growth = std::max(growth, re);
    }
    // Klingel: wavelength 2 pi sqrt(r0 e0 / lambda), so omega = V sqrt(lambda / (r0 e0)); the
    // inertia shifts it by terms of order (m V^2 / f22) ... 1e-3 at 10 m/s: 1 %.
    const double klingel = V * std::sqrt(w.conicity / (w.rolling_radius * w.lateral_arm));
    EXPECT_NEAR(omega, klingel, 0.01 * klingel) << V;
    EXPECT_GT(growth, 0.0) << V;  // a free wheelset is unstable at every speed
    compared += 2;
  }
  EXPECT_FALSE(linear_critical_speed(w).found);
  EXPECT_EQ(compared, 6);
  LinearWheelset bad = w;
  bad.f11 = -1.0;
  EXPECT_THROW(largest_growth_rate(bad, 10.0), InputError);
}

// The peak |dy| of each half-cycle of a time-domain run, from the zero crossings.
std::vector<double> half_cycle_peaks(const WheelsetMotion& m) {
  std::vector<double> peaks;
  double peak = 0.0;
  for (std::size_t i = 1; i < m.samples.size(); ++i) {
    const double a = m.samples[i - 1].state.dy, b = m.samples[i].state.dy;
    peak = std::max(peak, std::abs(b));
    if ((a < 0.0) != (b < 0.0)) {
      peaks.push_back(peak);
      peak = 0.0;
    }
  }
  return peaks;
}

TEST(LinearStability, CriticalSpeedSeparatesDecayingFromGrowingMotion) {
  const WheelsetModel model = conical_wheelset(0.1);
  const LinearWheelset w = linear_model(model, true);
  const CriticalSpeed critical = linear_critical_speed(w);
  ASSERT_TRUE(critical.found);
  std::printf("linear critical speed %.2f m/s\n", critical.speed);
  EXPECT_LT(largest_growth_rate(w, 0.99 * critical.speed), 0.0);
  EXPECT_GT(largest_growth_rate(w, 1.01 * critical.speed), 0.0);
  FreeWheelsetBody body;
  body.mass = w.mass;
  body.yaw_inertia = w.yaw_inertia;
  body.wheel_load = kWheelLoad;
  body.lateral_stiffness = w.lateral_stiffness;
  body.yaw_stiffness = w.yaw_stiffness;
  WheelsetMotionState start;
  start.dy = 0.5e-3;
  // 15 % either side: the growth rate there is a clear fraction of the oscillation's frequency,
  // so six half-cycles show the trend well beyond what the contact's non-linearity at 0.5 mm
  // amplitude changes.
  for (double factor : {0.85, 1.15}) {
    const double V = factor * critical.speed;
    MotionOptions options;
    const double wavelength =
        2.0 * std::numbers::pi * std::sqrt(w.rolling_radius * w.lateral_arm / w.conicity);
    options.duration = 4.0 * wavelength / V;
    options.time_step =
        1e-3;  // RK4 needs h below 2.8 times the creep time constant m V / (2 f22), 3 ms
    const WheelsetMotion m = simulate_free_wheelset(model, body, {V, 0.0, 0.3}, start, options);
    ASSERT_TRUE(m.completed) << m.message;
    const std::vector<double> peaks = half_cycle_peaks(m);
    ASSERT_GE(peaks.size(), 6u) << factor;
    std::printf("V %.1f m/s: half-cycle peaks %.3f ... %.3f mm\n", V, peaks[1] * 1e3,
                peaks.back() * 1e3);
    if (factor < 1.0)
      EXPECT_LT(peaks.back(), 0.8 * peaks[1]) << "decays below the critical speed";
    else
      EXPECT_GT(peaks.back(), 1.25 * peaks[1]) << "grows above the critical speed";
  }
}

}  // namespace
}  // namespace wheelwear::vehicle
