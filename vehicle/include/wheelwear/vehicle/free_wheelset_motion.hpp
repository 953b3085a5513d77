#pragma once
/// The motion of a single wheelset on tangent track, free or held by springs to a frame: its
/// lateral shift and yaw under the rails' forces (wheelset_forces), integrated in time. The axle
/// spin is not a degree of freedom here: it is held at free rolling on the centred wheelset's
/// rolling radius, as in Klingel's kinematic oscillation (a wheelset driven at constant speed). The
/// textbook check of the time-domain machinery: a conical wheelset's wavelength 2 pi sqrt(r0 e0 /
/// lambda).

#include <string>
#include <vector>

#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle {

/// The wheelset's inertia and load.
struct FreeWheelsetBody {
  double mass = 1813.0;         ///< [kg] (Manchester benchmark wheelset)
  double yaw_inertia = 1120.0;  ///< about the vertical axis [kg m^2]
  double wheel_load = 55e3;     ///< Q of each wheel [N]
  /// Springs to a frame that runs along the track's centre line (a bogie frame held still):
  /// lateral [N/m] and yaw [N m/rad]; 0: a free wheelset.
  double lateral_stiffness = 0.0;
  double yaw_stiffness = 0.0;
};

/// One sample of the motion.
struct WheelsetSample {
  double time = 0.0;      ///< [s]
  double distance = 0.0;  ///< travelled [m]
  WheelsetMotionState state;
};

/// How to integrate.
struct MotionOptions {
  double duration = 1.0;    ///< [s], > 0
  double time_step = 5e-4;  ///< [s]: classical Runge-Kutta 4 at a fixed step; the creep forces'
                            ///< time constant m V / (2 f22) is about 1 ms, so 0.5 ms is stable
  int sample_every = 1;     ///< keep every n-th step
};

/// The integrated motion.
struct WheelsetMotion {
  std::vector<WheelsetSample> samples;
  /// False when the integration stopped early: a wheel left its rail (no contact, not converged,
  /// profile end) or its loads were not met, as the amplitude of an unstable free wheelset
  /// grows past the profiles; the samples run up to there.
  bool completed = false;
  std::string message;  ///< why, when not completed
};

/// Integrates the wheelset from `start` (its dy, yaw, lateral velocity and yaw rate; the spin is
/// set to running.speed / r_c, r_c the rolling radius of the centred wheelset's most loaded
/// patch) on tangent track (running.curve_radius must be 0). Throws InputError on bad input.
WheelsetMotion simulate_free_wheelset(const WheelsetModel& model, const FreeWheelsetBody& body,
                                      const RunningConditions& running,
                                      const WheelsetMotionState& start,
                                      const MotionOptions& options = {});

}  // namespace wheelwear::vehicle
