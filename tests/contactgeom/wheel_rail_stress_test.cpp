// Seeded randomised sweeps of the wheel/rail contact: measured-like (noisy) wheel profiles,
// lateral shifts across the flange, loads from 1 N to 300 kN, with and without yaw and roll.
// Invariants: only documented statuses or InputError, every number finite, the load carried.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/contactgeom/wheelset.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::contactgeom {
namespace {

// S1002 with Gaussian noise of `sigma` [m] along the surface normal every 0.5 mm, read back as
// a measured profile would be (smoothed over 0.5 mm).
profiles::Profile noisy_s1002(double sigma, unsigned seed) {
  const profiles::Profile clean = profiles::s1002();
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  profiles::PointList points;
  for (double s = 0.0; s <= clean.length(); s += 0.5e-3)
    points.push_back(clean.position(s) + noise(random) * clean.normal(s));
  profiles::CurveOptions curve;
  curve.smoothing_length = 0.5e-3;
  return profiles::Profile(points, clean.info(), curve);
}

bool finite_patch(const WheelRailPatch& p) {
  for (double v : {p.sdec.a, p.sdec.b, p.sdec.psi, p.y_wheel, p.y_rail, p.contact_angle,
                   p.rolling_radius, p.normal_force, p.pmax, p.measures.area})
    if (!std::isfinite(v)) return false;
  return p.sdec.a > 0.0 && p.sdec.b > 0.0 && std::abs(p.sdec.psi) < 1.0 && p.normal_force > 0.0;
}

TEST(WheelRailStress, NoisyProfilesAcrossTheFlangeAtAnyLoad) {
  std::mt19937 random(20221122);
  std::uniform_real_distribution<double> shift(-10e-3, 8e-3), unit(0.0, 1.0);
  int solved = 0, statuses[7] = {};
  for (int profile = 0; profile < 4; ++profile) {
    // 2 to 20 um of noise: a good and a worn-out measuring device.
    const WheelRailPair pair(noisy_s1002(2e-6 * std::pow(10.0, profile / 3.0), 7 + profile),
                             profiles::rail_60e1());
    for (int k = 0; k < 60; ++k) {
      WheelsetPose pose;
      pose.dy = shift(random);
      pose.yaw = (unit(random) - 0.5) * 0.01;
      pose.roll = (unit(random) - 0.5) * 0.01;
      const double load = std::pow(10.0, unit(random) * std::log10(3e5));  // 1 N ... 300 kN
      WheelRailContact contact;
      try {
        contact = solve_wheel_rail(pair, pose, load);
      } catch (const InputError& error) {
        ADD_FAILURE() << "valid input rejected: " << error.what();
        continue;
      }
      ++statuses[static_cast<int>(contact.status)];
      for (const auto& p : contact.patches)
        EXPECT_TRUE(finite_patch(p)) << "dy " << pose.dy << " load " << load;
      if (contact.status == WheelRailStatus::ok) {
        ++solved;
        // The load solve stops at |Fz/Fz_target - 1| <= 1e-9 (WheelRailOptions); 1e-6 allows
        // for the patch sums' rounding.
        EXPECT_NEAR(contact.vertical_force, load, 1e-6 * load) << "dy " << pose.dy;
        EXPECT_TRUE(std::isfinite(contact.lateral_force));
      }
    }
  }
  // Most positions on noisy profiles still solve; the rest report a status, not a failure.
  EXPECT_GT(solved, 180) << "statuses: ok " << statuses[0] << ", no contact " << statuses[1]
                         << ", flange climb " << statuses[2] << ", not converged " << statuses[3]
                         << ", load jump " << statuses[4] << ", profile end " << statuses[5]
                         << ", past flange " << statuses[6];
}

TEST(WheelRailStress, WheelsetOnNoisyProfilesStaysFinite) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-9e-3, 9e-3), unit(0.0, 1.0);
  const WheelRailPair left(noisy_s1002(5e-6, 1), profiles::rail_60e1());
  const WheelRailPair right(noisy_s1002(5e-6, 2), profiles::rail_60e1());
  for (int k = 0; k < 25; ++k) {
    WheelsetState state;
    state.dy = shift(random);
    state.yaw = (unit(random) - 0.5) * 0.006;
    state.vertical_force_left = 20e3 + 80e3 * unit(random);
    state.vertical_force_right = 20e3 + 80e3 * unit(random);
    if (k % 3 == 0) state.lateral_force_left = 40e3 * unit(random);
    const WheelsetContact c = solve_wheelset({left, right}, state);
    EXPECT_TRUE(std::isfinite(c.roll)) << "dy " << state.dy;
    EXPECT_LT(std::abs(c.roll), 0.02) << "dy " << state.dy;  // 18 mm of shift tilt < 20 mrad
    for (const auto* wheel : {&c.left, &c.right})
      for (const auto& p : wheel->patches) EXPECT_TRUE(finite_patch(p)) << "dy " << state.dy;
  }
}

}  // namespace
}  // namespace wheelwear::contactgeom
