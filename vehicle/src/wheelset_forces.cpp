#include "wheelwear/vehicle/wheelset_forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

namespace {

// The solved-for vertical forces of a wheel whose Q fell below (above) its load, nearest it; Q
// grows with the force (a wheel's Q that does not is left to the secant steps).
struct LoadBracket {
  double below = -std::numeric_limits<double>::infinity(), Q_below = 0.0;
  double above = std::numeric_limits<double>::infinity(), Q_above = 0.0;

  void add(double force, double Q, double load) {
    if (Q < load && force > below) {
      below = force;
      Q_below = Q;
    } else if (Q >= load && force < above) {
      above = force;
      Q_above = Q;
    }
  }
  bool closed() const { return std::isfinite(below) && std::isfinite(above) && below < above; }
  // `proposal`, or the bracket's midpoint where it falls outside.
  double inside(double proposal) const {
    if (!closed() || (proposal > below && proposal < above)) return proposal;
    return 0.5 * (below + above);
  }
  double nearer(double load) const { return load - Q_below <= Q_above - load ? below : above; }
  double nearer_miss(double load) const { return std::min(load - Q_below, Q_above - load); }
  // Narrower than `width` with Q differing across it by a hundred times the width: Q grows with
  // the force at a rate near 1 where it is continuous, so this is a jump.
  bool jumps(double width) const {
    return closed() && above - below < width && Q_above - Q_below > 100.0 * (above - below);
  }
};

// The contact's vertical force is corrected by the creep forces' vertical part until Q meets
// the load to WheelsetModel::load_tolerance.
constexpr int kMaxLoadIterations = 40;
// A bracket of a wheel's Q narrower than this share of its load across which Q changes far more
// than the force is a jump of Q (contact regions that merge or part): no vertical force in
// between meets the load. Q that moves by less than this while the force moves is the flat side
// of such a jump.
constexpr double kJumpWidth = 1e-5;
// The largest miss of a wheel's load a jump may leave, as a share of the load: beyond it the
// loads count as not met (the contact is too far from the state asked for).
constexpr double kLargestJumpMiss = 0.05;

void validate(const RunningConditions& running) {
  require(std::isfinite(running.speed) && running.speed > 0.0, "speed", running.speed,
          "the forward speed must be positive (m/s)");
  require(std::isfinite(running.curve_radius) &&
              (running.curve_radius == 0.0 || std::abs(running.curve_radius) >= 10.0),
          "curve radius", running.curve_radius, "must be 0 (tangent track) or |R| >= 10 m");
  require(std::isfinite(running.friction) && running.friction > 0.0, "friction", running.friction,
          "must be positive");
  if (running.friction_flange)
    require(std::isfinite(*running.friction_flange) && *running.friction_flange > 0.0,
            "flange friction", *running.friction_flange, "must be positive");
}

// The patches of one wheel solved at the wheel's motion, summed into the wheel's forces.
WheelForces wheel_forces(const WheelsetModel& model, const contactgeom::WheelRailContact& contact,
                         const contactgeom::WheelsetPose& pose,
                         const contactgeom::WheelsetMotion& motion, double nominal_radius,
                         const contactgeom::RailFriction& friction) {
  WheelForces w;
  w.status = contact.status;
  if (contact.patches.empty()) return w;
  double largest = -1.0;
  for (const contactgeom::WheelRailPatch& patch : contact.patches) {
    PatchForces p;
    p.normal_force = patch.normal_force;
    p.contact_angle = patch.contact_angle;
    p.rolling_radius = patch.rolling_radius;
    p.creepages = contactgeom::kinematic_creepages(patch, pose, motion, nominal_radius);
    const contactgeom::Sdec region =
        model.ellipse_at_O ? contactgeom::Sdec{patch.sdec.a, patch.sdec.b, 0.0} : patch.sdec;
    const tangential::TangentialSolution s = tangential::solve_patch(
        model.method, region, p.creepages,
        {contactgeom::description_load(patch), friction.at(patch.contact_angle)}, model.material,
        model.solve);
    // A patch of a blend: its description's problem, weighted by its share.
    const tangential::CreepForces f = tangential::weighted(s.forces, patch.share);
    p.Fx = f.Fx;
    p.Fy = f.Fy;
    p.Mz = f.Mz.value_or(0.0);
    const double c = std::cos(p.contact_angle), sn = std::sin(p.contact_angle);
    w.Q += patch.vertical_force - p.Fy * sn;
    w.Y += patch.lateral_force + p.Fy * c;
    w.Fx += p.Fx;
    w.Fy += p.Fy * c;
    w.N += p.normal_force;
    w.torque += p.Fx * p.rolling_radius - p.Mz * sn;
    if (p.normal_force > largest) {
      largest = p.normal_force;
      w.contact_angle = p.contact_angle;
    }
    w.patches.push_back(p);
  }
  return w;
}

}  // namespace

contactgeom::WheelsetMotion wheel_motion(const WheelsetMotionState& state,
                                         const RunningConditions& running, int side,
                                         double lateral_arm) {
  // The wheelset turns at -V/R (counter-clockwise +: a right-hand curve turns clockwise) plus
  // its own yaw rate; a point at lateral position y moves forward at V - (turn rate) y.
  const double turn =
      (running.curve_radius == 0.0 ? 0.0 : -running.speed / running.curve_radius) + state.yaw_rate;
  const double sign = side == 0 ? 1.0 : -1.0;  // the right wheel is mirrored
  contactgeom::WheelsetMotion motion;
  motion.speed = running.speed;
  motion.lateral_velocity = sign * state.lateral_velocity;
  motion.yaw_rate = -sign * turn;  // V_w = V + yaw_rate * arm for the wheel at +-arm
  motion.angular_velocity = state.spin;
  motion.lateral_arm = lateral_arm;
  return motion;
}

double drive_torque(const WheelsetModel& model, double traction) {
  return traction * model.track.left.wheel_radius;
}

WheelsetForces wheelset_forces(const WheelsetModel& model, const WheelsetMotionState& state,
                               double load_left, double load_right,
                               const RunningConditions& running,
                               std::optional<contactgeom::KnownRoll> known_roll,
                               std::optional<std::array<double, 2>> vertical_start) {
  validate(running);
  require(std::isfinite(model.load_tolerance) && model.load_tolerance > 0.0 &&
              model.load_tolerance <= 0.01,
          "load tolerance", model.load_tolerance, "must lie in (0, 0.01]");
  require(std::isfinite(state.spin) && state.spin > 0.0, "spin", state.spin,
          "the axle's angular velocity must be positive (rad/s)");
  require(std::isfinite(load_left) && load_left > 0.0, "left wheel load", load_left,
          "must be positive (N)");
  require(std::isfinite(load_right) && load_right > 0.0, "right wheel load", load_right,
          "must be positive (N)");
  const std::array<double, 2> loads{load_left, load_right};
  // The vertical force the contact is solved for.
  std::array<double, 2> solved_for = loads;
  if (vertical_start && std::isfinite((*vertical_start)[0]) && std::isfinite((*vertical_start)[1]))
    for (int side = 0; side < 2; ++side)
      solved_for[side] = std::clamp((*vertical_start)[side], 0.5 * loads[side], 2.0 * loads[side]);
  // The previous iterate per wheel, for secant steps: Q grows with the solved-for force at a
  // rate near 1 (less the creep forces' share), which the secant finds in one step.
  std::array<double, 2> previous_for{0.0, 0.0}, previous_Q{0.0, 0.0};
  // Where the secant steps cycle (a kink of Q) or cannot arrive (a jump), bisection in the
  // bracket of forces whose Q fell below and above the load.
  std::array<LoadBracket, 2> bracket;
  std::array<bool, 2> at_jump{false, false};
  double jump_too_large = 0.0;  // the miss a jump would leave, when beyond kLargestJumpMiss [N]
  WheelsetForces out;
  for (int iteration = 0; iteration < kMaxLoadIterations; ++iteration) {
    contactgeom::WheelsetState geometry;
    geometry.dy = state.dy;
    geometry.yaw = state.yaw;
    geometry.vertical_force_left = solved_for[0];
    geometry.vertical_force_right = solved_for[1];
    geometry.known_roll = known_roll;
    std::optional<contactgeom::WheelsetContact> tabulated;
    if (model.table) tabulated = model.table->contact(geometry);
    out.contact = tabulated ? std::move(*tabulated)
                            : contactgeom::solve_wheelset(model.track, geometry, model.contact);
    out.tabulated = tabulated.has_value();
    // The roll depends on dy and yaw alone: the next load iterations take it as found.
    known_roll = out.contact.known_roll;
    ++out.load_iterations;
    out.vertical_forces = solved_for;
    bool met = true;
    for (int side = 0; side < 2; ++side) {
      const auto k = static_cast<std::size_t>(side);
      const contactgeom::WheelRailContact& c = side == 0 ? out.contact.left : out.contact.right;
      const contactgeom::WheelsetPose& pose =
          side == 0 ? out.contact.left_pose : out.contact.right_pose;
      const contactgeom::WheelRailPair& pair = side == 0 ? model.track.left : model.track.right;
      contactgeom::WheelsetMotion motion = wheel_motion(state, running, side, model.lateral_arm);
      motion.slip_point = model.slip_point;
      out.wheels[k] =
          wheel_forces(model, c, pose, motion, pair.wheel_radius, running.rail_friction());
      if (!contactgeom::carries_load(c.status)) continue;
      const double Q = out.wheels[k].Q;
      const double miss = loads[k] - Q;
      if (std::abs(miss) > model.load_tolerance * loads[k] && !at_jump[k]) {
        met = false;
        bracket[k].add(solved_for[k], Q, loads[k]);
        // Q that stays put while the force moves: the contact solve answers from one side of a
        // jump of its own (contactgeom's load_jump) whatever force inside it is asked.
        const bool flat = c.status == contactgeom::WheelRailStatus::load_jump && iteration > 0 &&
                          solved_for[k] != previous_for[k] &&
                          std::abs(Q - previous_Q[k]) <= kJumpWidth * loads[k];
        double rate = 1.0;
        if (iteration > 0 && solved_for[k] != previous_for[k]) {
          rate = (Q - previous_Q[k]) / (solved_for[k] - previous_for[k]);
          if (!(rate > 0.5 && rate < 2.0)) rate = 1.0;  // a jump of the contact: plain step
        }
        previous_for[k] = solved_for[k];
        previous_Q[k] = Q;
        if (flat || bracket[k].jumps(kJumpWidth * loads[k])) {
          // A jump: a flat side is kept as the contact answers it, a bracketed one at the side
          // whose Q is nearer the load.
          const double kept_miss = flat ? std::abs(miss) : bracket[k].nearer_miss(loads[k]);
          if (kept_miss > kLargestJumpMiss * loads[k]) {
            jump_too_large = kept_miss;
            break;
          }
          at_jump[k] = true;
          if (!flat) solved_for[k] = bracket[k].nearer(loads[k]);
        } else {
          solved_for[k] = bracket[k].inside(std::max(0.01 * loads[k], solved_for[k] + miss / rate));
        }
      }
    }
    if (jump_too_large > 0.0) break;
    if (met) {
      out.loads_met = true;
      out.load_jump = at_jump[0] || at_jump[1];
      break;
    }
  }
  if (jump_too_large > 0.0)
    out.message = "a wheel's Q jumps across its load, leaving it " +
                  std::to_string(jump_too_large) + " N off (more than 5 %)";
  else if (!out.loads_met)
    out.message = "the wheels' loads were not met in " + std::to_string(kMaxLoadIterations) +
                  " contact solves (a jump of the contact with the load?)";
  const WheelForces& left = out.wheels[0];
  const WheelForces& right = out.wheels[1];
  out.lateral = right.Y - left.Y;
  out.yaw_moment = model.lateral_arm * (right.Fx - left.Fx);
  out.Fx_axle = left.Fx + right.Fx;
  out.axle_torque = left.torque + right.torque;
  return out;
}

}  // namespace wheelwear::vehicle
