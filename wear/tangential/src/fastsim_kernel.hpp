#pragma once
// The strip-marching core shared by every FASTSIM variant (internal header).

#include <vector>

#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::tangential::detail {

/// The patch as ny strips of equal width dy: per strip its leading edge x_l (the strip spans
/// [-x_l, x_l]), its lateral position relative to O (for moments and output) and the lateral
/// coordinate that enters the spin terms of the rigid slip.
struct StripGrid {
  int nx = 0;
  int ny = 0;
  double dy = 0.0;
  std::vector<double> x_lead;  // [m]
  std::vector<double> y_at_o;  // [m]
  std::vector<double> y_spin;  // [m]

  void resize(int strips) {
    ny = strips;
    x_lead.resize(strips);
    y_at_o.resize(strips);
    y_spin.resize(strips);
  }
};

/// Inverse flexibilities of the simplified theory (1/L in Pa/m): the unsaturated tractions
/// are px = (vx/L11 - phi y/L13)(x - x_l), py = vy/L22 (x - x_l) + phi/(2 L23)(x^2 - x_l^2).
struct Flexibilities {
  double inv_l11 = 0.0, inv_l13 = 0.0, inv_l22 = 0.0, inv_l23 = 0.0;
  double effective = 0.0;  // single flexibility [m/Pa] that converts excess traction into slip
};

/// Rate of change of the unsaturated px along the marching distance t = x_l - x, on a strip at
/// spin coordinate y_spin: -(vx/L11 - phi y/L13) (Eq. 15), constant along the strip.
inline double px_rate(const Creepages& v, const Flexibilities& flex, double y_spin) {
  return -(v.vx * flex.inv_l11 - v.phi * y_spin * flex.inv_l13);
}

/// Traction bound: parabolic coefficient * (x_l^2 - x^2), or coefficient * sqrt(x_l^2 - x^2).
struct BoundLaw {
  TractionBound kind = TractionBound::parabolic;
  double coefficient = 0.0;
};

/// Totals of one march.
struct MarchTotals {
  double Fx = 0.0, Fy = 0.0, Mz = 0.0;  // Mz about O
  int slip_cells = 0;
  double work = 0.0;  // sum of |p||s| dA [N], only when fields are filled

  // Strip sums carry dx; the strip width dy multiplies them all at the end.
  void scale_by_strip_width(double dy) {
    Fx *= dy;
    Fy *= dy;
    Mz *= dy;
    work *= dy;
  }
};

/// Sizes the per-cell fields of `set` for an nx x ny grid of strip width dy and empties the
/// others (keeping their storage); zeroes them when `zero`, for marches that write only the
/// cells that slip.
void prepare_fields(CellFields& fields, int nx, int ny, double dy, bool zero, CellFieldSet set);

/// Marches every strip from its leading to its trailing edge (Kalker 1982): forces only.
MarchTotals march(const StripGrid& grid, const Creepages& creepages, const Flexibilities& flex,
                  const BoundLaw& bound);

/// The same march, also filling the per-cell fields of `set` (every cell; the pressure is left
/// to the caller); fastsim_fields.cpp.
MarchTotals march_with_fields(const StripGrid& grid, const Creepages& creepages,
                              const Flexibilities& flex, const BoundLaw& bound, CellFieldSet set,
                              CellFields& fields);

/// Second-order marching of every strip (FastsimScheme::second_order); fills `fields` when it
/// is not null.
MarchTotals march_second_order(const StripGrid& grid, const Creepages& creepages,
                               const Flexibilities& flex, const BoundLaw& bound,
                               CellFields* fields);

}  // namespace wheelwear::tangential::detail
