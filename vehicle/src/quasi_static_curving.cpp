#include "wheelwear/vehicle/quasi_static_curving.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

namespace {

// The unknowns: car body (y, yaw), bogies (y, yaw) each, wheelsets (dy, yaw, spin) each.
constexpr int kBodyUnknowns = 2 + 2 * kBogies;
constexpr int kUnknowns = kBodyUnknowns + 3 * kWheelsets;
using Vector = Eigen::Matrix<double, kUnknowns, 1>;
using Matrix = Eigen::Matrix<double, kUnknowns, kUnknowns>;

constexpr int bogie_index(int i) {
  return 2 + 2 * i;
}
constexpr int wheelset_index(int k) {
  return kBodyUnknowns + 3 * k;
}

// +1 when the outside of the curve is +y (a right-hand curve, R > 0), -1 for a left-hand one.
double outward(const SteadyCurve& curve) {
  const double r = curve.running.curve_radius;
  return r > 0.0 ? 1.0 : (r < 0.0 ? -1.0 : 0.0);
}

// The in-plane force that gravity and the centrifugal force put on a body of mass m [N], + y.
double applied_force(const SteadyCurve& curve, double mass) {
  return outward(curve) * curve.centripetal_force(mass);
}

// A suspension joint's relative displacement and yaw of a child body at distance d ahead of its
// parent, in the parent's frame (see the header).
struct JointDeflection {
  double lateral = 0.0;
  double yaw = 0.0;
};

JointDeflection deflection(double curvature, double d, const BodyPlacement& parent, double child_y,
                           double child_yaw) {
  return {child_y - 0.5 * curvature * d * d - parent.y - parent.yaw * d,
          child_yaw - curvature * d - parent.yaw};
}

struct Placement {
  BodyPlacement car_body;
  std::array<BodyPlacement, kBogies> bogies;
  std::array<WheelsetMotionState, kWheelsets> wheelsets;
};

Placement placement(const Vector& u) {
  Placement p;
  p.car_body = {u[0], u[1]};
  for (int i = 0; i < kBogies; ++i) p.bogies[i] = {u[bogie_index(i)], u[bogie_index(i) + 1]};
  for (int k = 0; k < kWheelsets; ++k) {
    WheelsetMotionState& s = p.wheelsets[k];
    s.dy = u[wheelset_index(k)];
    s.yaw = u[wheelset_index(k) + 1];
    s.spin = u[wheelset_index(k) + 2];
  }
  return p;
}

// The suspension's and the curve's share of every residual (no contact): body balances, and for
// the wheelsets the primary joints' forces plus the applied force.
struct SuspensionPart {
  Vector residual = Vector::Zero();
  std::array<double, kWheelsets> lateral{}, yaw{};  // primary joint on each wheelset
};

SuspensionPart suspension_part(const Vehicle& v, const SteadyCurve& curve, const Vector& u) {
  const Placement p = placement(u);
  const double curvature =
      curve.running.curve_radius == 0.0 ? 0.0 : 1.0 / curve.running.curve_radius;
  SuspensionPart out;
  Vector& r = out.residual;
  r[0] += applied_force(curve, v.car_body.mass);
  for (int i = 0; i < kBogies; ++i) {
    const int b = bogie_index(i);
    const double d = v.bogie_x(i);
    const JointDeflection j = deflection(curvature, d, p.car_body, p.bogies[i].y, p.bogies[i].yaw);
    const double force = -(v.secondary.joint_lateral_stiffness() * j.lateral +
                           v.lateral_stop.force_at(j.lateral));  // on the bogie
    const double moment = -v.secondary.joint_yaw_stiffness() * j.yaw;
    r[b] += force + applied_force(curve, v.bogie.mass);
    r[b + 1] += moment;
    r[0] -= force;
    r[1] -= moment + d * force;
  }
  for (int k = 0; k < kWheelsets; ++k) {
    const int i = k / 2, b = bogie_index(i), w = wheelset_index(k);
    const double d = v.wheelset_x(k) - v.bogie_x(i);
    const JointDeflection j =
        deflection(curvature, d, p.bogies[i], p.wheelsets[k].dy, p.wheelsets[k].yaw);
    const double force = -v.primary.joint_lateral_stiffness() * j.lateral;  // on the wheelset
    const double moment = -v.primary.joint_yaw_stiffness() * j.yaw;
    out.lateral[k] = force;
    out.yaw[k] = moment;
    r[w] += force + applied_force(curve, v.wheelset.body.mass);
    r[w + 1] += moment;
    r[b] -= force;
    r[b + 1] -= moment + d * force;
  }
  return out;
}

struct Evaluation {
  Vector residual = Vector::Zero();
  std::array<CurvingWheelset, kWheelsets> wheelsets;
};

// The largest step Newton takes at once: the linearisation at a tread contact knows nothing of
// the flange a millimetre away, and the soft secondary suspension turns a small force into a
// large shift. Returns the factor (<= 1) that brings `delta` within the limits.
double step_limit(const Vector& delta) {
  double ratio = 1.0;
  const auto limit = [&](double step, double largest) {
    ratio = std::max(ratio, std::abs(step) / largest);
  };
  limit(delta[0], 10e-3);
  limit(delta[1], 2e-3);
  for (int i = 0; i < kBogies; ++i) {
    limit(delta[bogie_index(i)], 5e-3);
    limit(delta[bogie_index(i) + 1], 2e-3);
  }
  for (int k = 0; k < kWheelsets; ++k) {
    limit(delta[wheelset_index(k)], 1e-3);
    limit(delta[wheelset_index(k) + 1], 1e-3);
  }
  return 1.0 / ratio;
}

class CurvingProblem {
 public:
  CurvingProblem(const Vehicle& vehicle, const std::array<WheelsetModel, kWheelsets>& models,
                 const SteadyCurve& curve, const CurvingOptions& options, int& evaluations)
      : v_(vehicle), models_(models), curve_(curve), options_(options), evaluations_(evaluations) {}

  // The rails' forces on wheelset k at `state` with the given loads.
  // `roll`: the roll at the same dy and yaw, when known.
  WheelsetForces contact(int k, const WheelsetMotionState& state, double left, double right,
                         std::optional<contactgeom::KnownRoll> roll = std::nullopt) const {
    ++evaluations_;
    return wheelset_forces(models_[k], state, left, right, curve_.running, roll);
  }

  Evaluation evaluate(const Vector& u) const {
    Evaluation e;
    const SuspensionPart s = suspension_part(v_, curve_, u);
    e.residual = s.residual;
    const Placement p = placement(u);
    for (int k = 0; k < kWheelsets; ++k) {
      CurvingWheelset& ws = e.wheelsets[k];
      ws.x = v_.wheelset_x(k);
      ws.state = p.wheelsets[k];
      const auto loads = wheel_loads(v_, curve_, models_[k].lateral_arm, p.car_body.y,
                                     p.bogies[k / 2].y, p.wheelsets[k].dy);
      ws.load_left = loads[0];
      ws.load_right = loads[1];
      ws.forces = contact(k, ws.state, loads[0], loads[1]);
      ws.suspension_lateral = s.lateral[k];
      ws.suspension_yaw = s.yaw[k];
      const int w = wheelset_index(k);
      e.residual[w] += ws.forces.lateral;
      e.residual[w + 1] += ws.forces.yaw_moment;
      // A powered axle's contact torque carries its drive (or brake) torque.
      const double drive = v_.powered[k] ? drive_torque(models_[k], curve_.traction) : 0.0;
      e.residual[w + 2] = ws.forces.axle_torque - drive;
      ws.balance = {e.residual[w], e.residual[w + 1]};
    }
    return e;
  }

  // The Jacobian: the suspension's exactly (finite differences of a linear or piecewise-linear
  // map); the contact's per wheelset in its own unknowns, and through its wheels' loads in the
  // lateral shifts of the bodies that load it (wheel_loads is linear in them).
  Matrix jacobian(const Vector& u, const Evaluation& at) const {
    Matrix J = Matrix::Zero();
    const Vector base = suspension_part(v_, curve_, u).residual;
    for (int c = 0; c < kUnknowns; ++c) {
      const double h = c >= kBodyUnknowns && (c - kBodyUnknowns) % 3 == 2 ? 1e-6 : 1e-7;
      Vector t = u;
      t[c] += h;
      J.col(c) = (suspension_part(v_, curve_, t).residual - base) / h;
    }
    const Placement p = placement(u);
    for (int k = 0; k < kWheelsets; ++k) {
      const int w = wheelset_index(k);
      const CurvingWheelset& ws = at.wheelsets[k];
      const auto forces_vector = [](const WheelsetForces& f) {
        return Eigen::Vector3d(f.lateral, f.yaw_moment, f.axle_torque);
      };
      const Eigen::Vector3d f0 = forces_vector(ws.forces);
      const std::optional<contactgeom::KnownRoll> known = ws.forces.contact.known_roll;
      const Eigen::Vector3d steps(1e-7, 1e-8, 1e-7 * ws.state.spin);
      for (int c = 0; c < 3; ++c) {
        WheelsetMotionState t = ws.state;
        if (c == 0) t.dy += steps[0];
        if (c == 1) t.yaw += steps[1];
        if (c == 2) t.spin += steps[2];
        // The spin leaves the wheelset where it is: its roll is the evaluation's.
        const auto roll = c == 2 ? known : std::nullopt;
        J.block<3, 1>(w, w + c) +=
            (forces_vector(contact(k, t, ws.load_left, ws.load_right, roll)) - f0) / steps[c];
      }
      // d(forces)/d(load) per wheel, and d(load)/d(shift) of the car body, bogie and wheelset.
      const double dQ = 1e-6 * std::max(ws.load_left, ws.load_right);
      const Eigen::Vector3d by_left =
          (forces_vector(contact(k, ws.state, ws.load_left + dQ, ws.load_right, known)) - f0) / dQ;
      const Eigen::Vector3d by_right =
          (forces_vector(contact(k, ws.state, ws.load_left, ws.load_right + dQ, known)) - f0) / dQ;
      // The unknowns of the car body's, the bogie's and the wheelset's shift, in wheel_loads'
      // order of arguments.
      const std::array<int, 3> shifts{0, bogie_index(k / 2), w};
      for (int j = 0; j < 3; ++j) {
        std::array<double, 3> y{p.car_body.y, p.bogies[k / 2].y, p.wheelsets[k].dy};
        const double h = 1e-4;
        y[j] += h;
        const int column = shifts[j];
        const auto moved = wheel_loads(v_, curve_, models_[k].lateral_arm, y[0], y[1], y[2]);
        J.block<3, 1>(w, column) +=
            by_left * (moved[0] - ws.load_left) / h + by_right * (moved[1] - ws.load_right) / h;
      }
    }
    return J;
  }

  // The residuals in units of their tolerances: within 1 everywhere is converged.
  Vector scaled(const Evaluation& e) const {
    Vector s;
    const double tol = options_.force_tolerance * kGravity;
    s[0] = e.residual[0] / (tol * v_.car_body.mass);
    s[1] = e.residual[1] / (tol * v_.car_body.mass);
    for (int i = 0; i < kBogies; ++i) {
      s[bogie_index(i)] = e.residual[bogie_index(i)] / (tol * v_.bogie.mass);
      s[bogie_index(i) + 1] = e.residual[bogie_index(i) + 1] / (tol * v_.bogie.mass);
    }
    for (int k = 0; k < kWheelsets; ++k) {
      const int w = wheelset_index(k);
      const CurvingWheelset& ws = e.wheelsets[k];
      double torque_scale = 1e-9 * std::max(ws.load_left, ws.load_right) * v_.wheelset.wheel_radius;
      for (const WheelForces& wheel : ws.forces.wheels)
        for (const PatchForces& patch : wheel.patches)
          torque_scale += 1e-7 * std::abs(patch.Fx) * patch.rolling_radius;
      s[w] = e.residual[w] / (tol * v_.wheelset.body.mass);
      s[w + 1] = e.residual[w + 1] / (tol * v_.wheelset.body.mass);
      s[w + 2] = e.residual[w + 2] / torque_scale;
    }
    return s;
  }

  bool loads_met(const Evaluation& e) const {
    return std::all_of(e.wheelsets.begin(), e.wheelsets.end(),
                       [](const CurvingWheelset& w) { return w.forces.loads_met; });
  }

  // A wheel whose contact has passed its flank's steepest point has derailed: a balance there
  // (the rail pushing the wheel on over its flange) is no state of the vehicle in the curve.
  static bool derailed(const Evaluation& e) {
    return std::any_of(e.wheelsets.begin(), e.wheelsets.end(), [](const CurvingWheelset& w) {
      return std::any_of(w.forces.wheels.begin(), w.forces.wheels.end(), [](const WheelForces& f) {
        return f.status == contactgeom::WheelRailStatus::past_flange;
      });
    });
  }

  // Newton from `u`; true when converged. `u` and `e` hold the last iterate.
  bool solve(Vector& u, Evaluation& e, int& iterations, std::string& message) const {
    e = evaluate(u);
    for (int it = 0; it < options_.max_iterations; ++it) {
      const Vector size = scaled(e);
      if (size.cwiseAbs().maxCoeff() <= 1.0 && loads_met(e) && !derailed(e)) return true;
      ++iterations;
      const Matrix Jm = jacobian(u, e);
      Vector delta = Jm.fullPivLu().solve(-e.residual);
      delta *= step_limit(delta);
      // Halve the step until the scaled residual falls (the contact is only piecewise smooth:
      // a second patch appears, the flange takes over).
      const auto try_step = [&](const Vector& step) {
        const Vector t = u + step;
        for (int k = 0; k < kWheelsets; ++k)
          if (!(t[wheelset_index(k) + 2] > 0.0)) return false;
        Evaluation trial;
        try {
          trial = evaluate(t);
        } catch (const InputError&) {
          return false;  // a shift beyond the profiles: a shorter step
        }
        if (!(scaled(trial).norm() < size.norm()) || (derailed(trial) && !derailed(e)))
          return false;
        u = t;
        e = std::move(trial);
        return true;
      };
      bool taken = false;
      double factor = 1.0;
      for (int halving = 0; halving < 8 && !taken; ++halving, factor *= 0.5)
        taken = try_step(factor * delta);
      // Where Newton's direction does not descend (at a kink of the contact forces, where a
      // patch appears), Levenberg-Marquardt steps on the scaled residual, growing the damping.
      if (!taken) {
        const Vector d = size.cwiseQuotient(e.residual).unaryExpr([](double x) {
          return std::isfinite(x) ? x : 0.0;
        });
        const Matrix A = d.asDiagonal() * Jm;
        const Matrix normal = A.transpose() * A;
        const Vector gradient = A.transpose() * size;
        for (double lambda = 1e-6; lambda <= 1e6 && !taken; lambda *= 10.0) {
          Matrix damped = normal;
          damped.diagonal() += lambda * normal.diagonal().cwiseMax(1e-300);
          Vector step = damped.ldlt().solve(-gradient);
          step *= step_limit(step);
          taken = try_step(step);
        }
      }
      if (!taken) {
        message = "the line search found no smaller residual (largest scaled residual " +
                  std::to_string(size.cwiseAbs().maxCoeff()) + ")";
        return false;
      }
    }
    message = "no convergence in " + std::to_string(options_.max_iterations) + " Newton iterations";
    return false;
  }

 private:
  const Vehicle& v_;
  const std::array<WheelsetModel, kWheelsets>& models_;
  SteadyCurve curve_;
  CurvingOptions options_;
  int& evaluations_;
};

Vector unknowns(const VehiclePlacement& p) {
  Vector u;
  u[0] = p.car_body.y;
  u[1] = p.car_body.yaw;
  for (int i = 0; i < kBogies; ++i) {
    u[bogie_index(i)] = p.bogies[i].y;
    u[bogie_index(i) + 1] = p.bogies[i].yaw;
  }
  for (int k = 0; k < kWheelsets; ++k) {
    u[wheelset_index(k)] = p.wheelsets[k].dy;
    u[wheelset_index(k) + 1] = p.wheelsets[k].yaw;
    u[wheelset_index(k) + 2] = p.wheelsets[k].spin;
  }
  return u;
}

// The start: every body centred and radial, each axle at the spin of its nominal radius.
Vector initial_guess(const Vehicle& v, const SteadyCurve& curve) {
  Vector u = Vector::Zero();
  for (int k = 0; k < kWheelsets; ++k)
    u[wheelset_index(k) + 2] = curve.running.speed / v.wheelset.wheel_radius;
  return u;
}

// The curve scaled towards tangent track by `share` of its curvature and cant.
SteadyCurve partial_curve(const SteadyCurve& curve, double share) {
  SteadyCurve c = curve;
  if (curve.running.curve_radius != 0.0)
    c.running.curve_radius = curve.running.curve_radius / share;
  c.cant = curve.cant * share;
  return c;
}

}  // namespace

std::array<double, 2> wheel_loads(const Vehicle& v, const SteadyCurve& curve, double lateral_arm,
                                  double car_body_y, double bogie_y, double wheelset_y) {
  struct Share {
    double mass, height, y;
  };
  const std::array<Share, 3> shares{
      Share{v.car_body.mass / kWheelsets, v.car_body.cg_height, car_body_y},
      Share{v.bogie.mass / 2.0, v.bogie.cg_height, bogie_y},
      Share{v.wheelset.body.mass, v.wheelset.body.cg_height, wheelset_y}};
  double weight = 0.0, moment = 0.0;  // e (Q_left - Q_right) = moment
  for (const Share& s : shares) {
    const double w = curve.normal_force(s.mass);
    weight += w;
    moment += w * s.y + s.height * applied_force(curve, s.mass);
  }
  const double difference = moment / lateral_arm;
  return {0.5 * (weight + difference), 0.5 * (weight - difference)};
}

void require_upright(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm) {
  // The centred vehicle's wheel loads: where the curve's unbalanced lateral acceleration tips a
  // wheel off its rail, no balance exists (and a load below zero is no contact to solve).
  const auto loads = wheel_loads(vehicle, curve, lateral_arm, 0.0, 0.0, 0.0);
  const double least = std::min(loads[0], loads[1]);
  if (least > 0.0) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the vehicle overturns in this curve: at R %g m, cant %g m and %g m/s (cant "
                "deficiency %.3f m) its %s wheels carry %.1f kN even with every body centred; "
                "lower the speed or raise the cant",
                curve.running.curve_radius, curve.cant, curve.running.speed,
                curve.cant_deficiency(), loads[0] < loads[1] ? "left" : "right", least * 1e-3);
  throw InputError(text);
}

void require_adhesion(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm) {
  if (curve.traction == 0.0) return;
  // Every wheelset of the centred vehicle carries the same loads.
  const auto loads = wheel_loads(vehicle, curve, lateral_arm, 0.0, 0.0, 0.0);
  for (int k = 0; k < kWheelsets; ++k) {
    // A powered axle carries its traction or braking through the creep forces, at most
    // mu (Q_left + Q_right): beyond it the wheels slip or slide and no balance exists.
    if (!vehicle.powered[static_cast<std::size_t>(k)]) continue;
    const double adhesion = curve.running.friction * (loads[0] + loads[1]);
    if (std::abs(curve.traction) < adhesion) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s of %.1f kN per powered axle is beyond the adhesion of wheelset %d, "
                  "friction %g times its %.1f kN of wheel load = %.1f kN: its wheels %s; "
                  "give at most that",
                  curve.traction > 0.0 ? "traction" : "braking", std::abs(curve.traction) * 1e-3,
                  k + 1, curve.running.friction, (loads[0] + loads[1]) * 1e-3, adhesion * 1e-3,
                  curve.traction > 0.0 ? "would slip" : "would slide");
    throw InputError(text);
  }
}

VehiclePlacement placement_of(const VehicleCurving& curving) {
  VehiclePlacement p;
  p.car_body = curving.car_body;
  p.bogies = curving.bogies;
  for (int k = 0; k < kWheelsets; ++k) p.wheelsets[k] = curving.wheelsets[k].state;
  return p;
}

VehicleCurving solve_vehicle_curving(const Vehicle& vehicle,
                                     const std::array<WheelsetModel, kWheelsets>& wheelsets,
                                     const SteadyCurve& curve, const CurvingOptions& options) {
  vehicle.validate();
  curve.validate();
  require(options.max_iterations > 0, "max iterations", options.max_iterations, "must be positive");
  require(std::isfinite(options.force_tolerance) && options.force_tolerance > 0.0,
          "force tolerance", options.force_tolerance, "must be positive");

  for (int k = 0; k < kWheelsets; ++k) {
    require_upright(vehicle, curve, wheelsets[k].lateral_arm);
    require_adhesion(vehicle, curve, wheelsets[k].lateral_arm);
  }
  VehicleCurving result;
  result.cant_deficiency = curve.cant_deficiency();
  Vector u = initial_guess(vehicle, curve);
  Evaluation e;
  bool converged = false;
  std::string message;
  // The tabulated contact (WheelsetModel::table) is linear between its nodes, and Newton can
  // stall at their kinks short of the tolerance, or at a jump of a worn tread's geometry that
  // the direct contacts pass. The attempt at the whole curve that came nearest is remembered.
  std::optional<Vector> nearest;
  double nearest_residual = std::numeric_limits<double>::infinity();
  bool nearest_from_start = false;
  const auto remember = [&](const CurvingProblem& problem, bool from_start) {
    const double residual = problem.scaled(e).norm();
    if (residual < nearest_residual) {
      nearest_residual = residual;
      nearest = u;
      nearest_from_start = from_start;
    }
  };
  const bool tabulated = std::any_of(wheelsets.begin(), wheelsets.end(),
                                     [](const WheelsetModel& m) { return m.table != nullptr; });
  // The models without their tables, copied only where needed (they hold the profiles).
  std::optional<std::array<WheelsetModel, kWheelsets>> untabulated;
  const auto direct = [&]() -> const std::array<WheelsetModel, kWheelsets>& {
    if (!untabulated) {
      untabulated = wheelsets;
      for (WheelsetModel& m : *untabulated) m.table.reset();
    }
    return *untabulated;
  };
  // Newton from the nearest failed attempt, on the direct contacts, where it came near: the
  // stalls at a table's kink end at scaled residual norms of 1.4 to 2e4 (new S1002/60E1, the
  // built-in route's R 1500 m); attempts that went astray on a worn tread end at 1e5 to 1e8 and
  // are better restarted.
  constexpr double kNearEnough = 1e5;
  const auto finish_directly = [&] {
    if (!nearest || nearest_residual > kNearEnough) return false;
    Vector v = *nearest;
    Evaluation f;
    std::string why;
    const CurvingProblem problem(vehicle, direct(), curve, options, result.wheelset_evaluations);
    try {
      if (!problem.solve(v, f, result.iterations, why)) {
        message += "; finished with direct contacts: " + why;
        return false;
      }
    } catch (const InputError& error) {
      message += std::string("; finished with direct contacts: ") + error.what();
      return false;
    }
    u = v;
    e = std::move(f);
    return true;
  };
  // Straight to the curve first; where that fails (a flange contact Newton overshoots), in
  // steps of curvature and cant from tangent track, each from the last one's state.
  const auto continuation = [&](const std::array<WheelsetModel, kWheelsets>& models,
                                std::initializer_list<int> attempts) {
    for (int steps : attempts) {
      u = initial_guess(vehicle, curve);
      bool reached = true;
      for (int s = 1; s <= steps && reached; ++s) {
        const CurvingProblem problem(vehicle, models, partial_curve(curve, double(s) / steps),
                                     options, result.wheelset_evaluations);
        std::string why;
        reached = problem.solve(u, e, result.iterations, why);
        if (!reached) message = why;
        if (!reached && s == steps) remember(problem, false);
      }
      result.continuation_steps = steps;
      if (reached) return true;
    }
    return false;
  };
  bool started = false;  // Newton ran from options.start
  if (options.start) {
    u = unknowns(*options.start);
    bool valid = u.allFinite();
    for (int k = 0; k < kWheelsets; ++k) valid = valid && u[wheelset_index(k) + 2] > 0.0;
    if (valid) {
      const CurvingProblem problem(vehicle, wheelsets, curve, options, result.wheelset_evaluations);
      try {
        converged = problem.solve(u, e, result.iterations, message);
        started = true;
        if (!converged) remember(problem, true);
      } catch (const InputError&) {
        converged = false;  // the start lies beyond the profiles now: start afresh
      }
      result.from_start = converged;
    }
  }
  // A start that could not be used (not finite, no spin, beyond the profiles) is no attempt:
  // the solve starts afresh whatever restart_on_failure says.
  const bool fresh = !options.start || options.restart_on_failure || !started;
  // On a table only the straight attempt: its continuation rarely reaches what the direct
  // contacts do not (measured on worn profiles it cost as much as their whole solve).
  if (!converged && fresh)
    converged = tabulated ? continuation(wheelsets, {1}) : continuation(wheelsets, {1, 4, 16});
  // On a table: from the nearest failed attempt with direct contacts, then (a fresh solve)
  // afresh with them, where the table's kinks led every attempt astray.
  if (!converged && tabulated) {
    converged = finish_directly();
    result.from_start = converged && nearest_from_start;
    if (!converged && fresh) {
      const std::string table_message = message;
      converged = continuation(direct(), {1, 4, 16});
      if (!converged) message = table_message + "; afresh with direct contacts: " + message;
    }
    result.finished_directly = converged;
  }
  result.converged = converged;
  if (!converged) result.message = message;
  const Placement p = placement(u);
  result.car_body = p.car_body;
  result.bogies = p.bogies;
  result.body_balances[0] = {e.residual[0], e.residual[1]};
  for (int i = 0; i < kBogies; ++i)
    result.body_balances[1 + i] = {e.residual[bogie_index(i)], e.residual[bogie_index(i) + 1]};
  result.wheelsets = std::move(e.wheelsets);
  return result;
}

}  // namespace wheelwear::vehicle
