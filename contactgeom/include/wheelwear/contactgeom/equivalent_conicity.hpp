#pragma once
/// Equivalent conicity of a wheelset on its track (EN 15302), from the rolling radius
/// difference function by linear regression over one harmonic cycle (EN 15302, Annex C).

#include <vector>

#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom {

/// The rolling radius difference r_left - r_right [m] at wheelset shifts `dy` [m] (+ to the
/// left), from the first-touch points of both wheels' undeformed surfaces (rigid rails; the
/// wheelset's roll, below 1e-3 rad here, is left out).
struct RollingRadiusDifference {
  std::vector<double> dy;       ///< [m], increasing
  std::vector<double> delta_r;  ///< [m]; NaN where a wheel has no contact
};

/// Delta r on `samples` equally spaced shifts in [-max_shift, max_shift]. `left` and `right`
/// are each wheel's pair in its own frame (the right one mirrored, as everywhere).
RollingRadiusDifference rolling_radius_difference(const contactgeom::WheelRailPair& left,
                                                  const contactgeom::WheelRailPair& right,
                                                  double max_shift, int samples);

/// tan(gamma_e) for the amplitude `amplitude` [m]: the slope of the line Delta r = 2 tan(gamma_e)
/// y fitted by least squares to Delta r along y = amplitude sin(t), t uniform over one cycle
/// (EN 15302, Annex C). NaN when Delta r is not defined over the whole amplitude.
double equivalent_conicity(const RollingRadiusDifference& delta_r, double amplitude);

}  // namespace wheelwear::contactgeom
