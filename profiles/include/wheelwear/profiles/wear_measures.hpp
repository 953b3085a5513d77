#pragma once
/// How far a worn wheel profile lies from its original: the depth worn along the original's
/// surface normal, and the change of rolling radius at each lateral position. Naive
/// subtraction of the two curves at equal arc length compares different points of the surface
/// (the worn tread is shorter); both measures here compare the same place.

#include <vector>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Depth worn along the original's inward normal, on an arc-length grid of the original.
struct NormalWear {
  std::vector<double> s;      ///< arc length on the original profile [m]: 0, spacing, ...
  std::vector<double> depth;  ///< [m], > 0 where material is gone; NaN where the normal misses
};

/// The worn profile's distance from `original` along the original's inward normal at
/// s = 0, spacing, 2 spacing, ... <= original.length(): where the line through the original's
/// point along its normal meets `worn` nearest (within 10 mm either way; NaN beyond).
NormalWear normal_wear(const Profile& original, const Profile& worn, double spacing = 0.1e-3);

/// The change of rolling radius on a fixed lateral grid.
struct RadiusChange {
  std::vector<double>
      y;  ///< lateral position [m]: the multiples of spacing in the original's range
  std::vector<double> delta;  ///< r(y) - r_original(y) = z(y) - z_original(y) [m] (< 0 where worn);
                              ///< NaN where either profile has no surface at y
};

/// Delta r(y) of a wheel: with z positive downwards (away from the axle), r(y) = r0 + z(y).
RadiusChange radius_change(const Profile& original, const Profile& worn, double spacing = 0.1e-3);

}  // namespace wheelwear::profiles
