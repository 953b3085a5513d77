#pragma once
/// Kalker's exact theory on one wheel/rail contact patch: the undeformed distance of the wheel
/// and its rail (contactgeom::undeformed_distance, yaw included) sampled on an element grid in
/// the patch's contact plane, the normal problem at the patch's normal force, then steady
/// rolling with the creepages at the patch's O (the chain of Vollebregt's CONTACT, wheel/rail
/// module with planar contact, with the patch located by contactgeom).

#include <vector>

#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

/// Grid and solver options of wheel_rail_exact.
struct WheelRailExactOptions {
  int nx = 40;  ///< elements along x (rolling direction) over the grid, 4 ... 1000
  int ny = 40;  ///< elements along the lateral contact coordinate s over the grid, 4 ... 1000
  /// The grid is the Kik-Piotrowski patch (its length and its lateral extent W2 + W1 about O)
  /// widened by this factor about its centre, 1 ... 5. The exact contact area differs from the
  /// patch it is sized from (virtual penetration is an approximation), hence more than
  /// CONTACT's 1.02 for a known patch.
  double margin = 1.3;
  /// Whether the longitudinal rigid slip follows the wheel's rolling radius across the patch.
  /// The planar theory (and CONTACT's planar wheel/rail contact) takes the radius linear in s,
  /// which the spin creepage accounts for; where a wide conformal patch spans a curved tread
  /// (a hollow-worn wheel) the radius departs from that line by up to a millimetre, a
  /// longitudinal creepage of order 1e-3 that varies across the patch. true adds it to each
  /// row: -(r(s) - r_O - r'_O s) / r_O (WheelRailExactSolution::row_vx).
  bool radius_variation = false;
  ExactSolverOptions solver;  ///< stopping tests of the normal and tangential iterations

  void validate() const;  ///< throws InputError naming the bad field
};

/// The exact solution of one wheel/rail patch.
struct WheelRailExactSolution {
  /// Forces (on the wheel, Kalker's convention, Mz about O), pressure, tractions, slip and
  /// element states. Its grid's coordinates: x along the track, y the lateral coordinate s in
  /// the contact plane, + towards the gauge side (as WheelRailPatch's s), origin at O.
  ExactSolution rolling;
  std::vector<double> h;  ///< undeformed distance along the contact normal per element [m],
                          ///< from the least distance in O's cross-section
  /// Approach of the bodies along the contact normal [m], beyond the least undeformed distance
  /// in O's cross-section (for a quadratic gap: Hertz's delta).
  double approach = 0.0;
  /// With WheelRailExactOptions::radius_variation: the longitudinal creepage added to each row
  /// of the grid (its lateral coordinate s, row j), the wheel's rolling radius departing from
  /// its tangent at O; empty otherwise.
  std::vector<double> row_vx;
  int normal_iterations = 0;       ///< iterations of the normal problem
  double contact_area = 0.0;       ///< contact elements times the element area [m^2]
  double adhesion_fraction = 0.0;  ///< adhesion elements / contact elements [-]
};

/// The element grid wheel_rail_exact solves `patch` on: x centred on `x_centre` [m] (where the
/// undeformed distance is least in O's cross-section; 0 without yaw), s centred on the patch's
/// lateral mid-point (W1 - W2)/2 from O, extents margin times the patch's length and width.
/// Throws InputError on bad options or a patch with non-finite or zero measures.
ElementGrid wheel_rail_exact_grid(const contactgeom::WheelRailPatch& patch, double x_centre,
                                  const WheelRailExactOptions& options = {});

/// Solves `patch` (found by contactgeom::solve_wheel_rail for `pair` at `pose`) with Kalker's
/// exact theory: normal force patch.normal_force, friction `mu` [-], creepages at O
/// `creepages` (vx, vy [-], phi [1/m]; w = (vx - phi s, vy + phi x)), the material of `pair`
/// (G = E / (2 (1 + nu))). Throws InputError on bad input (naming it), and when the contact
/// area reaches the grid's border or the end of a profile (the message says which edge and
/// how to fix it). A solve that does not converge returns its status in rolling.status.
WheelRailExactSolution wheel_rail_exact(const contactgeom::WheelRailPair& pair,
                                        const contactgeom::WheelsetPose& pose,
                                        const contactgeom::WheelRailPatch& patch,
                                        const Creepages& creepages, double mu,
                                        const WheelRailExactOptions& options = {});

}  // namespace wheelwear::tangential
