// The linear stability of the whole vehicle: the eigenvalues of its motion linearised about the
// centred state against the time-domain simulation of the same equations, whose hunting grows
// or decays at the rate of the least stable eigenvalue; the critical speed against conicity; bad
// input.

#include "wheelwear/vehicle/vehicle_stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "conical_wheelset.hpp"
#include "standard_wheelset.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"
#include "wheelwear/vehicle/vehicle_motion.hpp"

namespace wheelwear::vehicle {
namespace {

using testing::conical_wheelset;
using testing::four;

// Conical wheels (`lambda`) with Kalker's linear creep, their contacts from a look-up table.
std::array<WheelsetModel, kWheelsets> tabulated_cone(double lambda) {
  WheelsetModel m = conical_wheelset(lambda);
  m.table = std::make_shared<const contactgeom::WheelsetContactTable>(m.track, m.contact);
  return four(m);
}

// The critical speed of `models`, scanned from 5 m/s in steps of 5 m/s.
CriticalSpeed scanned_critical_speed(const std::array<WheelsetModel, kWheelsets>& models) {
  VehicleStabilityOptions search;
  search.speed_step = 5.0;
  return vehicle_critical_speed(default_vehicle(), models, search);
}

Route tangent(double speed) {
  RouteSection section;
  section.kind = SectionKind::tangent;
  section.length_m = 5000.0;
  section.speed_m_s = speed;
  Route route;
  route.sections = {section};
  return route;
}

// The leading wheelset's oscillation in time after `settle` [s] (when the other modes have
// died out): its growth rate [1/s], the least-squares slope of log |dy| at its half-cycle peaks
// against time, and its angular frequency [rad/s] from the zero crossings.
struct Oscillation {
  double growth_rate = NAN, frequency = NAN;
};

Oscillation observed(const VehicleMotion& m, double settle) {
  std::vector<double> t, log_peak, crossings;
  double peak = 0.0, peak_time = 0.0;
  for (std::size_t i = 1; i < m.samples.size(); ++i) {
    const double a = m.samples[i - 1].wheelsets[0].state.dy;
    const double b = m.samples[i].wheelsets[0].state.dy;
    if (std::abs(b) > peak) {
      peak = std::abs(b);
      peak_time = m.samples[i].time;
    }
    if ((a < 0.0) != (b < 0.0)) {
      const double crossing =
          m.samples[i - 1].time + (m.samples[i].time - m.samples[i - 1].time) * a / (a - b);
      if (peak_time > settle) {
        t.push_back(peak_time);
        log_peak.push_back(std::log(peak));
        crossings.push_back(crossing);
      }
      peak = 0.0;
    }
  }
  Oscillation o;
  if (t.size() < 6) return o;
  const double n = static_cast<double>(t.size());
  double st = 0.0, sl = 0.0, stt = 0.0, stl = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sl += log_peak[i];
    stt += t[i] * t[i];
    stl += t[i] * log_peak[i];
  }
  o.growth_rate = (n * stl - st * sl) / (n * stt - st * st);
  // Half a period between successive crossings.
  o.frequency = std::numbers::pi * static_cast<double>(crossings.size() - 1) /
                (crossings.back() - crossings.front());
  return o;
}

// The least damped eigenvalue oscillating faster than 10 rad/s: the wheelsets' and bogies'
// hunting, not the car body's sway and yaw (about 4 rad/s on its soft secondary suspension).
std::complex<double> hunting_mode(const VehicleModes& modes) {
  std::complex<double> best(-INFINITY, 0.0);
  for (const std::complex<double>& e : modes.eigenvalues)
    if (std::abs(e.imag()) > 10.0 && e.real() > best.real()) best = e;
  return best;
}

TEST(VehicleStability, HuntingGrowsAndDecaysAtTheEigenvaluesRate) {
  // Conical wheels (lambda 0.2) with Kalker's linear creep: the contact is linear over the
  // motion's amplitude, so the time-domain motion of the same equations must follow the
  // linearised model's least stable mode.
  const Vehicle v = default_vehicle();
  const auto models = tabulated_cone(0.2);
  const CriticalSpeed critical = scanned_critical_speed(models);
  ASSERT_TRUE(critical.found);
  std::printf("whole vehicle, lambda 0.2: linear critical speed %.2f m/s\n", critical.speed);
  int compared = 0;
  for (double factor : {0.85, 1.05}) {
    const double speed = factor * critical.speed;
    const VehicleModes modes = vehicle_modes(v, models, speed);
    EXPECT_EQ(modes.eigenvalues.size(), 32u);
    // Started from the centred state with the leading wheelset 0.1 mm off, for 4 s: the
    // hunting at 1.05 times the critical speed grows about 10 times (conical wheels have no
    // flange to stop it).
    SteadyCurve straight;
    straight.running.speed = speed;
    VehiclePlacement start = placement_of(solve_vehicle_curving(v, models, straight));
    start.wheelsets[0].dy = 0.1e-3;
    VehicleMotionOptions options;
    options.sample_distance = speed / 400.0;  // 400 samples a second
    options.fastsim_grid = 0;
    const VehicleMotion m =
        simulate_vehicle(v, models, tangent(speed), 1000.0, 4.0 * speed, {}, start, options);
    ASSERT_TRUE(m.completed) << m.message;
    const Oscillation seen = observed(m, 1.0);
    const std::complex<double> mode = hunting_mode(modes);
    std::printf(
        "V %.1f m/s: hunting in time %.4f 1/s at %.3f rad/s; eigenvalue %.4f %+.3fi "
        "(largest growth rate %.4f)\n",
        speed, seen.growth_rate, seen.frequency, mode.real(), mode.imag(), modes.growth_rate);
    EXPECT_EQ(seen.growth_rate > 0.0, factor > 1.0);
    // Measured: the frequency within 2 % and, above the critical speed, the growth rate within
    // 3.3 %: 5 % and 10 %. Below it the two bogies' hunting modes lie close together (-2.22
    // and -2.33 1/s at 28.0 and 28.1 rad/s) and the leading wheelset follows their sum, whose
    // envelope over 3 s decays at a rate near theirs but not at either (-2.51 1/s measured,
    // since the car body's weight acts over the bogies' pivots; -2.33 before): there it must
    // lie within 10 % of the span of the modes within 5 % of its frequency.
    EXPECT_NEAR(seen.frequency, std::abs(mode.imag()), 0.05 * std::abs(mode.imag()));
    double slowest = mode.real(), fastest = mode.real();
    for (const std::complex<double>& e : modes.eigenvalues)
      if (std::abs(std::abs(e.imag()) - seen.frequency) <= 0.05 * seen.frequency) {
        slowest = std::max(slowest, e.real());
        fastest = std::min(fastest, e.real());
      }
    if (factor > 1.0) {
      EXPECT_NEAR(seen.growth_rate, mode.real(), 0.1 * std::abs(mode.real()));
    } else {
      EXPECT_LE(seen.growth_rate, slowest + 0.1 * std::abs(slowest));
      EXPECT_GE(seen.growth_rate, fastest - 0.1 * std::abs(fastest));
    }
    if (factor > 1.0) {
      EXPECT_EQ(mode.real(), modes.growth_rate);  // hunting is the unstable mode
    }
    compared += 3;
  }
  EXPECT_EQ(compared, 6);
}

TEST(VehicleStability, HigherConicityLowersTheCriticalSpeed) {
  // A bogie's critical speed falls as the conicity rises (Wickens 2003, Fundamentals of Rail
  // Vehicle Dynamics, ch. 6).
  const Vehicle v = default_vehicle();
  VehicleStabilityOptions options;
  options.speed_step = 5.0;
  double last = INFINITY;
  for (double lambda : {0.1, 0.2, 0.4}) {
    const CriticalSpeed c = vehicle_critical_speed(v, tabulated_cone(lambda), options);
    ASSERT_TRUE(c.found) << lambda;
    EXPECT_LT(c.speed, last) << lambda;
    last = c.speed;
  }
}

TEST(VehicleStability, AStartSpeedFindsTheSameCrossing) {
  // Searched down from above and up from below the critical speed, the bisection lands on the
  // same crossing, within the tolerance (1e-4 of the speed) of the scan from the lowest speed.
  const Vehicle v = default_vehicle();
  const auto models = tabulated_cone(0.2);
  const CriticalSpeed scanned = scanned_critical_speed(models);
  ASSERT_TRUE(scanned.found);
  VehicleStabilityOptions options;
  options.speed_step = 5.0;
  for (double start : {scanned.speed - 7.0, scanned.speed + 7.0}) {
    options.start_speed = start;
    const CriticalSpeed c = vehicle_critical_speed(v, models, options);
    ASSERT_TRUE(c.found) << start;
    EXPECT_NEAR(c.speed, scanned.speed, 2e-4 * scanned.speed) << start;
  }
  // Stable up to the largest speed: not found.
  options.start_speed = 0.0;
  options.max_speed = 0.9 * scanned.speed;
  EXPECT_FALSE(vehicle_critical_speed(v, models, options).found);
}

TEST(VehicleStability, RefusesBadInput) {
  const Vehicle v = default_vehicle();
  const auto models = four(conical_wheelset(0.2));
  EXPECT_THROW(vehicle_modes(v, models, 0.0), InputError);
  EXPECT_THROW(vehicle_modes(v, models, NAN), InputError);
  EXPECT_THROW(vehicle_modes(v, models, 150.0), InputError);
  VehicleStabilityOptions o;
  o.step = 0.0;
  EXPECT_THROW(vehicle_modes(v, models, 30.0, o), InputError);
  o = {};
  o.speed_step = -1.0;
  EXPECT_THROW(vehicle_critical_speed(v, models, o), InputError);
  o = {};
  o.max_speed = 200.0;
  EXPECT_THROW(vehicle_critical_speed(v, models, o), InputError);
  Vehicle bad = v;
  bad.wheelset.spin_inertia = 0.0;
  EXPECT_THROW(vehicle_modes(bad, models, 30.0), InputError);
}

}  // namespace
}  // namespace wheelwear::vehicle
