// The load tolerances of the contact solvers: a prescribed load is met to |F/F_target - 1| <=
// load_tolerance, the status says so, and validate() keeps the tolerance in (0, 0.01].

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::contactgeom {
namespace {

const double kEstar = combined_modulus(200e9, 0.25);

// The message of the InputError `solve` throws, or "" when it throws none.
template <class Solve>
std::string input_error_of(Solve&& solve) {
  try {
    solve();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::vector<double> kBadTolerances = {0.0,
                                            -1e-9,
                                            0.0101,
                                            1.0,
                                            std::numeric_limits<double>::quiet_NaN(),
                                            std::numeric_limits<double>::infinity()};

// Sweeping the lateral position over tread, flange root and flange at three tolerances: every
// load is met to the tolerance (ok, or the flange/profile statuses that come after the load
// test), except where it falls inside a jump of the force (load_jump). The reference is the
// prescribed load against the sum of the patches' strip-wise vertical forces, summed here in
// another order than the solver's: rounding 1e-16 relative, so 1e-15 on top of the tolerance.
TEST(WheelRailLoadTolerance, VerticalForceMeetsTheRelativeTolerance) {
  const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  const double load = 55e3;
  int compared = 0, jumps = 0;
  for (double tol : {1e-9, 1e-6, 1e-3}) {
    WheelRailOptions options;
    options.load_tolerance = tol;
    for (int step = -10; step <= 8; ++step) {
      WheelsetPose pose;
      pose.dy = step * 1e-3;
      const WheelRailContact c = solve_wheel_rail(pair, pose, load, options);
      ASSERT_NE(c.status, WheelRailStatus::not_converged)
          << "tol " << tol << " dy " << pose.dy << ": " << c.message;
      ASSERT_NE(c.status, WheelRailStatus::no_contact) << "dy " << pose.dy;
      if (c.status == WheelRailStatus::load_jump) {
        ++jumps;
        continue;
      }
      double vertical = 0.0;
      for (auto p = c.patches.rbegin(); p != c.patches.rend(); ++p) vertical += p->vertical_force;
      EXPECT_LE(std::abs(vertical / load - 1.0), tol + 1e-15) << "tol " << tol << " dy " << pose.dy;
      EXPECT_LE(std::abs(c.vertical_force / load - 1.0), tol) << "tol " << tol << " dy " << pose.dy;
      ++compared;
    }
  }
  // 3 x 19 positions; the merge of tread and flange root catches at most one per tolerance.
  EXPECT_EQ(compared + jumps, 57);
  EXPECT_GE(compared, 54);
  RecordProperty("compared", compared);
}

// The wheel/rail solve meets its own tolerance also where the single-region fast path hands the
// load to the Kik-Piotrowski solver: a loose kp.load_tolerance does not leak into it.
TEST(WheelRailLoadTolerance, KpToleranceDoesNotLoosenTheWheelRailSolve) {
  const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  WheelRailOptions options;
  options.kp.load_tolerance = 1e-2;
  int compared = 0;
  for (double dy : {-4e-3, 0.0, 3e-3}) {
    WheelsetPose pose;
    pose.dy = dy;
    const WheelRailContact c = solve_wheel_rail(pair, pose, 55e3, options);
    ASSERT_EQ(c.status, WheelRailStatus::ok) << dy << ": " << c.message;
    ASSERT_EQ(c.patches.size(), 1u) << dy;  // the fast path's case
    EXPECT_LE(std::abs(c.vertical_force / 55e3 - 1.0), options.load_tolerance) << dy;
    ++compared;
  }
  EXPECT_EQ(compared, 3);
}

TEST(WheelRailLoadTolerance, ValidateKeepsItInRange) {
  const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  int rejected = 0;
  for (double tol : kBadTolerances) {
    WheelRailOptions options;
    options.load_tolerance = tol;
    const std::string message = input_error_of([&] { options.validate(); });
    EXPECT_NE(message.find("load_tolerance"), std::string::npos) << tol << ": " << message;
    if (std::isfinite(tol)) {
      EXPECT_NE(message.find("(0, 0.01]"), std::string::npos) << tol << ": " << message;
    }
    EXPECT_THROW(solve_wheel_rail(pair, {}, 55e3, options), InputError) << tol;
    ++rejected;
  }
  EXPECT_EQ(rejected, 6);
  for (double tol : {1e-12, 1e-2}) {
    WheelRailOptions options;
    options.load_tolerance = tol;
    EXPECT_NO_THROW(options.validate()) << tol;
  }
}

// The Kik-Piotrowski load solve on a single and a double well (two patches at small loads,
// merging at large ones), loads from 1 to 200 kN: converged exactly when |N/N_target - 1| <=
// load_tolerance, and every solve converges. The reference is the prescribed load itself.
TEST(KikPiotrowskiLoadTolerance, NormalForceMeetsTheRelativeTolerance) {
  const double ds = 1e-4;
  const int n = 240;
  std::vector<double> single(n), twin(n), ax(n, 1.0 / (2.0 * 0.46));
  for (int j = 0; j < n; ++j) {
    const double s = (j - n / 2 + 0.5) * ds;
    single[j] = 3.0 * s * s;
    twin[j] = std::min(3.0 * (s + 4e-3) * (s + 4e-3), 8.0 * (s - 5e-3) * (s - 5e-3) + 3e-6);
  }
  int compared = 0;
  for (const std::vector<double>* h : {&single, &twin}) {
    GapStrips gap;
    gap.s_first = (-n / 2 + 0.5) * ds;
    gap.ds = ds;
    gap.h = *h;
    gap.ax = ax;
    for (double tol : {1e-10, 1e-6, 1e-3, 1e-2}) {
      KpOptions options;
      options.load_tolerance = tol;
      for (double N = 1e3; N <= 200e3; N *= 1.7) {
        const KpResult r = solve_kp_load(gap, kEstar, N, options);
        const double error = std::abs(r.normal_force / N - 1.0);
        EXPECT_EQ(r.status, KpStatus::converged) << tol << " " << N << ": " << r.message;
        EXPECT_LE(error, tol) << tol << " " << N;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 2 * 4 * 10);
}

TEST(KikPiotrowskiLoadTolerance, ValidateKeepsItInRange) {
  int rejected = 0;
  for (double tol : kBadTolerances) {
    KpOptions options;
    options.load_tolerance = tol;
    const std::string message = input_error_of([&] { options.validate(); });
    EXPECT_NE(message.find("load_tolerance"), std::string::npos) << tol << ": " << message;
    if (std::isfinite(tol)) {
      EXPECT_NE(message.find("(0, 0.01]"), std::string::npos) << tol << ": " << message;
    }
    ++rejected;
  }
  EXPECT_EQ(rejected, 6);
  KpOptions loosest;
  loosest.load_tolerance = 1e-2;
  EXPECT_NO_THROW(loosest.validate());
}

}  // namespace
}  // namespace wheelwear::contactgeom
