// Numerical stability of every tangential method and of the wear laws: seeded random sweeps
// over the whole input range against the invariants of stability_sweep.hpp, and degenerate
// patches (a single cell, extremely slender patches, vanishing load, friction or creepage).
// studies/stability_study.cpp runs the same sweep longer and writes the worst margins.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "stability_sweep.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::wear {

// The patches these tests wear are solved by the tangential library.
using namespace wheelwear::tangential;
namespace {

using contactgeom::Sdec;
using stability::Case;
using stability::Margins;
constexpr double pi = std::numbers::pi;
// The bound's node sums may exceed mu N by their quadrature error: 1 % at 30 x 30 cells.
constexpr double kBoundQuadrature = 0.01;

std::string describe(const Case& c) {
  char text[512];
  std::snprintf(text, sizeof text,
                "%s %dx%d a=%.6g b=%.6g psi=%.6g vx=%.6g vy=%.6g phi=%.6g N=%.6g mu=%.6g nu=%.6g",
                stability::case_method_name(c).c_str(), c.options.nx, c.options.ny, c.patch.a,
                c.patch.b, c.patch.psi, c.creepages.vx, c.creepages.vy, c.creepages.phi, c.load.N,
                c.load.mu, c.material.nu);
  return text;
}

// 0.5 s of solves in Release: 400 random cases of 22 method variants, each with 35 more solves
// for its continuity probes and saturation curve.
TEST(StabilitySweep, RandomCasesKeepEveryInvariant) {
  std::mt19937_64 rng(20261122);
  const stability::Ranges ranges;
  const stability::Limits limits;
  Margins worst;
  for (int n = 0; n < 400; ++n) {
    std::array<double, 3> direction{};
    const Case c = stability::random_case(rng, ranges, direction);
    Margins m;
    ASSERT_NO_THROW(m = stability::check(c, direction, limits)) << describe(c);
    EXPECT_TRUE(stability::passes(m, c, limits))
        << describe(c) << "\n  finite " << m.finite << " |F|/muN " << m.force_ratio << " lipschitz "
        << m.lipschitz << " (" << m.worst_input << ") monotone drop " << m.monotone_drop
        << " wear imbalance " << m.wear_imbalance << " negative wear " << m.wear_negative;
    worst.force_ratio = std::max(worst.force_ratio, m.force_ratio);
    worst.lipschitz = std::max(worst.lipschitz, m.lipschitz);
    worst.monotone_drop = std::max(worst.monotone_drop, m.monotone_drop);
    worst.wear_imbalance = std::max(worst.wear_imbalance, m.wear_imbalance);
  }
  RecordProperty("worst_force_ratio", std::to_string(worst.force_ratio));
  RecordProperty("worst_lipschitz", std::to_string(worst.lipschitz));
  RecordProperty("worst_monotone_drop", std::to_string(worst.monotone_drop));
}

// Every FASTSIM variant, scheme and bound, for the degenerate cases below.
template <class Body>
void for_every_fastsim(Body body) {
  for (const FastsimMethod m : {FastsimMethod::sdec, FastsimMethod::eql, FastsimMethod::eqe,
                                FastsimMethod::eqe_shifted, FastsimMethod::elliptic}) {
    for (const FastsimScheme scheme : {FastsimScheme::kalker, FastsimScheme::second_order}) {
      for (const TractionBound bound : {TractionBound::parabolic, TractionBound::semi_elliptic}) {
        FastsimOptions options;
        options.scheme = scheme;
        options.bound = bound;
        options.cell_fields = true;
        body(m, options,
             std::string(method_name(m)) +
                 (scheme == FastsimScheme::kalker ? " kalker" : " second-order") +
                 (bound == TractionBound::parabolic ? " parabolic" : " semi-elliptic"));
      }
    }
  }
}

bool all_finite(const TangentialSolution& s) {
  bool ok = std::isfinite(s.forces.Fx) && std::isfinite(s.forces.Fy) &&
            std::isfinite(s.forces.Mz.value_or(0.0)) && std::isfinite(s.frictional_work);
  if (s.fields) {
    for (const auto* v : {&s.fields->px, &s.fields->py, &s.fields->sx, &s.fields->sy,
                          &s.fields->slip_norm, &s.fields->work, &s.fields->pressure}) {
      for (const double x : *v) ok = ok && std::isfinite(x);
    }
  }
  return ok;
}

// A single cell: one strip, one cell. Kalker's scheme gives the cell its trailing node's
// traction, and the trailing node lies on the patch edge where the bound vanishes: no force
// at all. The second-order scheme integrates the cell; its traction stays below the bound's
// integral over the one strip, width 2b times the integral along it of the parabolic bound,
// k (4/3) x_l^3 with k = 2 mu N/(pi a^3 b) (or, semi-elliptic, mu p0/a (pi/2) x_l^2).
TEST(StabilityDegenerate, SingleCellGrid) {
  const Sdec patch{5e-3, 4e-3, 0.4};
  const ContactLoad load{6e4, 0.3};
  const double xl = patch.leading_edge(patch.y0());  // the strip's centre is the mid-point O'
  for_every_fastsim([&](FastsimMethod m, FastsimOptions options, const std::string& name) {
    options.nx = options.ny = 1;
    for (const Creepages v : {Creepages{1e-3, 0, 0}, Creepages{0, -0.05, 0},
                              Creepages{2e-3, 1e-3, 2.0}, Creepages{0, 0, 40.0}}) {
      const TangentialSolution s = fastsim(m, patch, v, load, {}, options);
      ASSERT_TRUE(all_finite(s)) << name;
      const double magnitude = std::hypot(s.forces.Fx, s.forces.Fy);
      if (options.scheme == FastsimScheme::kalker) {
        EXPECT_EQ(magnitude, 0.0) << name;
        continue;
      }
      // The strip runs through O' (SDEC region) or through the ellipse's centre (x_l = a).
      const bool sdec_region = m == FastsimMethod::sdec || m == FastsimMethod::eql;
      const double x = sdec_region ? xl : patch.a;
      const double along =
          options.bound == TractionBound::parabolic
              ? 2 * load.mu * load.N / (pi * std::pow(patch.a, 3) * patch.b) * 4.0 / 3.0 * x * x * x
              : load.mu * patch.peak_pressure(load.N) / patch.a * pi / 2 * x * x;
      const double bound = 2 * patch.b * along;
      // 1e-12: Simpson's rule integrates the parabolic bound exactly; the semi-elliptic one
      // it underestimates, so the bound holds a fortiori.
      EXPECT_LE(magnitude, bound * (1 + 1e-12)) << name;
    }
  });
}

// Extremely slender patches (a/b = 1e-3 and 1e3, far outside Kalker's table): finite, below
// mu N up to the quadrature error, and in the linear limit Kalker's first-order result: the
// exact linear-theory force times (1 - 1/nx) (see FastsimLinearLimit).
TEST(StabilityDegenerate, ExtremelySlenderPatches) {
  const ContactLoad load{1e4, 0.3};
  for (const double g : {1e-3, 1e3}) {
    const double c = 4e-3;
    const Sdec patch{c * std::sqrt(g), c / std::sqrt(g), 0.5};
    for_every_fastsim([&](FastsimMethod m, FastsimOptions options, const std::string& name) {
      options.nx = options.ny = 100;
      for (const Creepages v :
           {Creepages{1e-2, 0, 0}, Creepages{0, 1, 0}, Creepages{1e-3, -1e-3, 5.0}}) {
        const TangentialSolution s = fastsim(m, patch, v, load, {}, options);
        ASSERT_TRUE(all_finite(s)) << name << " g " << g;
        EXPECT_LE(std::hypot(s.forces.Fx, s.forces.Fy), load.mu * load.N * (1 + kBoundQuadrature))
            << name;
      }
      if (m == FastsimMethod::sdec && options.scheme == FastsimScheme::kalker) {
        const Creepages tiny{1e-12, 0, 0};
        options.ny = 1000;
        const double fx = fastsim(m, patch, tiny, load, {}, options).forces.Fx;
        const double exact = linear_sdec_forces(patch, tiny, {}).Fx;
        // 1e-5: the midpoint rule's error over 1000 strips of x_l^2(y).
        EXPECT_NEAR(fx / exact, 1 - 1.0 / options.nx, 1e-5) << "g " << g;
      }
    });
  }
}

// Vanishing load or friction: the tractions scale with mu N (1 N down to 1e-6 N; mu down to
// 1e-12), everything stays finite and the wear vanishes with them. Zero load or zero friction
// is documented bad input (ContactLoad: N > 0, mu > 0) and throws InputError.
TEST(StabilityDegenerate, VanishingLoadAndFriction) {
  const Sdec patch{5e-3, 4e-3, -0.7};
  const Creepages v{1e-3, 2e-3, 1.0};
  const WearLaw law = *default_wear_law("usfd");
  for_every_fastsim([&](FastsimMethod m, FastsimOptions options, const std::string& name) {
    options.nx = options.ny = 30;
    for (const ContactLoad load :
         {ContactLoad{1e-6, 0.3}, ContactLoad{1.0, 0.3}, ContactLoad{1e4, 1e-12}}) {
      const TangentialSolution s = fastsim(m, patch, v, load, {}, options);
      ASSERT_TRUE(all_finite(s)) << name;
      EXPECT_LE(std::hypot(s.forces.Fx, s.forces.Fy), load.mu * load.N * (1 + kBoundQuadrature))
          << name;
      WearDistribution w = WearDistribution::zeros(-10e-3, 0.1e-3, 201);
      accumulate_wear(*s.fields, 20.0, law, {0.0, 0.46}, 1.0, w);
      EXPECT_TRUE(std::isfinite(w.area())) << name;
      EXPECT_GE(w.area(), 0.0) << name;
    }
    EXPECT_THROW(fastsim(m, patch, v, {0.0, 0.3}, {}, options), InputError) << name;
    EXPECT_THROW(fastsim(m, patch, v, {1e4, 0.0}, {}, options), InputError) << name;
  });
  EXPECT_THROW(she_sdec_forces(patch, v, {}, {0.0, 0.3}), InputError);
  EXPECT_THROW(she_sdec_forces(patch, v, {}, {1e4, 0.0}), InputError);
}

// Pure rolling: exactly no traction, no slip, no work, no wear, whatever the patch.
TEST(StabilityDegenerate, NoCreepageNoTraction) {
  const WearLaw law = *default_wear_law("archard");
  for (const Sdec patch :
       {Sdec{5e-3, 4e-3, 0.0}, Sdec{1e-5, 1e-2, 0.99}, Sdec{1e-2, 1e-5, -0.99}}) {
    for_every_fastsim([&](FastsimMethod m, FastsimOptions options, const std::string& name) {
      options.nx = 7;
      options.ny = 9;
      const TangentialSolution s = fastsim(m, patch, {}, {1e4, 0.3}, {}, options);
      EXPECT_EQ(s.forces.Fx, 0.0) << name;
      EXPECT_EQ(s.forces.Fy, 0.0) << name;
      EXPECT_EQ(s.frictional_work, 0.0) << name;
      EXPECT_EQ(s.slip_cells, 0) << name;
      WearDistribution w = WearDistribution::zeros(-20e-3, 0.1e-3, 401);
      accumulate_wear(*s.fields, 20.0, law, {0.0, 0.46}, 1.0, w);
      EXPECT_EQ(w.area(), 0.0) << name;
    });
    EXPECT_EQ(she_sdec_forces(patch, {}, {}, {1e4, 0.3}).Fx, 0.0);
  }
}

// A known limit of the second-order scheme. Its slip direction follows de/dt = (r - (e.r) e)/g,
// whose state e = -r/|r| is an equilibrium, unstable: where the rigid slip r reverses exactly
// against a sliding traction, the traction keeps its direction, while the least lateral
// creepage tips it over to follow r. Under pure spin that happens on a strip lying exactly on
// the line of zero longitudinal rigid slip (the middle strip of an odd number on a centred
// ellipse), so the force jumps as vx or vy crosses zero. The jump is bounded by that strip's
// share of the bound, twice mu N x_l^3 dy / (integral of x_l^3 dy) = 2 (16 / 3 pi) / ny;
// Kalker's scheme, which projects the trial traction, has no such jump.
TEST(StabilityKnownLimits, SecondOrderSlipDirectionBifurcatesWhereSpinReversesTheSlip) {
  // A case the stability study found (seed 11), to all its digits: whether the middle
  // strip's centre is exactly on the line depends on the rounding of its position.
  const Sdec ellipse{0.0030780102544457448, 0.0004802793797051856, 0.38044735638839755};
  const ContactLoad load{50667.413540127774, 0.6453923634872013};
  const Material material{80e9, 0.08814628796557529};
  FastsimOptions options;
  options.nx = options.ny = 21;
  options.bound = TractionBound::semi_elliptic;
  const double mu_n = load.mu * load.N;
  for (const FastsimScheme scheme : {FastsimScheme::second_order, FastsimScheme::kalker}) {
    options.scheme = scheme;
    const Creepages spin{0, 0, -4414.7506490501182};
    const double lateral = 1e-8 * std::abs(spin.phi) * ellipse.c();
    const CreepForces at_zero =
        fastsim(FastsimMethod::eqe, ellipse, spin, load, material, options).forces;
    const CreepForces nudged =
        fastsim(FastsimMethod::eqe, ellipse, {0, lateral, spin.phi}, load, material, options)
            .forces;
    const double jump = std::hypot(nudged.Fx - at_zero.Fx, nudged.Fy - at_zero.Fy) / mu_n;
    if (scheme == FastsimScheme::kalker) {
      EXPECT_LT(jump, 1e-6);  // continuous: a change of 1e-8 in the creepage
    } else {
      EXPECT_LT(jump, 2 * 16 / (3 * pi) / options.ny);
      RecordProperty("second_order_jump_over_mu_N", std::to_string(jump));
    }
  }
}

// Bad input throws InputError, never anything else; each field in turn takes a value its
// documentation rules out.
TEST(StabilityDegenerate, BadInputThrowsInputErrorOnly) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Sdec patch{5e-3, 4e-3, 0.3};
  const Creepages v{1e-3, 0, 0.5};
  const ContactLoad load{1e4, 0.3};
  auto expect_input_error = [](auto&& call, const std::string& what) {
    try {
      call();
      ADD_FAILURE() << what << ": no exception";
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": " << e.what() << " is not an InputError";
    }
  };
  for (const double bad : {nan, inf, -inf}) {
    for (int field = 0; field < 9; ++field) {
      Sdec p = patch;
      Creepages c = v;
      ContactLoad l = load;
      Material mat;
      double* target[] = {&p.a, &p.b, &p.psi, &c.vx, &c.vy, &c.phi, &l.N, &l.mu, &mat.nu};
      *target[field] = bad;
      const std::string what = "field " + std::to_string(field) + " = " + std::to_string(bad);
      expect_input_error([&] { fastsim(FastsimMethod::sdec, p, c, l, mat); }, what);
      expect_input_error([&] { she_sdec_forces(p, c, mat, l); }, what);
      if (field < 6 || field == 8) {
        expect_input_error([&] { linear_sdec_forces(p, c, mat); }, what);
      }
    }
  }
  for (const Sdec p : {Sdec{0, 4e-3, 0}, Sdec{-1e-3, 4e-3, 0}, Sdec{5e-3, 0, 0},
                       Sdec{5e-3, 4e-3, 1}, Sdec{5e-3, 4e-3, -1.5}}) {
    expect_input_error([&] { fastsim(FastsimMethod::eqe_shifted, p, v, load, {}); }, "patch");
    expect_input_error([&] { linear_sdec_forces(p, v, {}); }, "patch");
  }
  FastsimOptions grid;
  grid.nx = 0;
  expect_input_error([&] { fastsim(FastsimMethod::sdec, patch, v, load, {}, grid); }, "nx = 0");
  expect_input_error([&] { fastsim(FastsimMethod::sdec, patch, v, load, {0.0, 0.25}); }, "G = 0");
  expect_input_error(
      [&] {
        fastsim(FastsimMethod::sdec, patch, v, load, {80e9, 0.6});
      },
      "nu = 0.6");
}

}  // namespace
}  // namespace wheelwear::wear
