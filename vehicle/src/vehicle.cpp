#include "wheelwear/vehicle/vehicle.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

double SuspensionStage::joint_yaw_stiffness() const {
  const double half = 0.5 * lateral_spacing;
  return 2.0 * (kx * half * half + kpsi);
}

double SuspensionStage::joint_yaw_damping() const {
  const double half = 0.5 * lateral_spacing;
  return 2.0 * (cx + yaw_damper) * half * half;
}

namespace {

// The table's force beyond the clearance for a deflection d >= 0, and its slope.
std::pair<double, double> stop_branch(const LateralStop& stop, double d) {
  const std::vector<double>& x = stop.deflection;
  const std::vector<double>& f = stop.force;
  if (d <= x.front()) return {0.0, 0.0};
  const std::size_t n = x.size();
  std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), d) - x.begin());
  k = std::min(std::max<std::size_t>(k, 1), n - 1);  // the segment [k-1, k], the last continued
  const double slope = (f[k] - f[k - 1]) / (x[k] - x[k - 1]);
  return {f[k - 1] + slope * (d - x[k - 1]), slope};
}

void validate_body(const RigidBody& b, const std::string& name) {
  require(std::isfinite(b.mass) && b.mass > 0.0, name + " mass", b.mass, "must be positive (kg)");
  for (const auto& [field, v] :
       {std::pair{"roll inertia", b.roll_inertia}, std::pair{"pitch inertia", b.pitch_inertia},
        std::pair{"yaw inertia", b.yaw_inertia}})
    require(std::isfinite(v) && v >= 0.0, name + " " + field, v, "must be >= 0 (kg m^2)");
  require(std::isfinite(b.cg_height) && b.cg_height >= 0.0 && b.cg_height < 5.0,
          name + " centre of gravity height", b.cg_height, "must lie in 0 ... 5 m");
}

void validate_stage(const SuspensionStage& s, const std::string& name) {
  for (const auto& [field, v] :
       {std::pair{"kx", s.kx}, std::pair{"ky", s.ky}, std::pair{"kz", s.kz}, std::pair{"cx", s.cx},
        std::pair{"cy", s.cy}, std::pair{"cz", s.cz}, std::pair{"kpsi", s.kpsi},
        std::pair{"yaw damper", s.yaw_damper}, std::pair{"anti-roll bar", s.antiroll}})
    require(std::isfinite(v) && v >= 0.0, name + " " + field, v, "must be >= 0");
  require(s.ky > 0.0, name + " ky", s.ky, "a stage needs lateral stiffness to carry the vehicle");
  require(s.joint_yaw_stiffness() > 0.0, name + " kx", s.kx,
          "a stage needs yaw stiffness (kx at the lateral spacing, or kpsi)");
  require(std::isfinite(s.lateral_spacing) && s.lateral_spacing > 0.2 && s.lateral_spacing < 4.0,
          name + " lateral spacing", s.lateral_spacing, "must lie in 0.2 ... 4 m");
}

}  // namespace

double LateralStop::force_at(double dy) const {
  if (!present()) return 0.0;
  const double f = stop_branch(*this, std::abs(dy)).first;
  return dy < 0.0 ? -f : f;
}

double LateralStop::stiffness_at(double dy) const {
  if (!present()) return 0.0;
  return stop_branch(*this, std::abs(dy)).second;
}

double Vehicle::bogie_x(int i) const {
  return i == 0 ? 0.5 * pivot_spacing : -0.5 * pivot_spacing;
}

double Vehicle::wheelset_x(int k) const {
  return bogie_x(k / 2) + (k % 2 == 0 ? 0.5 : -0.5) * bogie_wheelbase;
}

double Vehicle::mass() const {
  return car_body.mass + kBogies * bogie.mass + kWheelsets * wheelset.body.mass;
}

void Vehicle::validate() const {
  validate_body(car_body, "car body");
  validate_body(bogie, "bogie");
  validate_body(wheelset.body, "wheelset");
  require(std::isfinite(wheelset.spin_inertia) && wheelset.spin_inertia >= 0.0,
          "wheelset spin inertia", wheelset.spin_inertia, "must be >= 0 (kg m^2)");
  require(std::isfinite(wheelset.wheel_radius) && wheelset.wheel_radius > 0.2 &&
              wheelset.wheel_radius < 0.8,
          "wheel radius", wheelset.wheel_radius, "must lie in 0.2 ... 0.8 m");
  require(std::isfinite(wheelset.lateral_arm) && wheelset.lateral_arm > 0.3 &&
              wheelset.lateral_arm < 1.2,
          "wheelset lateral arm", wheelset.lateral_arm, "must lie in 0.3 ... 1.2 m");
  require(std::isfinite(bogie_wheelbase) && bogie_wheelbase > 0.5 && bogie_wheelbase < 6.0,
          "bogie wheelbase", bogie_wheelbase, "must lie in 0.5 ... 6 m");
  require(std::isfinite(pivot_spacing) && pivot_spacing > bogie_wheelbase && pivot_spacing < 40.0,
          "pivot spacing", pivot_spacing, "must exceed the bogie wheelbase and be below 40 m");
  validate_stage(primary, "primary");
  validate_stage(secondary, "secondary");
  const LateralStop& s = lateral_stop;
  require(s.deflection.size() == s.force.size(), "lateral stop force count",
          static_cast<double>(s.force.size()), "must match the deflections'");
  if (s.present()) {
    require(s.deflection.size() >= 2, "lateral stop points", static_cast<double>(s.force.size()),
            "a stop table needs at least 2 points");
    require(std::isfinite(s.deflection[0]) && s.deflection[0] >= 0.0, "lateral stop clearance",
            s.deflection[0], "must be >= 0 (m)");
    require(s.force[0] == 0.0, "lateral stop force at the clearance", s.force[0], "must be 0");
    for (std::size_t k = 1; k < s.deflection.size(); ++k) {
      require(std::isfinite(s.deflection[k]) && s.deflection[k] > s.deflection[k - 1],
              "lateral stop deflection", s.deflection[k], "must increase along the table");
      require(std::isfinite(s.force[k]) && s.force[k] >= s.force[k - 1], "lateral stop force",
              s.force[k], "must not decrease along the table");
    }
  }
}

}  // namespace wheelwear::vehicle
