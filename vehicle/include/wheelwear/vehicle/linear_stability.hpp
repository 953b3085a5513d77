#pragma once
/// The linear stability of a wheelset held in a frame by lateral and yaw springs (a bogie frame
/// that does not move): its lateral and yaw motion with Kalker's linear creep forces and conical
/// wheels, linearised about the centred state, and the speed at which it loses stability (the
/// linear critical speed). The classical model of Wickens (Fundamentals of Rail Vehicle
/// Dynamics, 2003, ch. 2): with x = (y, psi, dy/dt, dpsi/dt),
///
///   m y''   = 2 f22 (psi - y'/V) - ky y
///   I psi'' = -2 f11 e0 (e0 psi'/V + lambda y / r0) - kpsi psi
///
/// y the lateral shift (+ left), psi the yaw (+ counter-clockwise), f11 and f22 the creep
/// coefficients of one wheel, e0 the lateral arm, lambda the conicity, r0 the rolling radius.
/// Without springs the wheelset is unstable at every speed; with them it is stable below the
/// critical speed.

#include <array>

namespace wheelwear::vehicle {

/// The linear model's parameters, SI units.
struct LinearWheelset {
  double mass = 1813.0;          ///< [kg]
  double yaw_inertia = 1120.0;   ///< [kg m^2]
  double lateral_stiffness = 0;  ///< ky of the springs to the frame [N/m]
  double yaw_stiffness = 0;      ///< kpsi of the springs to the frame [N m/rad]
  double f11 = 0.0;              ///< longitudinal creep coefficient of one wheel [N]
  double f22 = 0.0;              ///< lateral creep coefficient of one wheel [N]
  double conicity = 0.0;         ///< lambda [-]
  double rolling_radius = 0.46;  ///< r0 [m]
  double lateral_arm = 0.75;     ///< e0 [m]

  void validate() const;  ///< throws InputError naming a field out of range
};

/// The largest real part of the eigenvalues of the linearised motion at `speed` [1/s]: < 0
/// decays, > 0 grows.
double largest_growth_rate(const LinearWheelset& wheelset, double speed);

/// The eigenvalues' real and imaginary parts at `speed`, for plots and tests.
std::array<std::array<double, 2>, 4> eigenvalues(const LinearWheelset& wheelset, double speed);

/// Where the motion loses stability.
struct CriticalSpeed {
  bool found = false;
  double speed = 0.0;  ///< [m/s]
};

/// The speed at which the largest growth rate crosses zero from below, searched from 1 m/s up
/// to `max_speed` in steps of 1 m/s and refined by bisection to 1e-6 of the speed. Not found
/// when the wheelset is stable up to max_speed, or unstable from 1 m/s on (a free wheelset).
CriticalSpeed linear_critical_speed(const LinearWheelset& wheelset, double max_speed = 150.0);

}  // namespace wheelwear::vehicle
