// Properties of the steady-rolling solution that hold whatever the grid: Coulomb's law in every
// element, saturation at mu N, mirror symmetry in psi, similarity under a change of length
// scale, and agreement of the prescribed-pressure (SDEC) and solved-pressure (gap) paths.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/normal_contact.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {
namespace {

using contactgeom::Sdec;

const Material kSteel{80e9, 0.25};
const Sdec kPatch{4.25e-3, 4.25e-3, 0.6};  // the paper's reference patch
const ContactLoad kLoad{37830.0, 0.35};

SdecGridOptions grid(int n) {
  SdecGridOptions o;
  o.nx = o.ny = n;
  return o;
}

// In adhesion the slip vanishes (to the solver's tolerance); in slip the traction is on the
// bound and opposes the slip (Kalker 1990, Coulomb's law).
TEST(ExactSteadyRolling, EveryElementObeysCoulombsLaw) {
  const ExactSolution s = exact_sdec(kPatch, {1e-3, -5e-4, 0.6}, kLoad, kSteel, grid(30));
  ASSERT_EQ(s.status, ExactStatus::converged) << s.message;
  ASSERT_GT(s.adhesion_elements, 0);
  ASSERT_GT(s.slip_elements, 0);
  double slip_scale = 0.0;
  for (std::size_t e = 0; e < s.pn.size(); ++e)
    slip_scale = std::max(slip_scale, std::hypot(s.sx[e], s.sy[e]));
  for (std::size_t e = 0; e < s.pn.size(); ++e) {
    const double p = std::hypot(s.px[e], s.py[e]), bound = kLoad.mu * s.pn[e];
    const double slip = std::hypot(s.sx[e], s.sy[e]);
    switch (s.state[e]) {
      case ElementState::exterior:
        EXPECT_EQ(p, 0.0);
        break;
      case ElementState::adhesion:
        EXPECT_LE(p, bound * (1 + 1e-12));
        EXPECT_LT(slip, 1e-4 * slip_scale);  // rms tolerance 1e-6 on p; slip is C p
        break;
      case ElementState::slip:
        EXPECT_NEAR(p, bound, 1e-12 * bound);
        EXPECT_LT((s.px[e] * s.sx[e] + s.py[e] * s.sy[e]) / (p * slip), -1 + 1e-4);
        break;
    }
  }
}

// Large creepage: every element slides, so the force is mu times the grid's normal force.
TEST(ExactSteadyRolling, SaturatesAtMuTimesTheNormalForce) {
  const ExactSolution s = exact_sdec(kPatch, {0.05, 0.0, 0.0}, kLoad, kSteel, grid(20));
  ASSERT_EQ(s.status, ExactStatus::converged);
  EXPECT_EQ(s.adhesion_elements, 0);
  constexpr double kSliding = 1e-3;  // [fraction of mu N], every element on the Coulomb bound
  EXPECT_NEAR(s.forces.Fx, -kLoad.mu * s.normal_force, kSliding * kLoad.mu * s.normal_force);
  EXPECT_LT(std::abs(s.forces.Fy), kSliding * kLoad.mu * s.normal_force);
  // The grid's normal force is the sum of the sampled Eq. 4 pressure: within 1 % of N.
  EXPECT_NEAR(s.normal_force / kLoad.N, 1.0, 0.01);
}

// full_sliding_sdec is the limit of large creepage in a fixed direction:
// - pure spin on a circle (Hertz pressure): the tractions circle O, Mz = -mu int p rho dA =
//   -(3 pi / 16) mu N a (p0 pi^2 a^3 / 8 with N = 2 pi a^2 p0 / 3), no force; bound 1 % of
//   mu N a, the grid's quadrature of the pressure (the sum of the sampled pressure is within 1 %
//   of N) and the spin's offset dx/6;
// - creepages far beyond saturation (about 1e4 times the saturating creepage) whose spin pole
//   lies outside the patch: exact_sdec within 1e-3 of mu N of it (its elastic slip adds a
//   term falling as 1/|w|; 2.3e-5 measured); the same pressure and grid, so the comparison is
//   element by element.
TEST(ExactSteadyRolling, FullSlidingIsTheLimitOfLargeCreepage) {
  const Sdec circle{5e-3, 5e-3, 0.0};
  const CreepForces spin = full_sliding_sdec(circle, {0, 0, 1.0}, kLoad, grid(80));
  const double mu_n = kLoad.mu * kLoad.N;
  EXPECT_NEAR(*spin.Mz / (mu_n * circle.a), -3 * std::numbers::pi / 16, 0.01);
  EXPECT_LT(std::hypot(spin.Fx, spin.Fy), 0.01 * mu_n);
  // Independent of the creepages' magnitude.
  const CreepForces doubled = full_sliding_sdec(circle, {0, 0, 2.0}, kLoad, grid(80));
  EXPECT_DOUBLE_EQ(*doubled.Mz, *spin.Mz);

  for (const Creepages& v :
       {Creepages{50.0, 0.0, 0.0}, Creepages{20.0, -40.0, 1e3}, Creepages{-30.0, 10.0, -2e3}}) {
    const ExactSolution exact = exact_sdec(kPatch, v, kLoad, kSteel, grid(40));
    ASSERT_EQ(exact.status, ExactStatus::converged);
    const CreepForces limit = full_sliding_sdec(kPatch, v, kLoad, grid(40));
    EXPECT_NEAR(exact.forces.Fx, limit.Fx, 1e-3 * mu_n) << v.vx << " " << v.vy << " " << v.phi;
    EXPECT_NEAR(exact.forces.Fy, limit.Fy, 1e-3 * mu_n) << v.vx << " " << v.vy << " " << v.phi;
    EXPECT_NEAR(*exact.forces.Mz, *limit.Mz, 1e-3 * mu_n * kPatch.c());
  }
}

// Mirroring y maps psi to -psi, vy to -vy and phi to -phi; Fx is even, Fy and Mz are odd.
TEST(ExactSteadyRolling, MirrorImageInPsi) {
  const Creepages v{2e-4, 1e-4, 0.5};
  const ExactSolution a = exact_sdec(kPatch, v, kLoad, kSteel, grid(24));
  const ExactSolution b =
      exact_sdec({kPatch.a, kPatch.b, -kPatch.psi}, {v.vx, -v.vy, -v.phi}, kLoad, kSteel, grid(24));
  const double scale = kLoad.mu * kLoad.N;
  // Mirror-image grids: equal up to the solver's stopping tolerance (1e-6 relative change).
  constexpr double kStopping = 1e-6;  // [fraction of mu N, and of mu N a for Mz]
  EXPECT_NEAR(a.forces.Fx, b.forces.Fx, kStopping * scale);
  EXPECT_NEAR(a.forces.Fy, -b.forces.Fy, kStopping * scale);
  EXPECT_NEAR(*a.forces.Mz, -*b.forces.Mz, kStopping * scale * kPatch.a);
}

// Scaling all lengths by k (N by k^2, spin by 1/k) leaves the normalised forces unchanged:
// no hidden unit assumption (metres against millimetres).
TEST(ExactSteadyRolling, IsInvariantUnderAChangeOfLengthScale) {
  const double k = 1000.0;
  const ExactSolution a = exact_sdec(kPatch, {1e-4, 2e-4, 0.8}, kLoad, kSteel, grid(20));
  const ExactSolution b =
      exact_sdec({kPatch.a * k, kPatch.b * k, kPatch.psi}, {1e-4, 2e-4, 0.8 / k},
                 {kLoad.N * k * k, kLoad.mu}, kSteel, grid(20));
  // The same iterations (checked below) on scaled numbers: rounding only.
  constexpr double kScaled = 1e-9;
  EXPECT_NEAR(a.forces.Fx / a.normal_force, b.forces.Fx / b.normal_force, kScaled);
  EXPECT_NEAR(a.forces.Fy / a.normal_force, b.forces.Fy / b.normal_force, kScaled);
  EXPECT_EQ(a.iterations, b.iterations);
}

// The gap of a sphere solved by the normal problem gives Hertz's pressure, which CONTACT's SDEC
// option prescribes for psi = 0: the forces of both paths agree within the normal problem's
// discretisation error (0.5 % rms in the pressure on this grid, exact_normal_test; measured
// force difference 0.12 % of mu N).
TEST(ExactSteadyRolling, GapPathAgreesWithPrescribedHertzPressure) {
  const double radius = 0.3, force = 30e3;
  const double e_star = kSteel.G / (1.0 - kSteel.nu);
  const double a = std::cbrt(3.0 * force * radius / (4.0 * e_star));
  const Sdec circle{a, a, 0.0};
  const SdecGridOptions options = grid(30);
  const ElementGrid g = sdec_grid(circle, options);
  std::vector<double> h(static_cast<std::size_t>(g.size()));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      h[static_cast<std::size_t>(j * g.nx + i)] =
          (g.x(i) * g.x(i) + g.y(j) * g.y(j)) / (2 * radius);
  const Creepages v{3e-4, 2e-4, 0.5};
  const ContactLoad load{force, 0.3};
  const ExactSolution gap = exact_rolling(g, h, v, load, kSteel);
  const ExactSolution sdec = exact_sdec(circle, v, load, kSteel, options);
  ASSERT_EQ(gap.status, ExactStatus::converged) << gap.message;
  const double scale = load.mu * force;
  constexpr double kNormalProblem = 0.005;  // [mu N], see above
  EXPECT_NEAR(gap.forces.Fx / scale, sdec.forces.Fx / scale, kNormalProblem);
  EXPECT_NEAR(gap.forces.Fy / scale, sdec.forces.Fy / scale, kNormalProblem);
  RecordProperty("dFx_over_muN", std::to_string((gap.forces.Fx - sdec.forces.Fx) / scale));
  RecordProperty("dFy_over_muN", std::to_string((gap.forces.Fy - sdec.forces.Fy) / scale));
}

// A longitudinal creepage added to every row (exact_rolling's row_vx) is a shift of vx: the
// same rigid slip in every element, so the same forces (to rounding, the sums taken in another
// order), and the rigid slip's work it adds, row_creepage_work, is -k Fx, which with the
// creepages at O gives the work of the shifted creepages.
TEST(ExactSteadyRolling, AUniformRowCreepageIsAShiftOfVx) {
  const double radius = 0.3, force = 30e3;
  const SdecGridOptions options = grid(24);
  const ElementGrid g = sdec_grid({4e-3, 4e-3, 0.0}, options);
  std::vector<double> h(static_cast<std::size_t>(g.size()));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      h[static_cast<std::size_t>(j * g.nx + i)] =
          (g.x(i) * g.x(i) + g.y(j) * g.y(j)) / (2 * radius);
  const ContactLoad load{force, 0.3};
  constexpr double kShift = 4e-4;
  const Creepages at_O{1e-4, 2e-4, 0.5};
  const std::vector<double> rows(static_cast<std::size_t>(g.ny), kShift);
  const ExactSolution with_rows = exact_rolling(g, h, at_O, load, kSteel, {}, rows);
  const ExactSolution shifted =
      exact_rolling(g, h, {at_O.vx + kShift, at_O.vy, at_O.phi}, load, kSteel);
  ASSERT_EQ(with_rows.status, ExactStatus::converged) << with_rows.message;
  const double scale = load.mu * force;
  EXPECT_NEAR(with_rows.forces.Fx / scale, shifted.forces.Fx / scale, 1e-9);
  EXPECT_NEAR(with_rows.forces.Fy / scale, shifted.forces.Fy / scale, 1e-9);
  EXPECT_NEAR(with_rows.row_creepage_work, -kShift * with_rows.forces.Fx, 1e-9 * scale * kShift);
  EXPECT_EQ(shifted.row_creepage_work, 0.0);
  // Rows of the wrong number are refused.
  EXPECT_THROW(exact_rolling(g, h, at_O, load, kSteel, {}, std::vector<double>(3, 0.0)),
               InputError);
}

// Robustness: random patches (a/b = 0.2 ... 5, |psi| <= 0.8), creepages (1e-4 ... 1e-2, spin
// up to 10 1/m), loads, friction and Poisson's ratios all converge, and no force exceeds
// Coulomb's bound mu times the grid's normal force. (In development 400 such cases on 30 x 30
// and 60 x 60 grids converged within 182 sweeps.)
TEST(ExactSteadyRolling, ConvergesOverRandomInputs) {
  std::mt19937 rng(2022);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 30; ++k) {
    const double g = std::exp(std::log(0.2) + u(rng) * std::log(25.0));
    const Sdec patch{4e-3 * std::sqrt(g), 4e-3 / std::sqrt(g), -0.8 + 1.6 * u(rng)};
    const double scale = std::pow(10.0, -4.0 + 2.0 * u(rng));
    const Creepages v{scale * (2 * u(rng) - 1), scale * (2 * u(rng) - 1),
                      scale * 1e3 * (2 * u(rng) - 1)};
    const ContactLoad load{2e4 + 6e4 * u(rng), 0.1 + 0.5 * u(rng)};
    const ExactSolution s = exact_sdec(patch, v, load, {80e9, 0.5 * u(rng)}, grid(20));
    ASSERT_EQ(s.status, ExactStatus::converged) << "case " << k << ": " << s.message;
    EXPECT_LE(std::hypot(s.forces.Fx, s.forces.Fy), load.mu * s.normal_force * (1 + 1e-9));
  }
}

TEST(ExactSteadyRolling, ReportsAnUnconvergedSolveAsAStatus) {
  ExactSolverOptions capped;
  capped.max_iterations = 2;
  const ExactSolution s = exact_sdec(kPatch, {0, 0, 1.0}, kLoad, kSteel, grid(20), capped);
  EXPECT_EQ(s.status, ExactStatus::not_converged);
  EXPECT_FALSE(s.message.empty());
  EXPECT_EQ(s.iterations, 2);
}

TEST(ExactSteadyRolling, RejectsBadInput) {
  EXPECT_THROW(exact_sdec({4e-3, 4e-3, 1.0}, {}, kLoad, kSteel), InputError);
  EXPECT_THROW(exact_sdec(kPatch, {std::nan(""), 0, 0}, kLoad, kSteel), InputError);
  EXPECT_THROW(exact_sdec(kPatch, {}, {-1.0, 0.3}, kSteel), InputError);
  EXPECT_THROW(exact_sdec(kPatch, {}, kLoad, {-1.0, 0.25}), InputError);
  SdecGridOptions bad;
  bad.nx = 1;
  EXPECT_THROW(exact_sdec(kPatch, {}, kLoad, kSteel, bad), InputError);
  ExactSolverOptions bad_solver;
  bad_solver.tolerance = 0.0;
  EXPECT_THROW(exact_sdec(kPatch, {}, kLoad, kSteel, {}, bad_solver), InputError);
  bad = {};
  bad.margin = 0.9;
  EXPECT_THROW(exact_sdec(kPatch, {}, kLoad, kSteel, bad), InputError);
  bad = {};
  bad.shift_x = 0.7;
  EXPECT_THROW(exact_sdec(kPatch, {}, kLoad, kSteel, bad), InputError);
  EXPECT_THROW(full_sliding_sdec(kPatch, {std::nan(""), 0, 0}, kLoad), InputError);
  EXPECT_THROW(full_sliding_sdec(kPatch, {1, 0, 0}, {-1.0, 0.3}), InputError);
  EXPECT_THROW(full_sliding_sdec({4e-3, 4e-3, 1.0}, {1, 0, 0}, kLoad), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential
