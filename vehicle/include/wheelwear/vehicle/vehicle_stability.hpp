#pragma once
/// The linear stability of the whole vehicle on ideal tangent track: the equations of motion of
/// the time-domain simulation (vehicle_motion.hpp: lateral shift and yaw of the car body, both
/// bogie frames and the four wheelsets, and the axles' spins; the rails' forces from the
/// project's contact chain on the current profiles) linearised about the centred steady state
/// at speed V by central differences, their eigenvalues, and the linear critical speed, where
/// the largest real part of the eigenvalues crosses zero (the onset of hunting). Manual:
/// docs/vehicle.md, "Linear stability of the whole vehicle".
///
/// The linearisation is of the contact as the models give it: with a contact table, its
/// interpolation over the table's nodes next to the centre (the slopes of the two intervals
/// beside dy = 0 averaged); without, the contact solved a micrometre either side, the local
/// slope of the rolling-radius difference and of the creep forces. Where the rolling-radius
/// difference is far from linear near the centre, the local slope describes only motions of a
/// few micrometres: VehicleStabilityOptions::amplitude takes the wheelsets' shifts over a
/// stated amplitude instead.

#include <array>
#include <complex>
#include <vector>

#include "wheelwear/vehicle/linear_stability.hpp"
#include "wheelwear/vehicle/vehicle.hpp"
#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle {

/// How to linearise and search.
struct VehicleStabilityOptions {
  /// Step of the central differences: in metres for shifts, radians for yaws, m/s and rad/s for
  /// their rates, and relative to the spin for the spins. Small enough that FASTSIM stays in
  /// its linear range (no slip), large enough over the contact's load tolerance.
  double step = 1e-6;
  /// Half-width of the wheelsets' lateral shifts' differences [m]: 0 takes `step`, the local
  /// slope at the centre; a few millimetres take the secant over +-amplitude, a
  /// quasi-linearisation of the contact at that amplitude of motion (as EN 15302's equivalent
  /// conicity is one of the rolling-radius difference), which on profiles whose
  /// rolling-radius difference is far from linear near the centre (new S1002 on 60E1 1:40)
  /// describes the motion of real track better than the local slope.
  double amplitude = 0.0;
  /// Cells per strip and strips of the FASTSIM methods for the creep forces; 0 keeps the
  /// models' grids (as VehicleMotionOptions::fastsim_grid).
  int fastsim_grid = 20;
  double max_speed = 100.0;  ///< search the critical speed up to this [m/s], <= 100
  double speed_step = 2.0;   ///< scan in steps of this before bisecting [m/s]
  /// A guess of the critical speed (e.g. on the profiles of a run's last step) [m/s]: the scan
  /// starts there and steps up or down; 0: up from speed_step.
  double start_speed = 0.0;
  double tolerance = 1e-4;  ///< the bisection stops at this width relative to the speed
  /// Eigenvalues whose real part is within this of zero [1/s] count as neutral, not growing:
  /// the rounding of the differences (their growth would take hours to show).
  double neutral_rate = 1e-6;
};

/// The linearised motion at one speed.
struct VehicleModes {
  double speed = 0.0;                             ///< [m/s]
  std::vector<std::complex<double>> eigenvalues;  ///< [1/s], 32 of them
  double growth_rate = 0.0;                       ///< the largest real part [1/s]
  double frequency = 0.0;                         ///< |imaginary part| of that mode [rad/s]
};

/// The eigenvalues of the motion linearised about the centred free-rolling state on ideal
/// tangent track at `speed` [m/s]; `models` are the wheelsets' contacts in order of travel.
/// Throws InputError for bad input or when the centred state carries no load.
VehicleModes vehicle_modes(const Vehicle& vehicle,
                           const std::array<WheelsetModel, kWheelsets>& models, double speed,
                           const VehicleStabilityOptions& options = {});

/// The speed at which the largest growth rate crosses from below zero (or neutral) to above
/// it: scanned in speed_step from speed_step up to max_speed (or from start_speed up or down),
/// then bisected to `tolerance` of the speed. The lowest such speed when scanned from
/// speed_step; from a start speed, the crossing nearest it. Not found when the vehicle is
/// stable up to max_speed, or unstable down to speed_step.
CriticalSpeed vehicle_critical_speed(const Vehicle& vehicle,
                                     const std::array<WheelsetModel, kWheelsets>& models,
                                     const VehicleStabilityOptions& options = {});

}  // namespace wheelwear::vehicle
