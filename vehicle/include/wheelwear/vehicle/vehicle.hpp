#pragma once
/// A rail vehicle of one car body on two bogies of two wheelsets each: masses, inertias,
/// geometry and the primary (wheelset-bogie) and secondary (bogie-car body) suspension, as a
/// vehicle file gives them (vehicle_file.hpp). SI units throughout.

#include <array>
#include <set>
#include <string>
#include <vector>

namespace wheelwear::vehicle {

/// A rigid body's mass and inertias about its centre of gravity.
struct RigidBody {
  double mass = 0.0;           ///< [kg], > 0
  double roll_inertia = 0.0;   ///< about x [kg m^2]
  double pitch_inertia = 0.0;  ///< about y [kg m^2]
  double yaw_inertia = 0.0;    ///< about z [kg m^2]
  double cg_height = 0.0;      ///< centre of gravity above the rail tops [m]
};

/// One stage of linear suspension: springs and dampers per element (`elements_per_joint` of
/// them between each pair of bodies, at +-lateral_spacing/2).
struct SuspensionStage {
  double kx = 0.0, ky = 0.0, kz = 0.0;  ///< per element [N/m]
  double cx = 0.0, cy = 0.0, cz = 0.0;  ///< per element [N s/m]
  double kpsi = 0.0;                    ///< yaw stiffness per element [N m/rad]
  double yaw_damper = 0.0;       ///< longitudinal yaw damper per element, at its spring [N s/m]
  double antiroll = 0.0;         ///< anti-roll bar per joint [N m/rad]
  double lateral_spacing = 2.0;  ///< between the two elements of a joint [m]
  double height = 0.0;           ///< above the rail tops [m]

  /// Lateral stiffness of one joint (both elements) [N/m].
  double joint_lateral_stiffness() const { return 2.0 * ky; }
  /// Yaw stiffness of one joint: its longitudinal springs at +-spacing/2 and its yaw springs
  /// [N m/rad].
  double joint_yaw_stiffness() const;
  /// Lateral damping of one joint [N s/m].
  double joint_lateral_damping() const { return 2.0 * cy; }
  /// Yaw damping of one joint: its longitudinal and yaw dampers at +-spacing/2 [N m s/rad].
  double joint_yaw_damping() const;
};

/// A lateral stop between bogie frame and car body: no force inside the clearance, then the
/// force of a piecewise-linear table of deflection (relative lateral displacement) against
/// force, continued with its last slope.
struct LateralStop {
  std::vector<double> deflection;  ///< [m], increasing, the first the clearance
  std::vector<double> force;       ///< [N], the first 0
  double height = 0.0;             ///< above the rail tops [m]

  bool present() const { return !deflection.empty(); }
  /// The force on the car body for a relative displacement `dy` of the bogie against the body
  /// [N]: odd in dy, + along dy.
  double force_at(double dy) const;
  /// d(force)/d(dy) [N/m].
  double stiffness_at(double dy) const;
};

/// A wheelset's inertia and geometry.
struct WheelsetBody {
  RigidBody body;               ///< cg_height is the axle height
  double spin_inertia = 0.0;    ///< about the axle [kg m^2]
  double wheel_radius = 0.46;   ///< nominal rolling radius [m]
  double back_to_back = 1.360;  ///< distance between the wheels' internal faces [m]
  /// Lateral distance of each wheel's contact from the wheelset centre [m] (e0; half the
  /// distance between the taping lines).
  double lateral_arm = 0.75;
};

/// The wheel/rail pairing a vehicle file proposes (its [contact] table); a scene's profiles,
/// track and friction take precedence.
struct VehicleContactDefaults {
  std::string wheel_profile = "S1002";
  std::string rail_profile = "60E1";
  double rail_inclination = 0.025;  ///< tan of the rails' inclination [-]
  double gauge = 1.435;             ///< [m]
  double back_to_back = 1.360;      ///< [m]
  double friction = 0.3;            ///< [-]
  /// The keys the vehicle file states ("friction", "gauge_m", ...); the others are defaults.
  std::set<std::string> given;
};

/// The vehicle.
struct Vehicle {
  std::string name;
  std::string source;  ///< where the parameters come from
  RigidBody car_body;
  RigidBody bogie;
  WheelsetBody wheelset;
  double bogie_wheelbase = 2.56;  ///< distance between a bogie's axles [m]
  double pivot_spacing = 19.0;    ///< distance between the bogie centres [m]
  SuspensionStage primary;        ///< per axlebox; one joint per wheelset (2 axleboxes)
  SuspensionStage secondary;      ///< per bogie side; one joint per bogie (2 sides)
  LateralStop lateral_stop;       ///< per bogie, between bogie frame and car body
  VehicleContactDefaults contact;
  /// The wheelsets (in order of travel) a route's traction_N acts on: motored or braked axles.
  /// The others roll freely.
  std::array<bool, 4> powered{true, true, true, true};
  /// The longitudinal position of wheelset k (0..3, in order of travel) from the car body's
  /// centre [m], + forward.
  double wheelset_x(int k) const;
  /// The longitudinal position of bogie i (0 leading, 1 trailing) [m].
  double bogie_x(int i) const;
  /// Total mass [kg].
  double mass() const;
  /// Throws InputError naming the first bad field.
  void validate() const;
};

inline constexpr int kWheelsets = 4;
inline constexpr int kBogies = 2;

}  // namespace wheelwear::vehicle
