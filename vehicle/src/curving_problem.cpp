#include "curving_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle::detail {

namespace {

// The curve's curvature [1/m], + right-hand; 0 on tangent track.
double curvature_of(const SteadyCurve& curve) {
  return curve.running.curve_radius == 0.0 ? 0.0 : 1.0 / curve.running.curve_radius;
}

// +1 when the outside of the curve is +y (a right-hand curve, R > 0), -1 for a left-hand one.
double outward(const SteadyCurve& curve) {
  const double r = curve.running.curve_radius;
  return r > 0.0 ? 1.0 : (r < 0.0 ? -1.0 : 0.0);
}

// A suspension joint's relative displacement and yaw of a child body at distance d ahead of its
// parent, in the parent's frame (see quasi_static_curving.hpp).
struct JointDeflection {
  double lateral = 0.0;
  double yaw = 0.0;
};

JointDeflection deflection(double curvature, double d, const BodyPlacement& parent, double child_y,
                           double child_yaw) {
  return {child_y - 0.5 * curvature * d * d - parent.y - parent.yaw * d,
          child_yaw - curvature * d - parent.yaw};
}

// The suspension's and the curve's share of every residual (no contact): body balances, and for
// the wheelsets the primary joints' forces plus the applied force.
struct SuspensionPart {
  Vector residual = Vector::Zero();
  std::array<double, kWheelsets> lateral{}, yaw{};  // primary joint on each wheelset
};

SuspensionPart suspension_part(const Vehicle& v, const SteadyCurve& curve, const Vector& u) {
  const Placement p = placement(u);
  const double curvature = curvature_of(curve);
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

// The mean of the wheelset's two wheels' nominal radii (they differ where each wheel has its
// own profile) [m].
double nominal_radius(const WheelsetModel& model) {
  return 0.5 * (model.track.left.wheel_radius + model.track.right.wheel_radius);
}

}  // namespace

double applied_force(const SteadyCurve& curve, double mass) {
  return outward(curve) * curve.centripetal_force(mass);
}

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

Vector initial_guess(const std::array<WheelsetModel, kWheelsets>& models,
                     const SteadyCurve& curve) {
  Vector u = Vector::Zero();
  for (int k = 0; k < kWheelsets; ++k)
    u[wheelset_index(k) + 2] = curve.running.speed / nominal_radius(models[k]);
  return u;
}

SteadyCurve partial_curve(const SteadyCurve& curve, double share) {
  SteadyCurve c = curve;
  if (curve.running.curve_radius != 0.0)
    c.running.curve_radius = curve.running.curve_radius / share;
  c.cant = curve.cant * share;
  return c;
}

std::array<double, 2> CurvingProblem::loads(int k, const Vector& u) const {
  const Placement p = placement(u);
  const int i = k / 2;
  // The car body's weight reaches the bogie at its pivot, where the secondary suspension carries
  // it: the body's shift there, against the track there (in a curve the body's centre lies
  // inside the track by the versine, kappa d^2 / 2, while its pivots follow the bogies).
  const double curvature = curvature_of(curve_);
  const double d = v_.bogie_x(i);
  const double over_pivot = p.car_body.y + p.car_body.yaw * d + 0.5 * curvature * d * d;
  return wheel_loads(v_, curve_, models_[k].lateral_arm, over_pivot, p.bogies[i].y,
                     p.wheelsets[k].dy);
}

Evaluation CurvingProblem::evaluate(const Vector& u) const {
  Evaluation e;
  const SuspensionPart s = suspension_part(v_, curve_, u);
  e.residual = s.residual;
  const Placement p = placement(u);
  for (int k = 0; k < kWheelsets; ++k) {
    CurvingWheelset& ws = e.wheelsets[k];
    ws.x = v_.wheelset_x(k);
    ws.state = p.wheelsets[k];
    const auto wheel = loads(k, u);
    ws.load_left = wheel[0];
    ws.load_right = wheel[1];
    ws.forces = contact(k, ws.state, wheel[0], wheel[1]);
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

Matrix CurvingProblem::jacobian(const Vector& u, const Evaluation& at) const {
  Matrix J = Matrix::Zero();
  const Vector base = suspension_part(v_, curve_, u).residual;
  for (int c = 0; c < kUnknowns; ++c) {
    const double h = c >= kBodyUnknowns && (c - kBodyUnknowns) % 3 == 2 ? 1e-6 : 1e-7;
    Vector t = u;
    t[c] += h;
    J.col(c) = (suspension_part(v_, curve_, t).residual - base) / h;
  }
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
    // d(forces)/d(load) per wheel, and d(load)/d(unknown) of the car body's shift and yaw, the
    // bogie's shift and the wheelset's shift.
    const double dQ = 1e-6 * std::max(ws.load_left, ws.load_right);
    const Eigen::Vector3d by_left =
        (forces_vector(contact(k, ws.state, ws.load_left + dQ, ws.load_right, known)) - f0) / dQ;
    const Eigen::Vector3d by_right =
        (forces_vector(contact(k, ws.state, ws.load_left, ws.load_right + dQ, known)) - f0) / dQ;
    for (int column : {0, 1, bogie_index(k / 2), w}) {
      // loads() is linear in these: any step is exact.
      const double h = 1e-4;
      Vector moved_u = u;
      moved_u[column] += h;
      const auto moved = loads(k, moved_u);
      J.block<3, 1>(w, column) +=
          by_left * (moved[0] - ws.load_left) / h + by_right * (moved[1] - ws.load_right) / h;
    }
  }
  return J;
}

Vector CurvingProblem::scaled(const Evaluation& e) const {
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
    double torque_scale = 1e-9 * std::max(ws.load_left, ws.load_right) * nominal_radius(models_[k]);
    for (const WheelForces& wheel : ws.forces.wheels)
      for (const PatchForces& patch : wheel.patches)
        torque_scale += 1e-7 * std::abs(patch.Fx) * patch.rolling_radius;
    s[w] = e.residual[w] / (tol * v_.wheelset.body.mass);
    s[w + 1] = e.residual[w + 1] / (tol * v_.wheelset.body.mass);
    s[w + 2] = e.residual[w + 2] / torque_scale;
  }
  return s;
}

bool CurvingProblem::loads_met(const Evaluation& e) const {
  return std::all_of(e.wheelsets.begin(), e.wheelsets.end(),
                     [](const CurvingWheelset& w) { return w.forces.loads_met; });
}

bool CurvingProblem::derailed(const Evaluation& e) {
  return std::any_of(e.wheelsets.begin(), e.wheelsets.end(), [](const CurvingWheelset& w) {
    return std::any_of(w.forces.wheels.begin(), w.forces.wheels.end(), [](const WheelForces& f) {
      return f.status == contactgeom::WheelRailStatus::past_flange;
    });
  });
}

namespace {

// The balance that equation `i` of the residual states, for messages.
std::string equation_name(int i) {
  static constexpr std::array<const char*, 3> kWheelset{"lateral force", "yaw moment",
                                                        "axle torque"};
  if (i < 2) return std::string("car body ") + (i == 0 ? "lateral force" : "yaw moment");
  if (i < kBodyUnknowns)
    return "bogie " + std::to_string((i - 2) / 2 + 1) +
           ((i - 2) % 2 == 0 ? " lateral force" : " yaw moment");
  const int k = (i - kBodyUnknowns) / 3;
  return "wheelset " + std::to_string(k + 1) + " " + kWheelset[(i - kBodyUnknowns) % 3];
}

// "largest scaled residual 3.2, wheelset 1 axle torque": how far from the tolerance (1) the
// iterate stopped, and where.
std::string largest_residual(const Vector& scaled) {
  int at = 0;
  const double largest = scaled.cwiseAbs().maxCoeff(&at);
  char number[32];
  std::snprintf(number, sizeof number, "%.2g", largest);
  return std::string("largest scaled residual ") + number + ", " + equation_name(at);
}

}  // namespace

std::string CurvingProblem::shortfall(const Vector& scaled, const Evaluation& e) const {
  if (scaled.cwiseAbs().maxCoeff() <= 1.0) {
    if (derailed(e)) return "balanced, but a wheel's contact lies past its flange's steepest point";
    if (!loads_met(e)) return "balanced, but a wheel's contact does not carry its load";
  }
  return largest_residual(scaled);
}

bool CurvingProblem::solve(Vector& u, Evaluation& e, int& iterations, std::string& message) const {
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
      if (!(scaled(trial).norm() < size.norm()) || (derailed(trial) && !derailed(e))) return false;
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
      message = "the line search found no smaller residual (" + shortfall(size, e) + ")";
      return false;
    }
  }
  message = "no convergence in " + std::to_string(options_.max_iterations) +
            " Newton iterations (" + shortfall(scaled(e), e) + ")";
  return false;
}

}  // namespace wheelwear::vehicle::detail
