#pragma once
/// Options, grids and results of the solvers of Kalker's exact theory (Kalker 1990).

#include <cstdint>
#include <string>
#include <vector>

#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential {

/// Most elements along either side of a grid (keeps the padded FFT arrays within memory).
inline constexpr int kMaxElementsPerSide = 4096;

/// A rectangular grid of nx x ny equal elements in the contact plane; element (i, j) has index
/// j*nx + i, i along x (rolling direction, the leading edge at +x), j along y. Coordinates are
/// relative to the initial contact point O [m].
struct ElementGrid {
  int nx = 0, ny = 0;               ///< elements along x and y, >= 1
  double x_min = 0.0, y_min = 0.0;  ///< lower-left corner of the grid [m]
  double dx = 0.0, dy = 0.0;        ///< element size [m], > 0

  void validate() const;                ///< throws InputError naming the bad field
  int size() const { return nx * ny; }  ///< number of elements
  double x(int i) const { return x_min + (i + 0.5) * dx; }  ///< centre of column i [m]
  double y(int j) const { return y_min + (j + 0.5) * dy; }  ///< centre of row j [m]
  double area() const { return dx * dy; }                   ///< element area [m^2]
};

/// The element grid exact_sdec lays over an SDEC patch.
struct SdecGridOptions {
  int nx = 80;  ///< elements along x over the potential contact area, 2 ... 4096
  int ny = 80;  ///< elements along y over the potential contact area, 1 ... 4096
  /// The potential contact area of an SDEC patch is [-margin a, margin a] x
  /// [y0 - margin b, y0 + margin b] around its mid-point O' (CONTACT's choice: 1.02); >= 1.
  double margin = 1.02;
  /// Offset of the grid from its centred position, in elements along x and y, in
  /// [-0.5, 0.5]: moves the element centres against the patch boundary (to study or average
  /// out how the grid samples the boundary).
  double shift_x = 0.0, shift_y = 0.0;

  void validate() const;  ///< throws InputError naming the bad field
};

/// Stopping tests of the normal and tangential iterations of the exact-theory solvers.
struct ExactSolverOptions {
  /// The tangential iteration stops when rms|p_k - p_(k-1)| <= tolerance * rms|p_k| over the
  /// contact elements and no element changed between adhesion and slip; > 0.
  double tolerance = 1e-6;
  /// The normal iteration stops when sum|p_k - p_(k-1)| dA <= normal_tolerance * N; > 0.
  double normal_tolerance = 1e-8;
  int max_iterations = 1000;  ///< cap on either iteration, >= 1

  void validate() const;  ///< throws InputError naming the bad field
};

/// Numerical outcome of a solve (a result, not an error).
enum class ExactStatus {
  converged,      ///< the stopping test was met
  not_converged,  ///< max_iterations reached; the last iterate is returned
  no_contact,     ///< no element carries pressure
};

/// "converged", "not converged" or "no contact" (as the command line prints it).
const char* status_name(ExactStatus status);

/// Per-element state of the tangential problem.
enum class ElementState : std::uint8_t { exterior = 0, adhesion = 1, slip = 2 };

/// Solution of the normal problem on a grid.
struct NormalSolution {
  ElementGrid grid;                              ///< the grid solved on
  std::vector<double> pn;                        ///< pressure per element [Pa], >= 0
  double approach = 0.0;                         ///< approach of the bodies (penetration) [m]
  double normal_force = 0.0;                     ///< sum of pn dA [N]
  ExactStatus status = ExactStatus::no_contact;  ///< numerical outcome
  int iterations = 0;                            ///< conjugate-gradient iterations
  std::string message;                           ///< why, when not converged
};

/// Solution of the steady-rolling tangential problem of Kalker's exact theory.
struct ExactSolution {
  /// Total forces on body 1 (the wheel), Kalker's convention (they oppose the creepages);
  /// Mz is the spin moment about O [N m] (always present).
  CreepForces forces;
  ElementGrid grid;                 ///< the grid solved on
  std::vector<double> pn;           ///< normal pressure per element [Pa]
  std::vector<double> px, py;       ///< tangential traction on body 1 [Pa]
  std::vector<double> sx, sy;       ///< slip (relative velocity / rolling speed) [-]
  std::vector<ElementState> state;  ///< exterior, adhesion or slip
  int contact_elements = 0;         ///< elements with pn > 0
  int adhesion_elements = 0;        ///< contact elements that adhere
  int slip_elements = 0;            ///< contact elements that slip
  double normal_force = 0.0;        ///< sum of pn dA of the grid [N]
  double frictional_work = 0.0;     ///< sum of |p| |s| dA: frictional work per rolled distance [N]
  /// The rigid-slip work of a per-row longitudinal creepage (exact_rolling's row_vx) beyond that
  /// of the creepages at O, -sum_j row_vx_j Fx_j over the rows' forces Fx_j [N]; 0 without.
  double row_creepage_work = 0.0;
  ExactStatus status = ExactStatus::no_contact;  ///< numerical outcome
  int iterations = 0;   ///< tangential iterations (sweeps; of both tries on long elements)
  double change = 0.0;  ///< last rms|p_k - p_(k-1)| / rms|p_k| [-]
  std::string message;  ///< why, when not converged or without contact
};

}  // namespace wheelwear::tangential
