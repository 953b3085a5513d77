#pragma once
// The quasi-static balance of the whole vehicle in one curve on one set of wheelset models, and
// Newton's method on it: solve_vehicle_curving (quasi_static_curving.cpp) tries it from its
// starts, on the contact table and on the direct contacts.

#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>

#include "wheelwear/vehicle/quasi_static_curving.hpp"

namespace wheelwear::vehicle::detail {

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

// The in-plane force that gravity and the centrifugal force put on a body of mass m [N], + y.
double applied_force(const SteadyCurve& curve, double mass);

struct Placement {
  BodyPlacement car_body;
  std::array<BodyPlacement, kBogies> bogies;
  std::array<WheelsetMotionState, kWheelsets> wheelsets;
};
Placement placement(const Vector& u);

struct Evaluation {
  Vector residual = Vector::Zero();
  std::array<CurvingWheelset, kWheelsets> wheelsets;
};

// The unknowns of a placement, and back (placement).
Vector unknowns(const VehiclePlacement& p);
// The start: every body centred and radial, each axle at the spin of its wheels' nominal
// radius (the contact's, which a vehicle file's own radius need not match).
Vector initial_guess(const std::array<WheelsetModel, kWheelsets>& models, const SteadyCurve& curve);
// The curve scaled towards tangent track by `share` of its curvature and cant.
SteadyCurve partial_curve(const SteadyCurve& curve, double share);

// The balance of every body and axle in `curve` with the rails' forces from `models`; counts
// its wheelset evaluations into `evaluations`.
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
  // The wheels' loads (left, right) of wheelset k at `u` (wheel_loads).
  std::array<double, 2> loads(int k, const Vector& u) const;
  // Every residual at `u`, with each wheelset's contact.
  Evaluation evaluate(const Vector& u) const;
  // The Jacobian: the suspension's exactly (finite differences of a linear or piecewise-linear
  // map); the contact's per wheelset in its own unknowns, and through its wheels' loads in the
  // lateral shifts of the bodies that load it (wheel_loads is linear in them).
  Matrix jacobian(const Vector& u, const Evaluation& at) const;
  // The residuals in units of their tolerances: within 1 everywhere is converged.
  Vector scaled(const Evaluation& e) const;
  // Why `e` (scaled residual `scaled`) is not a solution, for messages: the balance furthest
  // from its tolerance, or the contact that a balanced state fails on.
  std::string shortfall(const Vector& scaled, const Evaluation& e) const;
  // Every wheel's contact met its load.
  bool loads_met(const Evaluation& e) const;
  // A wheel whose contact has passed its flank's steepest point has derailed: a balance there
  // (the rail pushing the wheel on over its flange) is no state of the vehicle in the curve.
  static bool derailed(const Evaluation& e);
  // Newton from `u`; true when converged. `u` and `e` hold the last iterate.
  bool solve(Vector& u, Evaluation& e, int& iterations, std::string& message) const;

 private:
  const Vehicle& v_;
  const std::array<WheelsetModel, kWheelsets>& models_;
  SteadyCurve curve_;
  CurvingOptions options_;
  int& evaluations_;
};

}  // namespace wheelwear::vehicle::detail
