#pragma once
/// Time-domain simulation of the whole vehicle along a piece of a route, with track
/// irregularities: the lateral and yaw motion of the car body, both bogie frames and all four
/// wheelsets, and the spin of every axle, under the rails' forces from the project's own contact
/// chain (wheelset_forces, with the wheelsets' contact tables where given), the suspension's
/// springs and dampers, gravity from the cant and the centrifugal force. Manual:
/// docs/vehicle.md, "Time-domain simulation".
///
/// The model is the quasi-static one (quasi_static_curving.hpp) set in motion:
/// - 18 degrees of freedom: lateral shift y and yaw of each of the 7 bodies relative to the
///   design track at its own distance along the route (a wheelset's yaw is its angle of attack),
///   and the spin of each of the 4 axles. The spin is a degree of freedom, driven by the axle
///   torque of the contact forces (coasting: no traction): free rolling is where it settles.
/// - Suspension joints as in the quasi-static model, their relative displacement taken against
///   the track's curvature between the bodies (exact for a curvature linear in distance, as in
///   a clothoid), plus the dampers on its rate.
/// - Track irregularities move the rails: a wheelset's contact sees its shift, yaw, lateral
///   velocity relative to the rails' alignment, and its wheels' loads and its in-plane share
///   of gravity follow the cant plus the cross-level. The irregularities' slope is a central
///   difference over +-kIrregularityStencil_m (or the record's widest spacing), which smooths
///   wavelengths below a few metres (the shortest a generated record has is 3 m).
/// - Wheel loads as the quasi-static model shares them (each wheelset its own mass, half its
///   bogie's and a quarter of the car body's; moment balance about the rails), at the cant and
///   cross-level under the wheelset: the bodies' roll and bounce are not modelled, so dynamic
///   load transfer is left out.
/// - Yaw relative to a track whose curvature changes (a transition) carries the inertial term
///   I V^2 dkappa/ds; the speed is constant over the piece.
///
/// Integration: classical Runge-Kutta 4 (Boost.Odeint) at a fixed step, by default the largest
/// the creep forces' fastest mode allows (VehicleMotionOptions::time_step).

#include <array>
#include <string>
#include <vector>

#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/track_irregularities.hpp"
#include "wheelwear/vehicle/vehicle.hpp"
#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle {

/// Central-difference half-width for the irregularities' slope and curvature [m].
inline constexpr double kIrregularityStencil_m = 0.25;

/// How to simulate.
struct VehicleMotionOptions {
  /// Integration step [s]; 0: automatic, 1.5 / lambda_max (classical Runge-Kutta 4 is stable
  /// up to 2.78 / lambda on the real axis) with lambda_max the fastest decay rate of the creep
  /// forces (lateral, yaw and spin, per wheelset; it grows as 1 / V) at the start and on the
  /// centred wheelset in pure rolling, where they are stiffest; at most 2 ms.
  double time_step = 0.0;
  /// Longest distance between samples [m], > 0: the piece is sampled at equal intervals no
  /// longer than this, both its ends included.
  double sample_distance = 0.5;
  /// Distance run before the first sample [m], >= 0: the start's transient dies out (the
  /// irregularities are best faded in over it, IrregularitySpec::run_in).
  double run_in = 0.0;
  /// Relative tolerance of the wheels' loads in each contact evaluation (WheelsetModel's
  /// loads are met to this; the quasi-static solver uses 1e-9). The model's loads leave out
  /// dynamic load transfer, far above 1e-4.
  double load_tolerance = 1e-4;
  /// Cells per strip and strips of the FASTSIM methods (and best's FASTSIM part) for the
  /// dynamics' creep forces; 0 keeps the models' grids. 20 x 20 moves the wheelsets' paths by
  /// about 0.2 % of their amplitude from 50 x 50 at 2.2 times the speed (docs/vehicle.md).
  int fastsim_grid = 20;
  /// Running speed over the whole piece [m/s]; 0: the route's at the car body's first sample.
  /// A piece that starts before its section (a transition's run-in) runs at the section's.
  double speed = 0.0;
};

/// One wheelset at one sample.
struct WheelsetMotionSample {
  double distance = 0.0;  ///< of the wheelset along the route [m]
  /// As the contact sees it: dy, yaw (angle of attack) and lateral velocity relative to the
  /// rails (irregularities included), the spin, and the yaw rate against the design track whose
  /// radius `running` gives (the longitudinal creepages follow the wheelset's absolute turning).
  WheelsetMotionState state;
  double load_left = 0.0;     ///< Q the left wheel carries [N]
  double load_right = 0.0;    ///< Q the right wheel carries [N]
  RunningConditions running;  ///< speed, radius and friction at the wheelset
  WheelsetForces forces;      ///< the rails' forces at `state`
};

/// The vehicle at one sample.
struct VehicleSample {
  double time = 0.0;       ///< since the start of the simulation [s]
  double distance = 0.0;   ///< of the car body's centre along the route [m]
  BodyPlacement car_body;  ///< relative to the design track
  std::array<BodyPlacement, kBogies> bogies;
  std::array<WheelsetMotionSample, kWheelsets> wheelsets;  ///< in order of travel
};

/// The simulated piece.
struct VehicleMotion {
  std::vector<VehicleSample> samples;
  /// False when the simulation stopped early (a wheel left its rail or its loads were not met,
  /// as an unstable motion grows past the profiles); the samples run up to there.
  bool completed = false;
  std::string message;            ///< why, when not completed
  double time_step = 0.0;         ///< used [s]
  long steps = 0;                 ///< integration steps
  long wheelset_evaluations = 0;  ///< calls of wheelset_forces
  /// The samples a completed simulation has, at equal intervals of sample_spacing [m] of the
  /// car body's travel (a stopped one has fewer).
  long planned_samples = 0;
  double sample_spacing = 0.0;
};

/// The piece of `route` the car body's centre runs from `start_m` over `length_m` [m] (plus
/// options.run_in before the first sample, so the simulation starts at start_m - run_in), at
/// one speed. `start_m` may lie before the route's start (a piece whose leading wheelset starts
/// at the route's start), the piece reaching onto the route. Each wheelset's track (curvature,
/// cant, friction) is the
/// route's at its own distance, clamped to the route's ends. `irregularities` (route distance)
/// moves the rails; outside the record (or with an empty one) the track is ideal, so a record
/// should cover the piece and the run-in plus the vehicle's length (a wheelset crossing its end
/// sees a step). The motion starts from
/// `start`'s placement (e.g. the quasi-static solution, placement_of) with every rate zero.
/// Throws InputError on bad input; a motion that leaves the rails is reported in the result.
VehicleMotion simulate_vehicle(const Vehicle& vehicle,
                               const std::array<WheelsetModel, kWheelsets>& wheelsets,
                               const Route& route, double start_m, double length_m,
                               const TrackIrregularities& irregularities,
                               const VehiclePlacement& start,
                               const VehicleMotionOptions& options = {});

}  // namespace wheelwear::vehicle
