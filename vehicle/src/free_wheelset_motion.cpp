#include "wheelwear/vehicle/free_wheelset_motion.hpp"

#include <array>
#include <boost/numeric/odeint/integrate/integrate_const.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

namespace {

using State = std::array<double, 4>;  // dy, yaw, lateral velocity, yaw rate

// Thrown from the right-hand side to stop the integration where the wheelset left its rails.
struct LeftTheRails {
  std::string why;
};

// The rolling radius of the wheel's most loaded patch.
double loaded_radius(const WheelForces& w) {
  double radius = 0.0, largest = -1.0;
  for (const PatchForces& p : w.patches)
    if (p.normal_force > largest) {
      largest = p.normal_force;
      radius = p.rolling_radius;
    }
  return radius;
}

}  // namespace

WheelsetMotion simulate_free_wheelset(const WheelsetModel& model, const FreeWheelsetBody& body,
                                      const RunningConditions& running,
                                      const WheelsetMotionState& start,
                                      const MotionOptions& options) {
  require(running.curve_radius == 0.0, "curve radius", running.curve_radius,
          "the free wheelset's motion is integrated on tangent track (0)");
  require(std::isfinite(body.mass) && body.mass > 0.0, "mass", body.mass, "must be positive");
  require(std::isfinite(body.yaw_inertia) && body.yaw_inertia > 0.0, "yaw inertia",
          body.yaw_inertia, "must be positive");
  require(std::isfinite(options.duration) && options.duration > 0.0, "duration", options.duration,
          "must be positive (s)");
  require(std::isfinite(options.time_step) && options.time_step > 0.0 &&
              options.time_step <= options.duration,
          "time step", options.time_step, "must lie in (0, duration] (s)");
  require(options.sample_every >= 1, "sample_every", options.sample_every, "must be >= 1");
  require(std::isfinite(body.lateral_stiffness) && body.lateral_stiffness >= 0.0,
          "lateral stiffness", body.lateral_stiffness, "must not be negative (N/m)");
  require(std::isfinite(body.yaw_stiffness) && body.yaw_stiffness >= 0.0, "yaw stiffness",
          body.yaw_stiffness, "must not be negative (N m/rad)");

  // Free rolling on the centred wheelset's radius.
  WheelsetMotionState centred;
  centred.spin = 1.0;
  const WheelsetForces at_centre =
      wheelset_forces(model, centred, body.wheel_load, body.wheel_load, running);
  require(
      contactgeom::carries_load(at_centre.wheels[0].status) && !at_centre.wheels[0].patches.empty(),
      "centred wheelset", 0.0, "has no contact on its rails");
  const double spin = running.speed / loaded_radius(at_centre.wheels[0]);

  const auto system = [&](const State& x, State& dxdt, double /*t*/) {
    WheelsetMotionState s;
    s.dy = x[0];
    s.yaw = x[1];
    s.lateral_velocity = x[2];
    s.yaw_rate = x[3];
    s.spin = spin;
    const WheelsetForces f = wheelset_forces(model, s, body.wheel_load, body.wheel_load, running);
    for (const WheelForces& w : f.wheels)
      if (!contactgeom::carries_load(w.status))
        throw LeftTheRails{"a wheel left its rail at dy = " + std::to_string(s.dy) + " m (" +
                           contactgeom::status_name(w.status) +
                           "): the motion has grown past the profiles"};
    if (!f.loads_met) throw LeftTheRails{f.message};
    dxdt = {x[2], x[3], (f.lateral - body.lateral_stiffness * x[0]) / body.mass,
            (f.yaw_moment - body.yaw_stiffness * x[1]) / body.yaw_inertia};
  };

  WheelsetMotion motion;
  std::vector<WheelsetSample>& samples = motion.samples;
  int step = 0;
  const auto observe = [&](const State& x, double t) {
    if (step++ % options.sample_every != 0) return;
    WheelsetSample s;
    s.time = t;
    s.distance = running.speed * t;
    s.state = {x[0], x[1], spin, x[2], x[3]};
    samples.push_back(s);
  };
  State x = {start.dy, start.yaw, start.lateral_velocity, start.yaw_rate};
  boost::numeric::odeint::runge_kutta4<State> stepper;
  try {
    boost::numeric::odeint::integrate_const(stepper, system, x, 0.0, options.duration,
                                            options.time_step, observe);
    motion.completed = true;
  } catch (const LeftTheRails& stop) {
    motion.message = stop.why;
  }
  return motion;
}

}  // namespace wheelwear::vehicle
