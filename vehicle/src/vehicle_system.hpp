#pragma once
// The equations of motion of the whole vehicle along a route (vehicle_motion.hpp): its state,
// the design track under each body and the right-hand side dx/dt, shared by the time-domain
// simulation and the linearised stability analysis (vehicle_stability.hpp).

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/vehicle/vehicle_motion.hpp"

namespace wheelwear::vehicle::detail {

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

// The irregularities at s: the rails' lateral position, its slope, the cross-level. Zero
// outside the record.
struct RailOffset {
  double alignment = 0.0, slope = 0.0, cross_level = 0.0;
};

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

// The vehicle's equations of motion: dx/dt from the rails' forces (wheelset_forces, each wheelset
// with its own model), the suspension, gravity from the cant and the centrifugal force, for a car
// body that runs at constant speed from s0 along the route.
class VehicleSystem {
 public:
  VehicleSystem(const Vehicle& v, const std::array<WheelsetModel, kWheelsets>& models,
                const Route& route, const TrackIrregularities& irregularities, double s0,
                double speed);

  // Thrown from the right-hand side where a wheel leaves its rail.
  struct LeftTheRails {
    std::string why;
  };

  double car_body_distance(double t) const { return s0_ + speed_ * t; }

  // dx/dt at time t; with `sample`, the wheelsets' contacts as well.
  void derivative(const State& x, State& dxdt, double t, VehicleSample* sample = nullptr);

  long evaluations() const { return evaluations_; }

 private:
  static constexpr double kCantBase = 1.5;

  // Joint motion of `child` against `parent` (body indices).
  // The parent's lateral shift at the child's place, against the design track there (the
  // joint's displacement is the child's shift less this).
  double parent_over(const State& x, const std::array<BodyTrack, kBodies>& tracks, int parent,
                     int child) const;
  JointMotion joint(const State& x, const std::array<BodyTrack, kBodies>& tracks, int parent,
                    int child) const;

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
  double carried_lateral(const BodyTrack& t, double tilt) const;

  // The rails' forces on wheelset k on the design track `t`, its rails at `rails`, tilted by
  // `tilt`, the car body's shift over its bogie's pivot `car_body_over_pivot` (against the track
  // there).
  WheelsetMotionSample contact(const State& x, const BodyTrack& t, const RailOffset& rails,
                               double tilt, int k, double car_body_over_pivot);

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

// The state of `start`'s placement with every rate zero.
State initial_state(const VehiclePlacement& start);

// The fastest decay rate of the creep forces [1/s] over the wheelsets, at their states `at` and
// centred in pure rolling (tread contact, unsaturated: where the creep forces are stiffest, which
// a start in saturated flange contact would miss): the lateral force's rate of change with the
// lateral velocity over the mass, the yaw moment's with the yaw rate over the yaw inertia and the
// axle torque's with the spin over the spin inertia.
double fastest_rate(const Vehicle& v, const std::array<WheelsetModel, kWheelsets>& models,
                    const std::array<WheelsetMotionSample, kWheelsets>& at);

}  // namespace wheelwear::vehicle::detail
