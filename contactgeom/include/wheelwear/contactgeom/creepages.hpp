#pragma once
/// Creepages of a contact at its initial contact point O.

namespace wheelwear::contactgeom {

/// Creepages at the initial contact point O (Liu, Fu & Bruni 2022, Eq. 5): the rigid slip of
/// the wheel over the rail, divided by the rolling speed, is w = (vx - phi*y, vy + phi*x).
struct Creepages {
  double vx = 0.0;   ///< longitudinal creepage [-]
  double vy = 0.0;   ///< lateral creepage [-]
  double phi = 0.0;  ///< spin creepage [1/m]

  void validate() const;  ///< throws InputError on NaN/inf
};

}  // namespace wheelwear::contactgeom
