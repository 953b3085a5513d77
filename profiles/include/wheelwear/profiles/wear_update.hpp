#pragma once
/// Applying a wear-depth distribution to a profile along its surface normal.

#include <vector>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Wear depth as a function of the profile's lateral coordinate: depth[i] [m] at y[i] [m],
/// linear in between and zero outside [y.front(), y.back()].
struct WearDepth {
  std::vector<double> y;      ///< lateral positions [m], strictly increasing
  std::vector<double> depth;  ///< material removed normal to the surface [m], >= 0

  /// Depth at y [m].
  double at(double y_query) const;
  /// Throws InputError unless sizes match (>= 2), y increases strictly and every depth is finite,
  /// >= 0 and below 0.01 m (one update is a small step).
  void validate() const;
};

/// How a wear step is applied.
struct WearUpdateOptions {
  /// Smoothing length of the depth distribution along the arc length [m] (smoothing_spline.hpp):
  /// the increment is smoothed, not the profile, so repeated updates do not blur the geometry.
  /// 0.5 mm removes the steps of a depth sampled on a coarse contact grid.
  double smoothing_length = 0.5e-3;

  /// Throws InputError unless finite and >= 0.
  void validate() const;
};

/// The profile after removing `wear` [m] along the inward normal at each knot: the depth applies
/// where the surface faces the mating body (outward normal with a component towards it: +z for
/// wheels, -z for rails), elsewhere (flange back, head flanks below vertical) it is zero. The
/// depth is taken at the knot's y, smoothed along s and the moved knots are interpolated again
/// (same knot spacing). Throws InputError if the worn curve would cross itself (a step too deep
/// for the local curvature).
Profile apply_wear(const Profile& profile, const WearDepth& wear,
                   const WearUpdateOptions& options = {});

}  // namespace wheelwear::profiles
