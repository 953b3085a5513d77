#pragma once
/// Wear of the wheel across its profile: per-cell wear of a tangential solution, summed along
/// the rolling direction for each strip, placed on the wheel profile's arc length.

#include <vector>

#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::wear {

/// Wear depth per unit running distance on a uniform grid of the wheel profile's arc length.
/// Bins are [s_first + (k - 1/2) ds, s_first + (k + 1/2) ds].
struct WearDistribution {
  double s_first = 0.0;       ///< arc length of the first bin centre on the wheel profile [m]
  double ds = 1e-4;           ///< bin width [m]
  std::vector<double> depth;  ///< worn depth per metre of running distance [m/m]

  /// A zero distribution of `bins` bins.
  static WearDistribution zeros(double s_first, double ds, std::size_t bins);
  double s(std::size_t k) const { return s_first + static_cast<double>(k) * ds; }  ///< [m]
  /// Worn cross-section per metre running, sum of depth * ds [m^2/m]; times the wheel's
  /// circumference it is the worn volume per revolution.
  double area() const;
  /// Adds `weight` times `other`, which must share the grid (InputError otherwise).
  void add(const WearDistribution& other, double weight);
};

/// Where a contact's strips lie on the wheel: the patch's lateral coordinate (+ towards the
/// flange) runs against the wheel profile's arc length, which grows towards the field side.
struct WheelPlacement {
  double s_at_O = 0.0;         ///< arc length of the initial contact point O on the wheel [m]
  double wheel_radius = 0.46;  ///< rolling radius [m]: each point passes the patch once a turn
};

/// Measures of a wear distribution or of one contact's wear.
struct WearSummary {
  double volume_per_metre = 0.0;  ///< worn cross-section per metre running [m^2/m] (= area())
  double peak_depth = 0.0;        ///< largest depth per metre running [m/m]
  double peak_s = 0.0;            ///< arc length of the peak [m]
  double centroid_s = 0.0;        ///< depth-weighted mean arc length [m]
  double band_width = 0.0;        ///< extent of the bins above 5 % of the peak [m]
};

WearSummary summarise(const WearDistribution& distribution);

/// Wear of one contact: each cell of `cells` (a FASTSIM solution with per-cell fields) wears by
/// the law's depth per passage at rolling speed V [m/s]; a strip's depth per passage is the sum
/// over its cells; divided by the wheel's circumference 2 pi R it becomes depth per metre
/// running, and it is added, times `weight`, to the bins the strip overlaps on the wheel (in
/// proportion to the overlap, so the worn area is conserved).
/// Strips outside the distribution's range are reported by the return value: the worn area
/// [m^2/m] that fell outside (0 when the grid covers the contact).
double accumulate_wear(const tangential::CellFields& cells, double speed, const WearLaw& law,
                       const WheelPlacement& placement, double weight, WearDistribution& into);

/// The worn area per metre running [m^2/m] of the same contact summed cell by cell, without
/// the mapping: the conservation reference for accumulate_wear.
double cell_wear_area(const tangential::CellFields& cells, double speed, const WearLaw& law,
                      double wheel_radius);

}  // namespace wheelwear::wear
