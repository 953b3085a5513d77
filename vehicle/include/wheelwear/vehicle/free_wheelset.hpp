#pragma once
/// A single wheelset without suspension in steady curving: the lateral shift, angle of attack
/// and axle spin at which the rails' forces balance the in-plane inertial and gravity forces, the
/// yaw moment vanishes and the axle rolls freely (zero axle torque). The building block of the
/// vehicle's quasi-static curving, and its textbook check: on conical wheels at zero cant
/// deficiency it settles on the pure-rolling line dy = r0 e0 / (lambda R) with no angle of attack.

#include <string>

#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle {

/// A constant curve and how fast the wheelset runs through it.
struct SteadyCurve {
  RunningConditions running;
  double cant = 0.0;  ///< height of the outer rail above the inner [m], >= 0 (0 on tangent track)
  /// Distance over which the cant is measured [m]: sin(cant angle) = cant / cant_base (1.5 m,
  /// the rail-centre distance of standard gauge, EN 13803).
  double cant_base = 1.5;
  /// Longitudinal force per powered axle [N]: > 0 traction, < 0 braking, 0 coasting. A powered
  /// axle's contact torque balances traction x the wheels' nominal radius instead of zero.
  double traction = 0.0;

  double cant_angle() const;  ///< [rad]
  /// The in-plane force towards the curve centre that a body of mass m needs [N]:
  /// m (V^2/|R| cos(cant angle) - g sin(cant angle)); 0 on tangent track.
  double centripetal_force(double mass) const;
  /// The force normal to the track plane that carries a body of mass m [N]:
  /// m (g cos(cant angle) + V^2/|R| sin(cant angle)).
  double normal_force(double mass) const;
  /// Cant deficiency [m]: cant_base V^2 / (g |R|) - cant (EN 13803's approximation).
  double cant_deficiency() const;
  void validate() const;  ///< throws InputError naming the bad field
};

inline constexpr double kGravity = 9.81;  ///< [m/s^2]

/// The solved steady state.
struct FreeWheelsetCurving {
  bool converged = false;
  int iterations = 0;
  WheelsetMotionState state;  ///< dy, yaw (angle of attack), spin; rates zero
  WheelsetForces forces;      ///< at `state`
  /// Residuals at `state`: lateral force balance [N], yaw moment [N m], axle torque [N m].
  double lateral_residual = 0.0, yaw_residual = 0.0, torque_residual = 0.0;
  std::string message;  ///< why, when not converged
};

/// Solves the steady curving of a free wheelset of mass `mass` [kg] whose wheels carry
/// `wheel_load` [N] each, by Newton's method on (dy, yaw, spin) with a finite-difference
/// Jacobian and a halving line search on the scaled residual. Converged when the lateral
/// balance is within 1e-7 of the wheel load, the yaw moment within 1e-7 of the load times the
/// lateral arm, and the axle torque within 1e-6 of the sum of |Fx| r (at least 1e-9 of the load
/// times the nominal radius).
FreeWheelsetCurving solve_free_wheelset_curving(const WheelsetModel& model, double mass,
                                                double wheel_load, const SteadyCurve& curve);

}  // namespace wheelwear::vehicle
