#include "wheelwear/contactgeom/kinematics.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

void WheelsetMotion::validate() const {
  require_finite("speed", speed);
  require(speed > 0.0, "speed", speed, "the forward speed must be positive (m/s)");
  require_finite("lateral_velocity", lateral_velocity);
  require_finite("yaw_rate", yaw_rate);
  require_finite("angular_velocity", angular_velocity);
  require(angular_velocity >= 0.0, "angular_velocity", angular_velocity,
          "the wheel spin must be >= 0 rad/s (0: free rolling)");
  require(lateral_arm > 0.0 && lateral_arm < 2.0, "lateral_arm", lateral_arm,
          "the lateral arm must lie in 0 ... 2 m");
}

Creepages kinematic_creepages(const WheelRailPatch& patch, const WheelsetPose& pose,
                              const WheelsetMotion& motion, double nominal_radius) {
  motion.validate();
  require(nominal_radius > 0.0, "nominal_radius", nominal_radius, "must be positive (m)");
  const double omega =
      motion.angular_velocity > 0.0 ? motion.angular_velocity : motion.speed / nominal_radius;
  const double wheel_speed = motion.speed + motion.yaw_rate * motion.lateral_arm;
  const double surface_speed = omega * patch.rolling_radius;
  const double rolling = 0.5 * (wheel_speed + surface_speed);
  require(rolling > 0.0, "rolling speed", rolling, "the wheel must roll forward");
  Creepages c;
  c.vx = (wheel_speed - surface_speed) / rolling;
  // Moving towards its flange the wheel moves towards the rail's field side, -y of the patch;
  // a yaw towards the flange makes the rolling material move the other way. At the contact point
  // the horizontal slip turns along the contact plane with the vertical slip that keeps the
  // wheel on its rail; at the axle plane it is projected onto it (header).
  const double horizontal = pose.yaw * wheel_speed - motion.lateral_velocity;
  const double c_angle = std::cos(patch.contact_angle);
  c.vy = motion.slip_point == SlipPoint::contact_point ? horizontal / c_angle / rolling
                                                       : horizontal * c_angle / rolling;
  c.phi = omega * std::sin(patch.contact_angle) / rolling;
  return c;
}

}  // namespace wheelwear::contactgeom
