#include "wheelwear/tangential/fastsim.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/linear_theory.hpp"

namespace wheelwear::tangential {
namespace {

using contactgeom::Sdec;

const Material kSteel{80e9, 0.25};
const ContactLoad kLoad{37830.0, 0.35};
const Sdec kSdec{4.25e-3, 4.25e-3, 0.6};
const Sdec kEllipse{4.25e-3, 6.0e-3, 0.0};

// The same arithmetic along two code paths (classic FASTSIM and a variant that reduces to it,
// the wear field set and the full one): equal to rounding.
constexpr double kSameArithmetic = 1e-12;  // [relative, or fraction of N]
// Sums of per-cell quantities against totals summed in another order, and mirror-image strip
// grids: rounding accumulated over a few thousand cells.
constexpr double kReordered = 1e-9;  // [fraction of N]

FastsimOptions grid(int nx, int ny) {
  FastsimOptions options;
  options.nx = nx;
  options.ny = ny;
  return options;
}

CreepForces solve(FastsimMethod method, const Sdec& patch, const Creepages& v,
                  const FastsimOptions& options = grid(50, 50), const ContactLoad& load = kLoad) {
  return fastsim(method, patch, v, load, kSteel, options).forces;
}

// Kalker's marching puts each cell's traction at its trailing node, and the last node lies on
// the trailing edge, where the bound is zero. For a creepage-only traction, linear in x along
// every strip, the sum is then the exact integral times (1 - 1/nx): a first-order error with
// unit coefficient, independent of the strip.
TEST(FastsimLinearLimit, LongitudinalForceConvergesAtFirstOrderWithKnownCoefficient) {
  const Creepages tiny{1e-9, 0, 0};
  const double exact = linear_sdec_forces(kSdec, tiny, kSteel).Fx;
  double previous_error = 0.0;
  for (int nx : {10, 20, 40, 80}) {
    const double fx = solve(FastsimMethod::sdec, kSdec, tiny, grid(nx, 1000)).Fx;
    const double error = fx / exact - 1;
    // 1e-5: the midpoint rule's error over 1000 strips of the quadratic x_l^2(y).
    EXPECT_NEAR(error, -1.0 / nx, 1e-5) << "nx = " << nx;
    if (previous_error != 0.0) {
      EXPECT_NEAR(previous_error / error, 2.0, 0.01);  // rate 1
    }
    previous_error = error;
  }
}

// The spin part of py, phi/(2 L23)(x^2 - x_l^2), vanishes at both ends of a strip, so neither
// the trailing-node sum nor the zero bound at the trailing edge adds a first-order term: Fy
// converges at second order.
TEST(FastsimLinearLimit, SpinLateralForceConvergesAtSecondOrder) {
  const Creepages tiny{0, 0, 1e-7};
  const CreepForces exact = linear_sdec_forces(kSdec, tiny, kSteel);
  double previous_error = 0.0;
  for (int nx : {10, 20, 40}) {
    const CreepForces f = solve(FastsimMethod::sdec, kSdec, tiny, grid(nx, 2000));
    const double error = std::abs(f.Fy / exact.Fy - 1);
    // The spin part of px is linear in x, like vx's: Fx keeps the (1 + 1/nx) factor.
    EXPECT_NEAR(f.Fx / exact.Fx - 1, -1.0 / nx, 2e-4) << "nx = " << nx;
    if (previous_error != 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.2);  // rate 2
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-3);
}

// FASTSIM-SDEC differs from classic FASTSIM only through L13, which multiplies the spin.
TEST(FastsimAtZeroPsi, EqualsClassicFastsimWithoutSpin) {
  for (const Creepages v :
       {Creepages{1e-4, 0, 0}, Creepages{2e-3, -1e-3, 0}, Creepages{0.05, 0.02, 0}}) {
    const CreepForces sdec = solve(FastsimMethod::sdec, kEllipse, v);
    const CreepForces classic = solve(FastsimMethod::elliptic, kEllipse, v);
    EXPECT_NEAR(sdec.Fx, classic.Fx, kSameArithmetic * kLoad.N);
    EXPECT_NEAR(sdec.Fy, classic.Fy, kSameArithmetic * kLoad.N);
  }
}

// At psi = 0 the spin-induced px is odd in y and its net Fx vanishes; in the linear regime
// py is classic FASTSIM's, so Fy agrees too.
TEST(FastsimAtZeroPsi, SpinGivesNoNetLongitudinalForce) {
  const Creepages tiny_spin{0, 0, 1e-6};
  const CreepForces sdec = solve(FastsimMethod::sdec, kEllipse, tiny_spin);
  const CreepForces classic = solve(FastsimMethod::elliptic, kEllipse, tiny_spin);
  EXPECT_NEAR(sdec.Fx, 0.0, kSameArithmetic * kLoad.N);
  EXPECT_NEAR(sdec.Fy, classic.Fy, kSameArithmetic * std::abs(classic.Fy));
  const CreepForces strong = solve(FastsimMethod::sdec, kEllipse, {0, 0, 2.0});
  EXPECT_NEAR(strong.Fx, 0.0, 1e-10 * kLoad.N);
}

// EQ.E, EQ.E-shifted and EQ.L are classic FASTSIM when the patch is an ellipse.
TEST(FastsimAtZeroPsi, ComparatorsReduceToClassicFastsim) {
  const Creepages v{1e-3, -5e-4, 0.8};
  const CreepForces classic = solve(FastsimMethod::elliptic, kEllipse, v);
  for (FastsimMethod m : {FastsimMethod::eqe, FastsimMethod::eqe_shifted, FastsimMethod::eql}) {
    const CreepForces f = solve(m, kEllipse, v);
    EXPECT_NEAR(f.Fx, classic.Fx, kSameArithmetic * kLoad.N) << method_name(m);
    EXPECT_NEAR(f.Fy, classic.Fy, kSameArithmetic * kLoad.N) << method_name(m);
    EXPECT_NEAR(*f.Mz, *classic.Mz, 1e-15 * kLoad.N) << method_name(m);
  }
}

// Mirroring the patch (psi -> -psi) mirrors the spin-induced Fx and keeps Fy; the strip grids
// are mirror images, so agreement is to rounding.
TEST(FastsimSymmetry, MirroringPsiMirrorsSpinInducedFx) {
  for (FastsimMethod m : {FastsimMethod::sdec, FastsimMethod::eql, FastsimMethod::eqe_shifted}) {
    for (double phi : {0.2, 1.0, 1.6}) {
      const CreepForces plus = solve(m, Sdec{4.25e-3, 5e-3, 0.6}, {0, 0, phi});
      const CreepForces minus = solve(m, Sdec{4.25e-3, 5e-3, -0.6}, {0, 0, phi});
      EXPECT_NEAR(plus.Fx, -minus.Fx, kReordered * kLoad.N) << method_name(m);
      EXPECT_NEAR(plus.Fy, minus.Fy, kReordered * kLoad.N) << method_name(m);
      EXPECT_GT(plus.Fx, 0.0);
    }
  }
}

// Saturation: large translational creepage slides the whole patch, |F| -> mu N. The bound
// sums at trailing nodes of a function vanishing at both strip ends: second-order accurate,
// so 100x100 lies within 2e-3 of mu N and halving the cell size divides the error by ~4.
TEST(FastsimSaturation, LargeCreepageReachesMuN) {
  const double limit = kLoad.mu * kLoad.N;
  for (FastsimMethod m : {FastsimMethod::sdec, FastsimMethod::eql, FastsimMethod::eqe,
                          FastsimMethod::eqe_shifted, FastsimMethod::elliptic}) {
    const CreepForces f = solve(m, kSdec, {0.05, 0, 0}, grid(100, 100));
    EXPECT_NEAR(std::hypot(f.Fx, f.Fy) / limit, 1.0, 2e-3) << method_name(m);
    EXPECT_LT(f.Fx, 0.0);
  }
  const double e1 =
      std::abs(solve(FastsimMethod::sdec, kSdec, {10, 0, 0}, grid(20, 400)).Fx / limit + 1);
  const double e2 =
      std::abs(solve(FastsimMethod::sdec, kSdec, {10, 0, 0}, grid(40, 400)).Fx / limit + 1);
  EXPECT_NEAR(e1 / e2, 4.0, 0.5);
}

// The semi-elliptic bound mu p_n also integrates to mu N.
TEST(FastsimSaturation, SemiEllipticBoundIntegratesToMuN) {
  FastsimOptions options = grid(200, 200);
  options.bound = TractionBound::semi_elliptic;
  const CreepForces f = solve(FastsimMethod::sdec, kSdec, {0, 10, 0}, options);
  // The sqrt edge of p_n makes the node sum converge at order 1.5: 3e-3 at 200 cells.
  EXPECT_NEAR(-f.Fy / (kLoad.mu * kLoad.N), 1.0, 3e-3);
}

// Pure spin never reaches mu N: the spin-induced tractions turn around the patch and cancel.
// (Like CONTACT's set b1, |F| peaks near phi = 1.5 1/m and then falls.)
TEST(FastsimSaturation, PureSpinStaysBelowMuN) {
  const double limit = kLoad.mu * kLoad.N;
  for (double phi : {0.5, 1.0, 2.0, 5.0, 20.0, 200.0}) {
    const CreepForces f = solve(FastsimMethod::sdec, kSdec, {0, 0, phi});
    EXPECT_LT(std::hypot(f.Fx, f.Fy) / limit, 0.9) << "phi = " << phi;
  }
}

// The per-cell fields add up to the totals, and frictional work appears only where cells slip.
TEST(FastsimFields, AddUpToTheTotalsAndDissipateOnlyInSlip) {
  FastsimOptions options = grid(40, 30);
  options.cell_fields = true;
  const Creepages v{1e-3, 5e-4, 0.8};
  const TangentialSolution s = fastsim(FastsimMethod::sdec, kSdec, v, kLoad, kSteel, options);
  ASSERT_TRUE(s.fields.has_value());
  const CellFields& c = *s.fields;
  double fx = 0, fy = 0;
  int slipping = 0;
  for (int j = 0; j < c.ny; ++j) {
    for (int i = 0; i < c.nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * c.nx + i;
      fx += c.px[k] * c.dx[j] * c.dy;
      fy += c.py[k] * c.dx[j] * c.dy;
      slipping += c.slip[k];
      EXPECT_GE(c.work[k], 0.0);
      if (c.slip[k]) {
        // Coulomb: in slip the traction opposes the slip.
        EXPECT_LE(c.px[k] * c.sx[k] + c.py[k] * c.sy[k], 0.0);
      } else {
        EXPECT_EQ(c.work[k], 0.0);
      }
    }
  }
  EXPECT_NEAR(fx, s.forces.Fx, kReordered * kLoad.N);
  EXPECT_NEAR(fy, s.forces.Fy, kReordered * kLoad.N);
  EXPECT_EQ(slipping, s.slip_cells);
  const TangentialSolution forces_only =
      fastsim(FastsimMethod::sdec, kSdec, v, kLoad, kSteel, grid(40, 30));
  EXPECT_NEAR(forces_only.forces.Fx, s.forces.Fx, kReordered * kLoad.N);
  EXPECT_EQ(forces_only.slip_cells, s.slip_cells);
}

// The slip magnitude and the strip positions are stored as such; the wear field set fills
// the same numbers for what it fills and leaves the rest empty.
TEST(FastsimFields, WearFieldSetMatchesTheFullSet) {
  for (const FastsimScheme scheme : {FastsimScheme::kalker, FastsimScheme::second_order}) {
    FastsimOptions options = grid(37, 21);  // neither a multiple of the march's blocks of 8
    options.cell_fields = true;
    options.scheme = scheme;
    const Creepages v{1e-3, 5e-4, 0.8};
    const TangentialSolution all = fastsim(FastsimMethod::sdec, kSdec, v, kLoad, kSteel, options);
    options.field_set = CellFieldSet::wear;
    const TangentialSolution wear = fastsim(FastsimMethod::sdec, kSdec, v, kLoad, kSteel, options);
    const CellFields& a = *all.fields;
    const CellFields& w = *wear.fields;
    ASSERT_EQ(a.slip_norm.size(), 37u * 21u);
    ASSERT_EQ(w.work.size(), a.work.size());
    ASSERT_EQ(w.pressure.size(), a.pressure.size());
    if (scheme == FastsimScheme::kalker) {
      EXPECT_TRUE(w.px.empty() && w.sx.empty() && w.x.empty() && w.slip.empty());
    }
    for (std::size_t k = 0; k < a.work.size(); ++k) {
      // 4e-16: hypot of the components against the magnitude they were scaled from, a few
      // roundings of the slip (at most ~1e-2 here) apart.
      EXPECT_NEAR(a.slip_norm[k], std::hypot(a.sx[k], a.sy[k]), 1e-13 * a.slip_norm[k] + 1e-300);
      // The same arithmetic in both sets: equal to rounding.
      EXPECT_NEAR(w.work[k], a.work[k], kSameArithmetic * a.work[k]);
      EXPECT_NEAR(w.slip_norm[k], a.slip_norm[k], kSameArithmetic * a.slip_norm[k]);
      EXPECT_DOUBLE_EQ(w.pressure[k], a.pressure[k]);
    }
    for (int j = 0; j < a.ny; ++j) {
      EXPECT_EQ(a.strip_y[j], a.y[static_cast<std::size_t>(j) * a.nx]);
      EXPECT_EQ(w.strip_y[j], a.strip_y[j]);
      EXPECT_EQ(w.dx[j], a.dx[j]);
    }
    EXPECT_NEAR(wear.forces.Fx, all.forces.Fx, kSameArithmetic * kLoad.N);
    EXPECT_NEAR(wear.frictional_work, all.frictional_work, kSameArithmetic * all.frictional_work);
  }
}

// In full sliding under a uniform creepage vx the work done per rolled metre is mu N |vx|
// (energy balance); the discrete sum telescopes to it up to the bound's quadrature error.
TEST(FastsimFields, FullSlidingDissipatesMuNTimesCreepage) {
  FastsimOptions options = grid(100, 100);
  options.cell_fields = true;
  const double vx = 0.05;
  const TangentialSolution s =
      fastsim(FastsimMethod::sdec, kSdec, {vx, 0, 0}, kLoad, kSteel, options);
  EXPECT_NEAR(s.frictional_work / (kLoad.mu * kLoad.N * vx), 1.0, 5e-3);
}

// Energy balance in steady rolling: the frictional work per rolled metre, summed cell by cell,
// equals -(Fx vx + Fy vy + Mz phi). It holds for a single creepage at any slip level (a single
// flexibility relates traction and slip there); 1 % at 100 x 100 covers the cell quadrature.
TEST(FastsimFields, FrictionalWorkBalancesTheCreepForcesPower) {
  FastsimOptions options = grid(100, 100);
  options.cell_fields = true;
  for (const Creepages v : {Creepages{1e-3, 0, 0}, Creepages{3e-3, 0, 0}, Creepages{0, -2e-3, 0}}) {
    const TangentialSolution s = fastsim(FastsimMethod::sdec, kSdec, v, kLoad, kSteel, options);
    const double power = -(s.forces.Fx * v.vx + s.forces.Fy * v.vy + *s.forces.Mz * v.phi);
    EXPECT_NEAR(s.frictional_work / power, 1.0, 0.01) << v.vx << " " << v.vy;
  }
}

TEST(FastsimInput, RejectsInvalidInput) {
  const Creepages v{0, 0, 1};
  EXPECT_THROW(solve(FastsimMethod::sdec, Sdec{4e-3, 4e-3, 1.0}, v), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, Sdec{4e-3, 4e-3, -1.2}, v), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, Sdec{0.0, 4e-3, 0.0}, v), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, Sdec{4e-3, -4e-3, 0.0}, v), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, kSdec, v, grid(50, 50), {0.0, 0.3}), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, kSdec, v, grid(50, 50), {1e4, -0.3}), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, kSdec, {std::nan(""), 0, 0}), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, kSdec, {0, INFINITY, 0}), InputError);
  EXPECT_THROW(solve(FastsimMethod::sdec, kSdec, v, grid(0, 50)), InputError);
}

TEST(FastsimInput, MethodNamesRoundTrip) {
  for (FastsimMethod m : {FastsimMethod::sdec, FastsimMethod::eql, FastsimMethod::eqe,
                          FastsimMethod::eqe_shifted, FastsimMethod::elliptic}) {
    EXPECT_EQ(parse_fastsim_method(method_name(m)), m);
  }
  EXPECT_FALSE(parse_fastsim_method("fastsim").has_value());
}

}  // namespace
}  // namespace wheelwear::tangential
