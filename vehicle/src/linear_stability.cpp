#include "wheelwear/vehicle/linear_stability.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

namespace {

Eigen::Matrix4d system_matrix(const LinearWheelset& w, double V) {
  const double e0 = w.lateral_arm;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A(0, 2) = 1.0;
  A(1, 3) = 1.0;
  // m y'' = 2 f22 (psi - y'/V) - ky y
  A(2, 0) = -w.lateral_stiffness / w.mass;
  A(2, 1) = 2.0 * w.f22 / w.mass;
  A(2, 2) = -2.0 * w.f22 / (w.mass * V);
  // I psi'' = -2 f11 e0 (e0 psi'/V + lambda y / r0) - kpsi psi
  A(3, 0) = -2.0 * w.f11 * e0 * w.conicity / (w.rolling_radius * w.yaw_inertia);
  A(3, 1) = -w.yaw_stiffness / w.yaw_inertia;
  A(3, 3) = -2.0 * w.f11 * e0 * e0 / (w.yaw_inertia * V);
  return A;
}

}  // namespace

void LinearWheelset::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(mass), "mass", mass, "must be positive (kg)");
  require(positive(yaw_inertia), "yaw inertia", yaw_inertia, "must be positive (kg m^2)");
  require(std::isfinite(lateral_stiffness) && lateral_stiffness >= 0.0, "lateral stiffness",
          lateral_stiffness, "must not be negative (N/m)");
  require(std::isfinite(yaw_stiffness) && yaw_stiffness >= 0.0, "yaw stiffness", yaw_stiffness,
          "must not be negative (N m/rad)");
  require(positive(f11), "f11", f11, "must be positive (N)");
  require(positive(f22), "f22", f22, "must be positive (N)");
  require(positive(conicity), "conicity", conicity, "must be positive");
  require(positive(rolling_radius), "rolling radius", rolling_radius, "must be positive (m)");
  require(positive(lateral_arm), "lateral arm", lateral_arm, "must be positive (m)");
}

std::array<std::array<double, 2>, 4> eigenvalues(const LinearWheelset& w, double speed) {
  w.validate();
  require(std::isfinite(speed) && speed > 0.0, "speed", speed, "must be positive (m/s)");
  const Eigen::EigenSolver<Eigen::Matrix4d> solver(system_matrix(w, speed), false);
  std::array<std::array<double, 2>, 4> out{};
  for (int i = 0; i < 4; ++i)
    out[static_cast<std::size_t>(i)] = {solver.eigenvalues()[i].real(),
                                        solver.eigenvalues()[i].imag()};
  return out;
}

double largest_growth_rate(const LinearWheelset& w, double speed) {
  double largest = -INFINITY;
  for (const auto& e : eigenvalues(w, speed)) largest = std::max(largest, e[0]);
  return largest;
}

CriticalSpeed linear_critical_speed(const LinearWheelset& w, double max_speed) {
  require(std::isfinite(max_speed) && max_speed > 1.0, "max speed", max_speed, "must exceed 1 m/s");
  double lo = 1.0;
  if (largest_growth_rate(w, lo) >= 0.0) return {};  // unstable from the start
  for (double hi = 2.0; hi <= max_speed; lo = hi, hi += 1.0) {
    if (largest_growth_rate(w, hi) < 0.0) continue;
    while (hi - lo > 1e-6 * hi) {
      const double mid = 0.5 * (lo + hi);
      (largest_growth_rate(w, mid) < 0.0 ? lo : hi) = mid;
    }
    return {true, 0.5 * (lo + hi)};
  }
  return {};
}

}  // namespace wheelwear::vehicle
