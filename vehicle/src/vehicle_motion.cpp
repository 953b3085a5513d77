#include "wheelwear/vehicle/vehicle_motion.hpp"

#include <algorithm>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>
#include <optional>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

namespace {

// The 7 bodies, each with a lateral shift and a yaw: car body, bogies, wheelsets.
constexpr int kBodies = 1 + kBogies + kWheelsets;
constexpr int kPositions = 2 * kBodies;
// Positions, their rates, then the 4 axle spins.
constexpr int kStates = 2 * kPositions + kWheelsets;
using State = std::array<double, kStates>;

constexpr int bogie_body(int i) {
  return 1 + i;
}
constexpr int wheelset_body(int k) {
  return 1 + kBogies + k;
}
constexpr int spin_index(int k) {
  return 2 * kPositions + k;
}

// The design track along the route without the per-call validation of track_at: curvature and
// cant linear within each section, each section's start taken from track_at once.
class DesignTrack {
 public:
  explicit DesignTrack(const Route& route)
      : route_(route), starts_(route.section_starts()), total_(route.total_length()) {
    for (std::size_t i = 0; i < starts_.size(); ++i) begin_.push_back(track_at(route, starts_[i]));
  }

  // The track at `s`, clamped to the route's ends, and d(curvature)/ds there [1/m^2]
  // (constant within a section, 0 except in transitions).
  struct Point {
    TrackPoint track;
    double curvature_slope = 0.0;
  };

  Point at(double s) const {
    s = std::clamp(s, 0.0, total_);
    const auto after = std::upper_bound(starts_.begin(), starts_.end(), s);
    const auto i = static_cast<std::size_t>(after - starts_.begin()) - 1;
    Point out{begin_[i]};
    TrackPoint& p = out.track;
    p.offset_m = s - starts_[i];
    const RouteSection& section = route_.sections[i];
    if (section.kind == SectionKind::transition) {
      out.curvature_slope = (section.curvature() - p.curvature_1_m) / section.length_m;
      const double t = std::clamp(p.offset_m / section.length_m, 0.0, 1.0);
      p.curvature_1_m += t * (section.curvature() - p.curvature_1_m);
      p.cant_m += t * (section.cant_m - p.cant_m);
      p.radius_m = p.curvature_1_m == 0.0 ? 0.0 : 1.0 / p.curvature_1_m;
    }
    return out;
  }

 private:
  const Route& route_;
  std::vector<double> starts_;
  double total_;
  std::vector<TrackPoint> begin_;
};

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

// The irregularities at s: the rails' lateral position, its slope, the cross-level. Zero
// outside the record.
struct RailOffset {
  double alignment = 0.0, slope = 0.0, cross_level = 0.0;
};

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

// A suspension joint between a parent body and a child at distance d ahead of it: the child's
// relative displacement and yaw against the parent's attachment point, and their rates.
struct JointMotion {
  double lateral = 0.0, yaw = 0.0, lateral_rate = 0.0, yaw_rate = 0.0;
};

// The design track under one body.
struct BodyTrack {
  double s = 0.0;  // along the route
  TrackPoint point;
  double kappa = 0.0;  // design curvature
  double kappa_slope = 0.0;
  double theta = 0.0;  // design tilt
};

class VehicleSystem {
 public:
  VehicleSystem(const Vehicle& v, const std::array<WheelsetModel, kWheelsets>& models,
                const Route& route, const TrackIrregularities& irregularities, double s0,
                double speed)
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

  // Thrown from the right-hand side where a wheel leaves its rail.
  struct LeftTheRails {
    std::string why;
  };

  double car_body_distance(double t) const { return s0_ + speed_ * t; }

  // dx/dt at time t; with `sample`, the wheelsets' contacts as well.
  void derivative(const State& x, State& dxdt, double t, VehicleSample* sample = nullptr) {
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
    for (int i = 0; i < kBogies; ++i) {
      const JointMotion j = joint(x, tracks, 0, bogie_body(i));
      const double lateral = -(v_.secondary.joint_lateral_stiffness() * j.lateral +
                               v_.lateral_stop.force_at(j.lateral) +
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
      const WheelsetMotionSample c = contact(x, tracks[b], rails, tilt, k);
      force[2 * b] += c.forces.lateral + carried_lateral(tracks[b], tilt);
      force[2 * b + 1] += c.forces.yaw_moment;
      dxdt[spin_index(k)] = -c.forces.axle_torque / v_.wheelset.spin_inertia;
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

  long evaluations() const { return evaluations_; }

 private:
  static constexpr double kCantBase = 1.5;

  // Joint motion of `child` against `parent` (body indices).
  JointMotion joint(const State& x, const std::array<BodyTrack, kBodies>& tracks, int parent,
                    int child) const {
    const double d = xs_[child] - xs_[parent];
    const BodyTrack& p = tracks[parent];
    const BodyTrack& c = tracks[child];
    // The design track's offset and turn from the parent's tangent to the child, exact for a
    // curvature linear in distance, and their rates at speed V.
    const double offset = d * d / 6.0 * (2.0 * p.kappa + c.kappa);
    const double turn = 0.5 * d * (p.kappa + c.kappa);
    const double offset_rate = speed_ * d * d / 6.0 * (2.0 * p.kappa_slope + c.kappa_slope);
    const double turn_rate = speed_ * 0.5 * d * (p.kappa_slope + c.kappa_slope);
    const auto q = [&](int body, int dof) { return x[2 * body + dof]; };
    const auto rate = [&](int body, int dof) { return x[kPositions + 2 * body + dof]; };
    return {q(child, 0) - offset - q(parent, 0) - q(parent, 1) * d,
            q(child, 1) - turn - q(parent, 1),
            rate(child, 0) - offset_rate - rate(parent, 0) - rate(parent, 1) * d,
            rate(child, 1) - turn_rate - rate(parent, 1)};
  }

  // A joint's force and moment on the child; the reactions on the parent at distance d behind.
  static void apply(std::array<double, kPositions>& force, int parent, int child, double d,
                    double lateral, double moment) {
    force[2 * child] += lateral;
    force[2 * child + 1] += moment;
    force[2 * parent] -= lateral;
    force[2 * parent + 1] -= moment + d * lateral;
  }

  // The tilt under a wheelset: the cant plus the cross-level.
  static double wheelset_tilt(const BodyTrack& t, const RailOffset& rails) {
    return t.theta + std::asin(std::clamp(rails.cross_level / kCantBase, -1.0, 1.0));
  }

  // The weight the wheelset carries (its bogie's half, the car body's quarter) comes through
  // the suspension normal to the design track; in the plane of the rails, tilted further by
  // the cross-level, it has the lateral part -W sin(cross-level tilt).
  double carried_lateral(const BodyTrack& t, double tilt) const {
    const double extra = tilt - t.theta;
    const double carried =
        normal(v_.car_body.mass / kWheelsets + 0.5 * v_.bogie.mass, speed_, t.kappa, t.theta);
    // The wheelset's own mass feels the full tilt: move its design-tilt share over.
    const double own = in_plane(v_.wheelset.body.mass, speed_, t.kappa, t.theta + extra) -
                       in_plane(v_.wheelset.body.mass, speed_, t.kappa, t.theta);
    return -carried * std::sin(extra) + own;
  }

  // The rails' forces on wheelset k on the design track `t`, its rails at `rails`, tilted by
  // `tilt`.
  WheelsetMotionSample contact(const State& x, const BodyTrack& t, const RailOffset& rails,
                               double tilt, int k) {
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
        Share{v_.car_body.mass / kWheelsets, v_.car_body.cg_height, x[0]},
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
                         std::to_string(c.load_left) + " and " + std::to_string(c.load_right) +
                         " N"};
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

  const Vehicle& v_;
  std::array<WheelsetModel, kWheelsets> models_;
  DesignTrack track_;
  const TrackIrregularities& irregular_;
  double stencil_;
  double s0_, speed_;
  std::array<double, kBodies> xs_{}, masses_{}, inertias_{};
  // Per wheelset: the vertical forces of its last contact solve (the next solve's start).
  std::array<std::optional<std::array<double, 2>>, kWheelsets> vertical_{};
  long evaluations_ = 0;
};

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

// The fastest decay rate over the wheelsets, at their start and centred in pure rolling (tread
// contact, unsaturated: where the creep forces are stiffest, which a start in saturated flange
// contact would miss).
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

}  // namespace

VehicleMotion simulate_vehicle(const Vehicle& vehicle,
                               const std::array<WheelsetModel, kWheelsets>& wheelsets,
                               const Route& route, double start_m, double length_m,
                               const TrackIrregularities& irregularities,
                               const VehiclePlacement& start, const VehicleMotionOptions& options) {
  vehicle.validate();
  route.validate();
  require(std::isfinite(start_m) && start_m >= 0.0 && start_m <= route.total_length(), "start",
          start_m, "must lie on the route (0 ... its length, m)");
  require(std::isfinite(length_m) && length_m > 0.0, "length", length_m, "must be positive (m)");
  require(std::isfinite(options.time_step) && options.time_step >= 0.0 && options.time_step <= 0.01,
          "time step", options.time_step, "must lie in [0, 0.01] s (0: automatic)");
  require(std::isfinite(options.sample_distance) && options.sample_distance > 0.0,
          "sample distance", options.sample_distance, "must be positive (m)");
  require(std::isfinite(options.run_in) && options.run_in >= 0.0, "run-in distance", options.run_in,
          "must not be negative (m)");
  require(std::isfinite(options.load_tolerance) && options.load_tolerance > 0.0 &&
              options.load_tolerance <= 0.01,
          "load tolerance", options.load_tolerance, "must lie in (0, 0.01]");
  require(vehicle.wheelset.spin_inertia > 0.0, "wheelset spin inertia",
          vehicle.wheelset.spin_inertia,
          "must be positive for the time-domain simulation (kg m^2)");
  require(std::isfinite(options.speed) && options.speed >= 0.0 && options.speed <= 100.0, "speed",
          options.speed, "must lie in [0, 100] m/s (0: the route's)");
  const double speed = options.speed > 0.0 ? options.speed : track_at(route, start_m).speed_m_s;
  // Samples at equal intervals no longer than the sample distance, both ends included.
  const double intervals = std::ceil(length_m / options.sample_distance - 1e-9);
  require(intervals < 1e7, "samples", intervals,
          "too many: raise the sample distance or shorten the piece");
  const long samples_wanted = std::max(1L, static_cast<long>(intervals)) + 1;
  const double spacing = length_m / static_cast<double>(samples_wanted - 1);
  require(options.fastsim_grid >= 0 && options.fastsim_grid <= 1000, "FASTSIM grid",
          options.fastsim_grid, "must lie in 0 ... 1000 (0: the models' grids)");
  std::array<WheelsetModel, kWheelsets> models = wheelsets;
  for (WheelsetModel& m : models) {
    m.load_tolerance = options.load_tolerance;
    if (options.fastsim_grid > 0) m.solve.fastsim.nx = m.solve.fastsim.ny = options.fastsim_grid;
  }

  const double s0 = start_m - options.run_in;
  VehicleSystem system(vehicle, models, route, irregularities, s0, speed);
  State x = initial_state(start);
  VehicleMotion motion;
  try {
    VehicleSample first;
    State dxdt{};
    system.derivative(x, dxdt, 0.0, &first);
    double dt = options.time_step;
    if (dt == 0.0) {
      dt = std::min(2e-3, 1.5 / fastest_rate(vehicle, models, first.wheelsets));
    }
    motion.time_step = dt;
    const auto rhs = [&](const State& s, State& d, double t) { system.derivative(s, d, t); };
    boost::numeric::odeint::runge_kutta4<State> stepper;
    const double t_first = options.run_in / speed;
    const double t_end = (options.run_in + length_m) / speed;
    long next = 0;  // the next sample's number
    double t = 0.0;
    const auto sample_time = [&](long n) {
      return n + 1 == samples_wanted ? t_end : t_first + static_cast<double>(n) * spacing / speed;
    };
    while (next < samples_wanted) {
      // Step up to the next sample, the last step shortened to land on it.
      const double target = sample_time(next);
      while (t < target - 1e-12 * t_end) {
        const double h = std::min(dt, target - t);
        stepper.do_step(rhs, x, t, h);
        t += h;
        ++motion.steps;
      }
      VehicleSample sample;
      system.derivative(x, dxdt, t, &sample);
      motion.samples.push_back(std::move(sample));
      ++next;
    }
    motion.completed = true;
  } catch (const VehicleSystem::LeftTheRails& stop) {
    motion.message = stop.why;
  } catch (const InputError& e) {
    // A diverging motion carries a stage beyond what the contact accepts; the start was valid.
    if (motion.time_step == 0.0) throw;
    motion.message = std::string("the motion left the contact's range: ") + e.what();
  }
  motion.wheelset_evaluations = system.evaluations();
  return motion;
}

}  // namespace wheelwear::vehicle
