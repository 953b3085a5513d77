#include "vehicle_system.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle::detail {

namespace {

// The track's tilt in its cross-section, + when the left rail is higher [rad]: the cant
// raises the outer rail (the left one in a right-hand curve, curvature > 0).
double cant_tilt(const TrackPoint& p, double cant_base) {
  const double sign = p.curvature_1_m > 0.0 ? 1.0 : (p.curvature_1_m < 0.0 ? -1.0 : 0.0);
  return sign * std::asin(std::min(p.cant_m / cant_base, 1.0));
}

// The in-plane force of gravity and the centrifugal force on mass m at curvature kappa and
// tilt theta, + y [N]; and the force normal to the tilted plane that carries it [N].
double in_plane(double m, double speed, double kappa, double theta) {
  return m * (speed * speed * kappa * std::cos(theta) - kGravity * std::sin(theta));
}
double normal(double m, double speed, double kappa, double theta) {
  return m * (kGravity * std::cos(theta) + speed * speed * kappa * std::sin(theta));
}

// The stencil of the slope: kIrregularityStencil_m, or the record's widest sample spacing
// where that is wider (a coarser record is piecewise linear: a narrower difference would turn
// its kinks into jumps).
double stencil(const TrackIrregularities& r) {
  double h = kIrregularityStencil_m;
  for (std::size_t i = 1; i < r.distance.size(); ++i)
    h = std::max(h, r.distance[i] - r.distance[i - 1]);
  return h;
}

// Within the record, its stencil points held inside it, so the difference turns one-sided at
// its ends.
RailOffset rail_offset(const TrackIrregularities& r, double h, double s) {
  RailOffset o;
  if (r.distance.size() < 2 || s < r.distance.front() || s > r.distance.back()) return o;
  const double lo = std::max(s - h, r.distance.front()), hi = std::min(s + h, r.distance.back());
  const double a0 = r.alignment_at(s), am = r.alignment_at(lo), ap = r.alignment_at(hi);
  o.alignment = a0;
  o.slope = (ap - am) / (hi - lo);
  o.cross_level = r.cross_level_at(s);
  return o;
}

// The fastest decay rate of the creep forces [1/s] of a wheelset at `state` (with the loads
// and running conditions of `c`): the lateral
// force's rate of change with the lateral velocity over the mass, the yaw moment's with the yaw
// rate over the yaw inertia and the axle torque's with the spin over the spin inertia.
double fastest_rate(const Vehicle& v, const WheelsetModel& model, const WheelsetMotionSample& c,
                    const WheelsetMotionState& state) {
  const auto forces = [&](const WheelsetMotionState& s) {
    return wheelset_forces(model, s, c.load_left, c.load_right, c.running);
  };
  const WheelsetForces at = forces(state);
  double fastest = 0.0;
  WheelsetMotionState s = state;
  const double dv = 1e-4 * c.running.speed;
  s.lateral_velocity += dv;
  fastest = std::max(fastest, std::abs(forces(s).lateral - at.lateral) / dv / v.wheelset.body.mass);
  s = state;
  const double dr = 1e-4 * c.running.speed / model.lateral_arm;
  s.yaw_rate += dr;
  fastest = std::max(
      fastest, std::abs(forces(s).yaw_moment - at.yaw_moment) / dr / v.wheelset.body.yaw_inertia);
  s = state;
  const double dw = 1e-4 * state.spin;
  s.spin += dw;
  return std::max(fastest,
                  std::abs(forces(s).axle_torque - at.axle_torque) / dw / v.wheelset.spin_inertia);
}

}  // namespace

VehicleSystem::VehicleSystem(const Vehicle& v, const std::array<WheelsetModel, kWheelsets>& models,
                             const Route& route, const TrackIrregularities& irregularities,
                             double s0, double speed)
    : v_(v),
      models_(models),
      track_(route),
      irregular_(irregularities),
      stencil_(stencil(irregularities)),
      s0_(s0),
      speed_(speed) {
  xs_[0] = 0.0;
  for (int i = 0; i < kBogies; ++i) xs_[bogie_body(i)] = v.bogie_x(i);
  for (int k = 0; k < kWheelsets; ++k) xs_[wheelset_body(k)] = v.wheelset_x(k);
  masses_[0] = v.car_body.mass;
  inertias_[0] = v.car_body.yaw_inertia;
  for (int i = 0; i < kBogies; ++i) {
    masses_[bogie_body(i)] = v.bogie.mass;
    inertias_[bogie_body(i)] = v.bogie.yaw_inertia;
  }
  for (int k = 0; k < kWheelsets; ++k) {
    masses_[wheelset_body(k)] = v.wheelset.body.mass;
    inertias_[wheelset_body(k)] = v.wheelset.body.yaw_inertia;
  }
}

void VehicleSystem::derivative(const State& x, State& dxdt, double t, VehicleSample* sample) {
  std::array<BodyTrack, kBodies> tracks;
  for (int b = 0; b < kBodies; ++b) {
    BodyTrack& bt = tracks[b];
    bt.s = car_body_distance(t) + xs_[b];
    const DesignTrack::Point p = track_.at(bt.s);
    bt.point = p.track;
    bt.kappa = p.track.curvature_1_m;
    bt.kappa_slope = p.curvature_slope;
    bt.theta = cant_tilt(p.track, kCantBase);
  }
  std::array<double, kPositions> force{};  // lateral force and yaw moment per body
  for (int b = 0; b < kBodies; ++b)
    force[2 * b] += in_plane(masses_[b], speed_, tracks[b].kappa, tracks[b].theta);
  // The car body's shift over each bogie's pivot, against the track there: where its weight
  // reaches the bogie (the wheels' loads).
  std::array<double, kBogies> over_pivot{};
  for (int i = 0; i < kBogies; ++i) {
    const JointMotion j = joint(x, tracks, 0, bogie_body(i));
    over_pivot[i] = parent_over(x, tracks, 0, bogie_body(i));
    const double lateral =
        -(v_.secondary.joint_lateral_stiffness() * j.lateral + v_.lateral_stop.force_at(j.lateral) +
          v_.secondary.joint_lateral_damping() * j.lateral_rate);
    const double moment = -(v_.secondary.joint_yaw_stiffness() * j.yaw +
                            v_.secondary.joint_yaw_damping() * j.yaw_rate);
    apply(force, 0, bogie_body(i), v_.bogie_x(i), lateral, moment);
  }
  for (int k = 0; k < kWheelsets; ++k) {
    const int i = k / 2;
    const JointMotion j = joint(x, tracks, bogie_body(i), wheelset_body(k));
    const double lateral = -(v_.primary.joint_lateral_stiffness() * j.lateral +
                             v_.primary.joint_lateral_damping() * j.lateral_rate);
    const double moment =
        -(v_.primary.joint_yaw_stiffness() * j.yaw + v_.primary.joint_yaw_damping() * j.yaw_rate);
    apply(force, bogie_body(i), wheelset_body(k), v_.wheelset_x(k) - v_.bogie_x(i), lateral,
          moment);
  }
  for (int k = 0; k < kWheelsets; ++k) {
    const int b = wheelset_body(k);
    const RailOffset rails = rail_offset(irregular_, stencil_, tracks[b].s);
    const double tilt = wheelset_tilt(tracks[b], rails);
    const WheelsetMotionSample c = contact(x, tracks[b], rails, tilt, k, over_pivot[k / 2]);
    force[2 * b] += c.forces.lateral + carried_lateral(tracks[b], tilt);
    force[2 * b + 1] += c.forces.yaw_moment;
    // A powered axle's motor or brake, driving the section's traction force.
    const double drive = v_.powered[k] ? drive_torque(models_[k], tracks[b].point.traction_N) : 0.0;
    dxdt[spin_index(k)] = (drive - c.forces.axle_torque) / v_.wheelset.spin_inertia;
    if (sample) sample->wheelsets[k] = c;
  }
  for (int b = 0; b < kBodies; ++b) {
    dxdt[2 * b] = x[kPositions + 2 * b];
    dxdt[2 * b + 1] = x[kPositions + 2 * b + 1];
    dxdt[kPositions + 2 * b] = force[2 * b] / masses_[b];
    // The track's heading turns at -V kappa (a right-hand curve, kappa > 0, turns clockwise):
    // relative to it the yaw accelerates by M / I + V^2 dkappa/ds.
    dxdt[kPositions + 2 * b + 1] =
        force[2 * b + 1] / inertias_[b] + speed_ * speed_ * tracks[b].kappa_slope;
  }
  if (sample) {
    sample->time = t;
    sample->distance = car_body_distance(t);
    sample->car_body = {x[0], x[1]};
    for (int i = 0; i < kBogies; ++i)
      sample->bogies[i] = {x[2 * bogie_body(i)], x[2 * bogie_body(i) + 1]};
  }
}

namespace {

// The design track's lateral offset from a parent body's tangent to a child body at distance d
// along it, exact for a curvature linear in distance (kappa at the parent and at the child).
double track_offset(double d, double parent_kappa, double child_kappa) {
  return d * d / 6.0 * (2.0 * parent_kappa + child_kappa);
}

}  // namespace

double VehicleSystem::parent_over(const State& x, const std::array<BodyTrack, kBodies>& tracks,
                                  int parent, int child) const {
  const double d = xs_[child] - xs_[parent];
  const double offset = track_offset(d, tracks[parent].kappa, tracks[child].kappa);
  return x[2 * parent] + x[2 * parent + 1] * d + offset;
}

JointMotion VehicleSystem::joint(const State& x, const std::array<BodyTrack, kBodies>& tracks,
                                 int parent, int child) const {
  const double d = xs_[child] - xs_[parent];
  const BodyTrack& p = tracks[parent];
  const BodyTrack& c = tracks[child];
  // The design track's offset and turn from the parent's tangent to the child, exact for a
  // curvature linear in distance, and their rates at speed V.
  const double offset = track_offset(d, p.kappa, c.kappa);
  const double turn = 0.5 * d * (p.kappa + c.kappa);
  const double offset_rate = speed_ * d * d / 6.0 * (2.0 * p.kappa_slope + c.kappa_slope);
  const double turn_rate = speed_ * 0.5 * d * (p.kappa_slope + c.kappa_slope);
  const auto q = [&](int body, int dof) { return x[2 * body + dof]; };
  const auto rate = [&](int body, int dof) { return x[kPositions + 2 * body + dof]; };
  return {q(child, 0) - offset - q(parent, 0) - q(parent, 1) * d, q(child, 1) - turn - q(parent, 1),
          rate(child, 0) - offset_rate - rate(parent, 0) - rate(parent, 1) * d,
          rate(child, 1) - turn_rate - rate(parent, 1)};
}

double VehicleSystem::carried_lateral(const BodyTrack& t, double tilt) const {
  const double extra = tilt - t.theta;
  const double carried =
      normal(v_.car_body.mass / kWheelsets + 0.5 * v_.bogie.mass, speed_, t.kappa, t.theta);
  // The wheelset's own mass feels the full tilt: move its design-tilt share over.
  const double own = in_plane(v_.wheelset.body.mass, speed_, t.kappa, t.theta + extra) -
                     in_plane(v_.wheelset.body.mass, speed_, t.kappa, t.theta);
  return -carried * std::sin(extra) + own;
}

WheelsetMotionSample VehicleSystem::contact(const State& x, const BodyTrack& t,
                                            const RailOffset& rails, double tilt, int k,
                                            double car_body_over_pivot) {
  const int b = wheelset_body(k);
  const TrackPoint& p = t.point;
  WheelsetMotionSample c;
  c.distance = t.s;
  c.state.dy = x[2 * b] - rails.alignment;
  c.state.yaw = x[2 * b + 1] - rails.slope;
  c.state.lateral_velocity = x[kPositions + 2 * b] - speed_ * rails.slope;
  // The yaw rate against the design track, whose radius the contact is given: the
  // longitudinal creepages see the wheelset's absolute turning, -V kappa + yaw rate, whatever
  // the rails' own curvature (the rails are fixed; their alignment enters through dy and yaw).
  c.state.yaw_rate = x[kPositions + 2 * b + 1];
  c.state.spin = x[spin_index(k)];
  c.running.speed = speed_;
  c.running.curve_radius = p.radius_m;
  c.running.friction = p.friction_top;
  c.running.friction_flange = p.friction_flange;
  // Loads at the tilt under the wheelset, the bodies' shifts taken against its rails.
  struct Share {
    double mass, height, y;
  };
  const std::array<Share, 3> shares{
      Share{v_.car_body.mass / kWheelsets, v_.car_body.cg_height, car_body_over_pivot},
      Share{v_.bogie.mass / 2.0, v_.bogie.cg_height, x[2 * bogie_body(k / 2)]},
      Share{v_.wheelset.body.mass, v_.wheelset.body.cg_height, x[2 * b]}};
  double weight = 0.0, moment = 0.0;
  for (const Share& s : shares) {
    const double w = normal(s.mass, speed_, t.kappa, tilt);
    weight += w;
    moment += w * (s.y - rails.alignment) + s.height * in_plane(s.mass, speed_, t.kappa, tilt);
  }
  const double difference = moment / models_[k].lateral_arm;
  c.load_left = 0.5 * (weight + difference);
  c.load_right = 0.5 * (weight - difference);
  if (!(c.load_left > 0.0 && c.load_right > 0.0))
    throw LeftTheRails{"wheelset " + std::to_string(k + 1) + " lifts a wheel: its loads are " +
                       std::to_string(c.load_left) + " and " + std::to_string(c.load_right) + " N"};
  if (!(c.state.spin > 0.0))
    throw LeftTheRails{"wheelset " + std::to_string(k + 1) + "'s spin fell to " +
                       std::to_string(c.state.spin) + " rad/s: the integration is unstable"};
  ++evaluations_;
  c.forces = wheelset_forces(models_[k], c.state, c.load_left, c.load_right, c.running,
                             std::nullopt, vertical_[k]);
  for (const WheelForces& w : c.forces.wheels)
    if (!contactgeom::carries_load(w.status))
      throw LeftTheRails{"wheelset " + std::to_string(k + 1) +
                         " left its rail at dy = " + std::to_string(c.state.dy) + " m (" +
                         std::string(contactgeom::status_name(w.status)) + ")"};
  if (!c.forces.loads_met)
    throw LeftTheRails{"wheelset " + std::to_string(k + 1) + ": " + c.forces.message};
  vertical_[k] = c.forces.vertical_forces;
  return c;
}

State initial_state(const VehiclePlacement& start) {
  State x{};
  x[0] = start.car_body.y;
  x[1] = start.car_body.yaw;
  for (int i = 0; i < kBogies; ++i) {
    x[2 * bogie_body(i)] = start.bogies[i].y;
    x[2 * bogie_body(i) + 1] = start.bogies[i].yaw;
  }
  for (int k = 0; k < kWheelsets; ++k) {
    x[2 * wheelset_body(k)] = start.wheelsets[k].dy;
    x[2 * wheelset_body(k) + 1] = start.wheelsets[k].yaw;
    x[spin_index(k)] = start.wheelsets[k].spin;
  }
  return x;
}

double fastest_rate(const Vehicle& v, const std::array<WheelsetModel, kWheelsets>& models,
                    const std::array<WheelsetMotionSample, kWheelsets>& at) {
  double fastest = 0.0;
  for (int k = 0; k < kWheelsets; ++k) {
    WheelsetMotionState centred;
    centred.spin = at[k].state.spin;
    fastest = std::max({fastest, fastest_rate(v, models[k], at[k], at[k].state),
                        fastest_rate(v, models[k], at[k], centred)});
  }
  return fastest;
}

}  // namespace wheelwear::vehicle::detail
