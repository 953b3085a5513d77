#pragma once
// The energy balance of a patch: the frictional work the wear laws read, the cells' sum
// W = sum |tau| |s| dA (J/m), against the work of the rigid slip, -(Fx vx + Fy vy + Mz phi),
// with each method's own forces and spin moment about O (docs/architecture.md, "Patch frame").
//
// Why they are equal. In steady rolling the slip is the rigid slip w = (vx - phi y, vy + phi x)
// plus the elastic part, the derivative of the displacement along the rolling direction. Where
// the surfaces slip the traction opposes the slip, so |tau| |s| = -tau . s, and
//   W = -integral tau . w dA - integral tau . (elastic part) dA
//     = -(Fx vx + Fy vy + phi integral (x tau_y - y tau_x) dA) - 0,
// the last integral being Mz (about O, as every method reports it). The elastic part does no
// net work in the continuum: its operator is antisymmetric. What each discretisation makes of
// that:
//
// - FASTSIM family (Kalker 1982; Liu, Fu & Bruni 2022, Eq. 15-18). Along a strip, at marching
//   distance t from the leading edge, the traction grows at the rate R of the rigid slip divided
//   by the flexibilities, R = -(vx/L11 - phi y/L13, vy/L22 + phi x/L23); where the bound removes
//   part of it (at the rate lambda) the slip is s = -L lambda p/|p|, with one slip flexibility L
//   (fastsim.cpp: the flexibilities weighted by the squares of the creepages). Then
//   d(|p|^2/2)/dt = p.R - lambda |p| and |p| = 0 at both ends of the strip, so the cells' work
//   tends to the power of the model's own slip, W_model = L sum p.R dA. It is the rigid slip's
//   work only where every rate has the flexibility L: a single translational creepage (one
//   flexibility), and spin with L13 = L23 (classic FASTSIM: EQ.L, EQ.E, elliptic; EQ.E shifted
//   only with psi = 0, since its shift puts vx' = -phi psi b beside the spin).
//   Kalker's march (each cell's traction at its trailing node, the work with the mean of the
//   cell's end tractions) makes a translational creepage's sum telescope exactly:
//   (p_(i-1) + d - p_i)(p_(i-1) + p_i) = p_(i-1)^2 - p_i^2 + d (p_(i-1) + p_i), so the balance
//   holds to rounding on every grid. Under spin the traction turns and the trapezoidal work is
//   second-order accurate: the balance error falls as (cell size)^2.
//   The spin moment is reported by every FASTSIM method, so spin is tested everywhere.
// - exact (Kalker's exact theory): the raw sum of |p| |s| dA converges only to first order
//   (Kalker's backward difference; the spin term of the rigid slip dx/6 upstream), so its cells
//   carry one factor that makes them sum to the rigid slip's work of the totals
//   (exact_fields.hpp). The cells then balance to rounding, the factor tends to 1 at first
//   order, and an unconverged iterate moves the work by the solver's stopping tolerance.
// - best: inside the book of tables the same construction on the table's totals (rounding);
//   outside it FASTSIM-SDEC, whose balance it then has.
//
// Found: FASTSIM-SDEC under spin and every FASTSIM variant under combined creepage (and EQ.E
// shifted under spin with psi != 0) do not balance in the limit of a fine grid: their work is
// the model's W_model, which differs from the rigid slip's by 3.8-14.4 %. Those tests skip with the
// measured gaps while the defect is there (SdecSpin... and CombinedCreepage... in
// frictional_work_fastsim_test.cpp).
//
// This header holds what the balance tests share: the patches, the creepage cases, the solve and
// its balance, and FASTSIM's model work; frictional_work_fastsim_test.cpp tests the FASTSIM
// family, frictional_work_exact_test.cpp Kalker's exact theory and best.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "wheelwear/tangential/kalker_coefficients.hpp"
#include "wheelwear/tangential/sdec_coefficients.hpp"
#include "wheelwear/tangential/table_correction.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::tangential::frictional_work {

using contactgeom::Sdec;

inline const Material kSteel{80e9, 0.25};
// The paper's a = 4.25 mm (Liu, Fu & Bruni 2022, Section 5): an ellipse (a/b = 0.71) and an
// SDEC region reaching further on the gauge side (psi = 0.6).
inline const Sdec kEllipse{4.25e-3, 6.0e-3, 0.0};
inline const Sdec kSdecRegion{4.25e-3, 4.25e-3, 0.6};
inline const std::vector<Sdec> kPatches = {kEllipse, kSdecRegion};

// p0 = 1000 MPa, as the reference data (N = 2/3 p0 pi a b), mu = 0.35 as in the paper.
inline ContactLoad load_of(const Sdec& patch) {
  return {2.0 / 3.0 * 1e9 * std::numbers::pi * patch.a * patch.b, 0.35};
}

enum class Regime { partial_slip, near_full_slip };

struct Case {
  std::string name;
  Creepages v;
  Regime regime;
};

// Creepages at O. Saturation of a translational creepage lies near 3 mu N/(G c^2 C11) = 7e-3 on
// these patches; the spin's slip area covers the patch near phi = 2.5 1/m, which keeps every
// case inside the book of tables (best).
inline const Case kLongitudinalPartial{
    "longitudinal, partial slip", {1.5e-3, 0, 0}, Regime::partial_slip};
inline const Case kLongitudinalNear{
    "longitudinal, near full slip", {6e-3, 0, 0}, Regime::near_full_slip};
inline const Case kLateralPartial{"lateral, partial slip", {0, 1.5e-3, 0}, Regime::partial_slip};
inline const Case kLateralNear{"lateral, near full slip", {0, 6e-3, 0}, Regime::near_full_slip};
inline const Case kSpinPartial{"spin, partial slip", {0, 0, 1.0}, Regime::partial_slip};
inline const Case kSpinNear{"spin, near full slip", {0, 0, 2.5}, Regime::near_full_slip};
inline const Case kCombinedPartial{
    "combined, partial slip", {1e-3, -8e-4, 0.8}, Regime::partial_slip};
inline const Case kCombinedNear{
    "combined, near full slip", {4e-3, 3e-3, 2.0}, Regime::near_full_slip};

inline const std::vector<Case> kTranslational = {kLongitudinalPartial, kLongitudinalNear,
                                                 kLateralPartial, kLateralNear};
inline const std::vector<Case> kSpin = {kSpinPartial, kSpinNear};
inline const std::vector<Case> kCombined = {kCombinedPartial, kCombinedNear};
inline const std::vector<Case> kAllCases = {
    kLongitudinalPartial, kLongitudinalNear, kLateralPartial,  kLateralNear,
    kSpinPartial,         kSpinNear,         kCombinedPartial, kCombinedNear};

inline const std::vector<Method> kFastsimMethods = {
    Method::fastsim_sdec, Method::fastsim_eql, Method::fastsim_eqe, Method::fastsim_eqe_shifted,
    Method::fastsim_elliptic};

// Grids of the refinement studies: cells per strip and strips, n x n, halving the cell size.
inline const std::vector<int> kRefinement = {25, 50, 100, 200};
inline constexpr int kDefaultGrid = 50;  // FastsimOptions' default nx = ny

// The work of the rigid slip, -(Fx vx + Fy vy + Mz phi) [N], written out here rather than taken
// from rigid_slip_work (which best and exact use to build their cells).
inline double rigid_work(const CreepForces& f, const Creepages& v) {
  return -(f.Fx * v.vx + f.Fy * v.vy + f.Mz.value() * v.phi);
}

// One solve with its cells and what the balance compares.
struct Balance {
  double cells = 0.0;     // sum of work * dx * dy over the cells [N]
  double reported = 0.0;  // TangentialSolution::frictional_work [N]
  double rigid = 0.0;     // -(Fx vx + Fy vy + Mz phi) [N]
  double model = 0.0;     // FASTSIM's W_model (model_work), 0 for other methods [N]
  double slip_fraction = 0.0;
  TangentialSolution solution;

  double error() const { return cells / rigid - 1.0; }  // the balance's relative error
  double model_error() const { return cells / model - 1.0; }
};

// The flexibilities of a FASTSIM variant (Liu, Fu & Bruni 2022, Eq. 17; classic FASTSIM has
// L13 = L23) and the creepages and spin origin its strips see (EQ.E shifted: at O' = O + psi b,
// vx' = vx - phi psi b, Eq. 10).
struct Model {
  double l11 = 0.0, l13 = 0.0, l22 = 0.0, l23 = 0.0;  // [m/Pa]
  Creepages v;                                        // at the spin origin
  double spin_origin = 0.0;                           // [m] from O
  // fastsim.cpp's slip flexibility: L11, L22, L23 weighted by vx^2, vy^2, c^2 phi^2.
  double slip_flexibility(double c) const {
    const double wx = v.vx * v.vx, wy = v.vy * v.vy, wphi = c * c * v.phi * v.phi;
    return (wx * l11 + wy * l22 + wphi * l23) / (wx + wy + wphi);
  }
};

inline Model model_of(FastsimMethod variant, const Sdec& patch, const Creepages& v) {
  const double a = patch.a, c = patch.c(), G = kSteel.G;
  double c11 = 0.0, c22 = 0.0, c23 = 0.0;
  std::optional<double> k13;
  if (variant == FastsimMethod::sdec) {
    const SdecCoefficients k = sdec_coefficients(patch, kSteel.nu);
    c11 = k.c11s;
    c22 = k.c22s;
    c23 = k.c23s;
    k13 = k.row.k13;
  } else {
    const KalkerCoefficients k = kalker_coefficients(patch.ellipticity(), kSteel.nu);
    c11 = k.c11;
    c22 = k.c22;
    c23 = k.c23;
  }
  Model m;
  m.l11 = 8.0 * a / (3.0 * G * c11);
  m.l22 = 8.0 * a / (3.0 * G * c22);
  m.l23 = std::numbers::pi * a * a / (4.0 * G * c * c23);
  m.l13 = k13 ? 2.0 * c / (G * *k13) : m.l23;
  m.v = v;
  if (variant == FastsimMethod::eqe_shifted) {
    m.spin_origin = patch.y0();
    m.v.vx = v.vx - v.phi * m.spin_origin;
  }
  return m;
}

// W_model = L sum p.R dA: the power of the model's slip, to which FASTSIM's cells' work
// converges (see the top of the file), from the totals and the cells' moments about the spin
// origin: sum x p_y dA = Mz + sum y p_x dA (x of each traction's node as the march counts it).
inline double model_work(FastsimMethod variant, const Sdec& patch, const Creepages& v,
                         const TangentialSolution& s) {
  const CellFields& f = *s.fields;
  double y_px = 0.0;  // sum of y p_x dA about O [N m]
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i)
      y_px += f.strip_y[static_cast<std::size_t>(j)] *
              f.px[static_cast<std::size_t>(j) * f.nx + i] * f.dx[static_cast<std::size_t>(j)] *
              f.dy;
  const double x_py = s.forces.Mz.value() + y_px;
  const Model m = model_of(variant, patch, v);
  const double y_px_spin = y_px - m.spin_origin * s.forces.Fx;
  return -m.slip_flexibility(patch.c()) *
         (m.v.vx * s.forces.Fx / m.l11 + m.v.vy * s.forces.Fy / m.l22 +
          m.v.phi * (x_py / m.l23 - y_px_spin / m.l13));
}

inline SolveOptions grid_options(int n, FastsimScheme scheme = FastsimScheme::kalker) {
  SolveOptions o;
  o.fastsim.nx = o.fastsim.ny = n;
  o.fastsim.scheme = scheme;
  o.fastsim.cell_fields = true;
  o.exact_grid.nx = o.exact_grid.ny = n;
  return o;
}

inline Balance balance(Method method, const Sdec& patch, const Creepages& v,
                       const SolveOptions& o) {
  Balance b;
  b.solution = solve_patch(method, patch, v, load_of(patch), kSteel, o);
  const TangentialSolution& s = b.solution;
  const CellFields& f = s.fields.value();
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i)
      b.cells +=
          f.work[static_cast<std::size_t>(j) * f.nx + i] * f.dx[static_cast<std::size_t>(j)] * f.dy;
  b.reported = s.frictional_work;
  b.rigid = rigid_work(s.forces, v);
  b.slip_fraction = static_cast<double>(s.slip_cells) / s.cells;
  if (const auto variant = fastsim_variant(method); variant && method != Method::best)
    b.model = model_work(*variant, patch, v, s);
  return b;
}

inline std::string describe(Method method, const Sdec& patch, const Case& c, int n = 0) {
  std::ostringstream out;
  out << method_name(method) << ", psi " << patch.psi << ", " << c.name;
  if (n > 0) out << ", " << n << " x " << n;
  return out.str();
}

// The observed order of convergence between grids n and 2n: log2(e(n)/e(2n)).
inline double observed_order(double coarse, double fine) {
  return std::log2(std::abs(coarse) / std::abs(fine));
}

// Cells' sums against the totals over up to 200 x 200 cells, summed in another order:
// rounding (measured below 2e-14).
inline constexpr double kRounding = 1e-12;

// The two slip regimes of the cases, as FASTSIM's slip area (fraction of the cells) shows them,
// so that the cases test what their names say. Measured 0.24-0.65 and 0.79-1.
inline void expect_regime(const Case& c, const Balance& b, const std::string& what) {
  if (c.regime == Regime::partial_slip) {
    EXPECT_GT(b.slip_fraction, 0.15) << what;
    EXPECT_LT(b.slip_fraction, 0.7) << what;
  } else {
    EXPECT_GT(b.slip_fraction, 0.75) << what;
  }
}

}  // namespace wheelwear::tangential::frictional_work
