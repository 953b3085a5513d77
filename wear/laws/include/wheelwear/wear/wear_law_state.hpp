#pragma once
/// The local state of one cell of a contact patch, as the wear laws read it, and the unit
/// conventions the laws share.

#include <span>

namespace wheelwear::wear {

/// Local state of one cell of the tangential solution (FASTSIM's CellFields plus the patch's
/// normal pressure). All magnitudes are non-negative; a cell that adheres has slip 0.
/// The laws do not check a state per cell (they sit in the innermost loop); a NaN or a
/// negative magnitude gives a NaN depth. Call validate() where states enter from outside.
struct CellState {
  double pressure = 0.0;  ///< normal pressure p [Pa], >= 0
  double traction = 0.0;  ///< tangential traction magnitude |tau| [Pa], >= 0
  double slip = 0.0;      ///< slip magnitude |s| = |slip velocity| / V [-], >= 0
  double speed = 0.0;     ///< rolling (forward) speed V [m/s], >= 0

  /// Frictional work density |tau||s| [N/m^2 = J/m^2 per m rolled]: the local T gamma / A.
  double work_density() const { return traction * slip; }
  /// Sliding speed |s| V [m/s] of the wheel surface relative to the rail.
  double sliding_speed() const { return slip * speed; }

  /// Throws InputError unless every field is finite and >= 0.
  void validate() const;
};

/// The states of a row of cells as columns (one value per cell in each), the layout a patch's
/// per-cell fields already have: the laws read them without building a CellState per cell.
/// Cell i has pressure[i], work density work[i] = |tau||s| and slip[i]; all share `speed`.
/// The spans have the same size (not checked); the per-cell rules of CellState apply.
struct CellColumns {
  std::span<const double> pressure;  ///< normal pressure p [Pa], >= 0
  std::span<const double> work;      ///< frictional work density |tau||s| [N/m^2], >= 0
  std::span<const double> slip;      ///< slip magnitude |s| [-], >= 0
  double speed = 0.0;                ///< rolling speed V [m/s], >= 0
};

}  // namespace wheelwear::wear
