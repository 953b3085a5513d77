#include "wheelwear/vehicle/vehicle_stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "vehicle_system.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"

namespace wheelwear::vehicle {

namespace {

using detail::State;
using detail::VehicleSystem;

// A tangent long enough for the car body's centre and all its wheelsets: on ideal straight
// track the place does not matter.
Route tangent_route(double speed) {
  RouteSection section;
  section.kind = SectionKind::tangent;
  section.length_m = 1e4;
  section.speed_m_s = speed;
  Route route;
  route.name = "tangent";
  route.sections = {section};
  return route;
}

// The models as the linearisation evaluates them: loads met to the quasi-static solver's
// tolerance (a looser one would add its noise to the differences) on the options' grid.
std::array<WheelsetModel, kWheelsets> linearised_models(
    const std::array<WheelsetModel, kWheelsets>& models, const VehicleStabilityOptions& options) {
  std::array<WheelsetModel, kWheelsets> out = models;
  for (WheelsetModel& m : out) {
    m.load_tolerance = 1e-9;
    if (options.fastsim_grid > 0) m.solve.fastsim.nx = m.solve.fastsim.ny = options.fastsim_grid;
  }
  return out;
}

// dx/dt of `system` at x, a wheel leaving its rail reported as bad input.
State rate_of(VehicleSystem& system, const State& x) {
  State dxdt{};
  try {
    system.derivative(x, dxdt, 0.0);
  } catch (const VehicleSystem::LeftTheRails& e) {
    throw InputError("linearised vehicle: " + e.why);
  }
  return dxdt;
}

// Whether state j is a wheelset's lateral shift.
bool wheelset_shift(int j) {
  for (int k = 0; k < kWheelsets; ++k)
    if (j == 2 * detail::wheelset_body(k)) return true;
  return false;
}

using Jacobian = Eigen::Matrix<double, detail::kStates, detail::kStates>;

// The central-difference Jacobian of the vehicle's motion about x0.
Jacobian jacobian(VehicleSystem& system, const State& x0,
                         const VehicleStabilityOptions& options) {
  const int n = detail::kStates;
  Jacobian J;
  for (int j = 0; j < n; ++j) {
    double h = options.step;
    if (j >= detail::spin_index(0)) h = options.step * std::abs(x0[static_cast<std::size_t>(j)]);
    if (wheelset_shift(j) && options.amplitude > 0.0) h = options.amplitude;
    State plus = x0, minus = x0;
    plus[static_cast<std::size_t>(j)] += h;
    minus[static_cast<std::size_t>(j)] -= h;
    const State fp = rate_of(system, plus), fm = rate_of(system, minus);
    for (int i = 0; i < n; ++i)
      J(i, j) = (fp[static_cast<std::size_t>(i)] - fm[static_cast<std::size_t>(i)]) / (2.0 * h);
  }
  return J;
}

}  // namespace

VehicleModes vehicle_modes(const Vehicle& vehicle,
                           const std::array<WheelsetModel, kWheelsets>& models, double speed,
                           const VehicleStabilityOptions& options) {
  vehicle.validate();
  require(std::isfinite(speed) && speed > 0.0 && speed <= 100.0, "speed", speed,
          "must lie in (0, 100] m/s");
  require(std::isfinite(options.step) && options.step > 0.0 && options.step <= 1e-3,
          "linearisation step", options.step, "must lie in (0, 1e-3]");
  require(
      std::isfinite(options.amplitude) && options.amplitude >= 0.0 && options.amplitude <= 10e-3,
      "linearisation amplitude", options.amplitude, "must lie in [0, 10 mm] (0: the step)");
  require(options.fastsim_grid >= 0 && options.fastsim_grid <= 1000, "FASTSIM grid",
          options.fastsim_grid, "must lie in 0 ... 1000 (0: the models' grids)");
  require(vehicle.wheelset.spin_inertia > 0.0, "wheelset spin inertia",
          vehicle.wheelset.spin_inertia, "must be positive (kg m^2)");
  const std::array<WheelsetModel, kWheelsets> evaluated = linearised_models(models, options);
  // The steady state on tangent track: centred for mirror-symmetric wheelsets, free rolling.
  SteadyCurve straight;
  straight.running.speed = speed;
  const VehicleCurving steady = solve_vehicle_curving(vehicle, evaluated, straight);
  if (!steady.converged)
    throw InputError("linearised vehicle: no steady state on tangent track at " +
                     std::to_string(speed) + " m/s: " + steady.message);
  const Route route = tangent_route(speed);
  const TrackIrregularities ideal;
  VehicleSystem system(vehicle, evaluated, route, ideal, 0.5 * route.total_length(), speed);
  const Jacobian J = jacobian(system, detail::initial_state(placement_of(steady)), options);
  const Eigen::EigenSolver<Jacobian> solver(J, false);
  VehicleModes modes;
  modes.speed = speed;
  modes.growth_rate = -INFINITY;
  for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i) {
    const std::complex<double> e = solver.eigenvalues()[i];
    modes.eigenvalues.push_back(e);
    if (e.real() > modes.growth_rate) {
      modes.growth_rate = e.real();
      modes.frequency = std::abs(e.imag());
    }
  }
  return modes;
}

CriticalSpeed vehicle_critical_speed(const Vehicle& vehicle,
                                     const std::array<WheelsetModel, kWheelsets>& models,
                                     const VehicleStabilityOptions& options) {
  require(std::isfinite(options.max_speed) && options.max_speed > 0.0 && options.max_speed <= 100.0,
          "largest speed", options.max_speed, "must lie in (0, 100] m/s");
  require(std::isfinite(options.speed_step) && options.speed_step > 0.0 &&
              options.speed_step <= options.max_speed,
          "speed step", options.speed_step, "must lie in (0, the largest speed] m/s");
  require(std::isfinite(options.neutral_rate) && options.neutral_rate >= 0.0, "neutral rate",
          options.neutral_rate, "must not be negative (1/s)");
  require(std::isfinite(options.start_speed) && options.start_speed >= 0.0 &&
              options.start_speed <= options.max_speed,
          "start speed", options.start_speed, "must lie in [0, the largest speed] m/s");
  require(std::isfinite(options.tolerance) && options.tolerance > 0.0 && options.tolerance < 0.5,
          "tolerance", options.tolerance, "must lie in (0, 0.5)");
  const auto growing = [&](double speed) {
    return vehicle_modes(vehicle, models, speed, options).growth_rate > options.neutral_rate;
  };
  // A bracket [stable, unstable] one speed step wide, found by stepping from the start.
  const double step = options.speed_step;
  double stable = 0.0, unstable = 0.0;
  double speed = options.start_speed > 0.0 ? options.start_speed : step;
  if (growing(speed)) {
    unstable = speed;
    for (speed -= step; speed >= step - 1e-9; speed -= step) {
      if (!growing(speed)) break;
      unstable = speed;
    }
    if (speed < step - 1e-9) return {};  // unstable down to the first speed
    stable = speed;
  } else {
    stable = speed;
    while (true) {
      if (stable >= options.max_speed) return {};  // stable up to the largest speed
      speed = std::min(stable + step, options.max_speed);
      if (growing(speed)) break;
      stable = speed;
    }
    unstable = speed;
  }
  while (unstable - stable > options.tolerance * unstable) {
    const double mid = 0.5 * (stable + unstable);
    (growing(mid) ? unstable : stable) = mid;
  }
  return {true, 0.5 * (stable + unstable)};
}

}  // namespace wheelwear::vehicle
