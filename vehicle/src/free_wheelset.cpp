#include "wheelwear/vehicle/free_wheelset.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/route.hpp"

namespace wheelwear::vehicle {

double SteadyCurve::cant_angle() const {
  return std::asin(cant / cant_base);
}

double SteadyCurve::centripetal_force(double mass) const {
  if (running.curve_radius == 0.0) return 0.0;
  const double phi = cant_angle();
  return mass * (running.speed * running.speed / std::abs(running.curve_radius) * std::cos(phi) -
                 kGravity * std::sin(phi));
}

double SteadyCurve::normal_force(double mass) const {
  const double phi = cant_angle();
  const double centrifugal = running.curve_radius == 0.0
                                 ? 0.0
                                 : running.speed * running.speed / std::abs(running.curve_radius);
  return mass * (kGravity * std::cos(phi) + centrifugal * std::sin(phi));
}

double SteadyCurve::cant_deficiency() const {
  if (running.curve_radius == 0.0) return 0.0;
  return vehicle::cant_deficiency(running.speed, 1.0 / running.curve_radius, cant, cant_base);
}

void SteadyCurve::validate() const {
  require(std::isfinite(cant_base) && cant_base > 0.5 && cant_base < 3.0, "cant base", cant_base,
          "must lie in 0.5 ... 3 m");
  require(std::isfinite(cant) && cant >= 0.0 && cant <= 0.25 * cant_base, "cant", cant,
          "the outer rail's height above the inner must lie in 0 ... cant_base / 4 (m)");
  require(running.curve_radius != 0.0 || cant == 0.0, "cant", cant,
          "tangent track (curve radius 0) has no cant");
  require(std::isfinite(traction) && std::abs(traction) <= 5e5, "traction", traction,
          "the longitudinal force per powered axle must lie in [-5e5, 5e5] N");
}

namespace {

struct Residual {
  Eigen::Vector3d r;  // lateral [N], yaw moment [N m], axle torque [N m]
  WheelsetForces forces;
};

}  // namespace

FreeWheelsetCurving solve_free_wheelset_curving(const WheelsetModel& model, double mass,
                                                double wheel_load, const SteadyCurve& curve) {
  curve.validate();
  require(std::isfinite(mass) && mass > 0.0, "mass", mass, "must be positive (kg)");
  require(std::isfinite(wheel_load) && wheel_load > 0.0, "wheel load", wheel_load,
          "must be positive (N)");
  const RunningConditions& running = curve.running;
  const double r0 = model.track.left.wheel_radius;
  // Towards the curve centre is -y for a right-hand curve (R > 0).
  const double inward =
      running.curve_radius > 0.0 ? -1.0 : (running.curve_radius < 0.0 ? 1.0 : 0.0);
  const double required = inward * curve.centripetal_force(mass);

  const auto evaluate = [&](const WheelsetMotionState& s) {
    Residual out;
    out.forces = wheelset_forces(model, s, wheel_load, wheel_load, running);
    out.r << out.forces.lateral - required, out.forces.yaw_moment,
        out.forces.axle_torque - drive_torque(model, curve.traction);
    return out;
  };
  // Residuals in units of their tolerances: one is converged.
  const auto scaled = [&](const Residual& res) {
    double torque_scale = 1e-9 * wheel_load * r0;
    for (const WheelForces& w : res.forces.wheels)
      for (const PatchForces& p : w.patches)
        torque_scale += 1e-6 * std::abs(p.Fx) * p.rolling_radius;
    return Eigen::Vector3d(res.r[0] / (1e-7 * wheel_load),
                           res.r[1] / (1e-7 * wheel_load * model.lateral_arm),
                           res.r[2] / torque_scale);
  };

  FreeWheelsetCurving result;
  WheelsetMotionState s;
  s.spin = running.speed / r0;
  Residual res = evaluate(s);
  const Eigen::Vector3d steps(1e-7, 1e-8, 1e-7 * s.spin);
  for (; result.iterations < 40; ++result.iterations) {
    const Eigen::Vector3d size = scaled(res);
    if (size.cwiseAbs().maxCoeff() <= 1.0 && res.forces.loads_met) {
      result.converged = true;
      break;
    }
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) {
      WheelsetMotionState t = s;
      if (k == 0) t.dy += steps[0];
      if (k == 1) t.yaw += steps[1];
      if (k == 2) t.spin += steps[2];
      J.col(k) = (evaluate(t).r - res.r) / steps[k];
    }
    const Eigen::Vector3d delta = J.fullPivLu().solve(-res.r);
    // Halve the step until the scaled residual falls (the contact is only piecewise smooth).
    double factor = 1.0;
    bool taken = false;
    for (int halving = 0; halving < 12; ++halving, factor *= 0.5) {
      WheelsetMotionState t = s;
      t.dy += factor * delta[0];
      t.yaw += factor * delta[1];
      t.spin += factor * delta[2];
      if (!(t.spin > 0.0)) continue;
      Residual trial = evaluate(t);
      if (scaled(trial).norm() < size.norm()) {
        s = t;
        res = std::move(trial);
        taken = true;
        break;
      }
    }
    if (!taken) {
      result.message = "the line search found no smaller residual";
      break;
    }
  }
  if (!result.converged && result.message.empty())
    result.message = "no convergence in 40 Newton iterations";
  result.state = s;
  result.forces = std::move(res.forces);
  result.lateral_residual = res.r[0];
  result.yaw_residual = res.r[1];
  result.torque_residual = res.r[2];
  return result;
}

}  // namespace wheelwear::vehicle
