#include "wheelwear/vehicle/vehicle_motion.hpp"

#include <algorithm>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>
#include <optional>

#include "vehicle_system.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

using detail::fastest_rate;
using detail::initial_state;
using detail::State;
using detail::VehicleSystem;

VehicleMotion simulate_vehicle(const Vehicle& vehicle,
                               const std::array<WheelsetModel, kWheelsets>& wheelsets,
                               const Route& route, double start_m, double length_m,
                               const TrackIrregularities& irregularities,
                               const VehiclePlacement& start, const VehicleMotionOptions& options) {
  vehicle.validate();
  route.validate();
  require(std::isfinite(length_m) && length_m > 0.0, "length", length_m, "must be positive (m)");
  require(std::isfinite(start_m) && start_m <= route.total_length() && start_m + length_m > 0.0,
          "start", start_m,
          "must lie before the route's end with the piece reaching onto the route (m)");
  require(std::isfinite(options.time_step) && options.time_step >= 0.0 && options.time_step <= 0.01,
          "time step", options.time_step, "must lie in [0, 0.01] s (0: automatic)");
  require(std::isfinite(options.sample_distance) && options.sample_distance > 0.0,
          "sample distance", options.sample_distance, "must be positive (m)");
  require(std::isfinite(options.run_in) && options.run_in >= 0.0, "run-in distance", options.run_in,
          "must not be negative (m)");
  require(std::isfinite(options.load_tolerance) && options.load_tolerance > 0.0 &&
              options.load_tolerance <= 0.01,
          "load tolerance", options.load_tolerance, "must lie in (0, 0.01]");
  require(vehicle.wheelset.spin_inertia > 0.0, "wheelset spin inertia",
          vehicle.wheelset.spin_inertia,
          "must be positive for the time-domain simulation (kg m^2)");
  require(std::isfinite(options.speed) && options.speed >= 0.0 && options.speed <= 100.0, "speed",
          options.speed, "must lie in [0, 100] m/s (0: the route's)");
  const double speed =
      options.speed > 0.0 ? options.speed : track_at(route, std::max(0.0, start_m)).speed_m_s;
  // Samples at equal intervals no longer than the sample distance, both ends included.
  const double intervals = std::ceil(length_m / options.sample_distance - 1e-9);
  require(intervals < 1e7, "samples", intervals,
          "too many: raise the sample distance or shorten the piece");
  const long samples_wanted = std::max(1L, static_cast<long>(intervals)) + 1;
  const double spacing = length_m / static_cast<double>(samples_wanted - 1);
  require(options.fastsim_grid >= 0 && options.fastsim_grid <= 1000, "FASTSIM grid",
          options.fastsim_grid, "must lie in 0 ... 1000 (0: the models' grids)");
  std::array<WheelsetModel, kWheelsets> models = wheelsets;
  for (WheelsetModel& m : models) {
    m.load_tolerance = options.load_tolerance;
    if (options.fastsim_grid > 0) m.solve.fastsim.nx = m.solve.fastsim.ny = options.fastsim_grid;
  }

  const double s0 = start_m - options.run_in;
  VehicleSystem system(vehicle, models, route, irregularities, s0, speed);
  State x = initial_state(start);
  VehicleMotion motion;
  motion.planned_samples = samples_wanted;
  motion.sample_spacing = spacing;
  try {
    VehicleSample first;
    State dxdt{};
    system.derivative(x, dxdt, 0.0, &first);
    double dt = options.time_step;
    if (dt == 0.0) {
      dt = std::min(2e-3, 1.5 / fastest_rate(vehicle, models, first.wheelsets));
    }
    motion.time_step = dt;
    const auto rhs = [&](const State& s, State& d, double t) { system.derivative(s, d, t); };
    boost::numeric::odeint::runge_kutta4<State> stepper;
    const double t_first = options.run_in / speed;
    const double t_end = (options.run_in + length_m) / speed;
    long next = 0;  // the next sample's number
    double t = 0.0;
    const auto sample_time = [&](long n) {
      return n + 1 == samples_wanted ? t_end : t_first + static_cast<double>(n) * spacing / speed;
    };
    while (next < samples_wanted) {
      // Step up to the next sample, the last step shortened to land on it.
      const double target = sample_time(next);
      while (t < target - 1e-12 * t_end) {
        const double h = std::min(dt, target - t);
        stepper.do_step(rhs, x, t, h);
        t += h;
        ++motion.steps;
      }
      VehicleSample sample;
      system.derivative(x, dxdt, t, &sample);
      motion.samples.push_back(std::move(sample));
      ++next;
    }
    motion.completed = true;
  } catch (const VehicleSystem::LeftTheRails& stop) {
    motion.message = stop.why;
  } catch (const InputError& e) {
    // A diverging motion carries a stage beyond what the contact accepts; the start was valid.
    if (motion.time_step == 0.0) throw;
    motion.message = std::string("the motion left the contact's range: ") + e.what();
  }
  motion.wheelset_evaluations = system.evaluations();
  return motion;
}

}  // namespace wheelwear::vehicle
