#pragma once
/// What a tangential solve returns, whichever method solved it: totals, status and, on
/// request, per-cell fields for the wear laws.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

/// Per-cell fields on the strip grid, stored strip by strip: index = j*nx + i, with strip j
/// (lateral) and cell i counted from the leading edge. Tractions are the cell's value in the
/// scheme's force sum (Kalker: its trailing node; second order: its average); positions are
/// cell centres relative to O.
struct CellFields {
  int nx = 0, ny = 0;
  double dy = 0.0;                 ///< strip width [m]
  std::vector<double> dx;          ///< cell length of each strip [m], size ny
  std::vector<double> strip_y;     ///< lateral position of each strip's centre from O [m], size ny
  std::vector<double> x, y;        ///< cell centre [m]
  std::vector<double> px, py;      ///< tangential traction on the wheel [Pa]
  std::vector<double> sx, sy;      ///< slip (relative velocity / V) [-]; 0 where adhering
  std::vector<double> slip_norm;   ///< slip magnitude |s| = sqrt(sx^2 + sy^2) [-]
  std::vector<double> work;        ///< frictional work density |p||s| [J/m^2 per m rolled]
  std::vector<double> pressure;    ///< normal pressure of the region at the cell centre [Pa]
  std::vector<std::uint8_t> slip;  ///< 1 where the cell slips, 0 where it adheres
};

/// Numerical outcome of a solve (data, not an error).
enum class SolveStatus {
  ok,             ///< solved as asked
  not_converged,  ///< exact: the iteration cap was reached; the last iterate is returned
  no_contact,     ///< exact: no element carries pressure
};

/// Result of a tangential solve, by any method (tangential.hpp's solve_patch, fastsim()).
struct TangentialSolution {
  /// Kalker's convention: forces on the wheel, opposing the creepages; Mz about O where the
  /// method defines it.
  CreepForces forces;
  SolveStatus status = SolveStatus::ok;
  std::string message;  ///< why, when status is not ok
  int cells = 0;        ///< cells (FASTSIM: nx*ny) or contact elements (exact); 0: totals only
  int slip_cells = 0;   ///< of them, slipping (the traction reached the bound)
  /// Per-cell fields, with FastsimOptions::cell_fields and a method that has them.
  std::optional<CellFields> fields;
  /// Frictional work per rolled distance [N]: FASTSIM methods, the sum of work * dA over the
  /// cells; best (inside the table) and exact, the rigid slip's work -(Fx vx + Fy vy + Mz phi),
  /// which their cells then sum to (table_correction.hpp); 0 for linear-sdec, she-sdec, table.
  double frictional_work = 0.0;
  /// Method best: true where the totals came from the book of tables; false where the patch
  /// is outside it (table_outside says why) and FASTSIM-SDEC answered alone, or the exact
  /// theory (SolveOptions::exact_beyond_table; `exact` then holds its solution).
  bool from_table = false;
  std::optional<std::string> table_outside;
  /// Method exact, and best where the exact theory answered: the whole solution on its grid.
  std::optional<ExactSolution> exact;
};

/// "ok", "not converged", "no contact".
std::string_view status_name(SolveStatus status);

}  // namespace wheelwear::tangential
