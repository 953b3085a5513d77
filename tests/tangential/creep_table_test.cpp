// The book of creep-force tables (creep_table.hpp, data/creep_table.h5): interpolated forces
// against fresh exact-theory solves between the table's nodes and at them, its symmetries, and
// its refusal outside its range.

#include "wheelwear/tangential/creep_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "support/contact_cases.hpp"
#include "support/creep_table_points.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::tangential {
namespace {

using contactgeom::Sdec;

using testing::creep_table::creepages_for;
using testing::creep_table::kLoad;
using testing::creep_table::Point;

void expect_measured(const testing::creep_table::TableError& e) {
  EXPECT_EQ(e.status, ExactStatus::converged);
  EXPECT_FALSE(std::isnan(e.moment)) << "table or exact solve without Mz";
}

double error_against_exact(const Point& p) {
  const testing::creep_table::TableError e = testing::creep_table::table_error(p);
  expect_measured(e);
  return std::max(e.force, e.moment);
}

// At a node of every axis (theta in steps of pi/32, beta of pi/18) the table returns the exact
// solution it stores: a fresh solve on the same grid agrees to the solver's stopping tolerance
// (1e-6 relative change): 1e-5 of mu N (and of mu N c for Mz).
TEST(CreepTable, ReproducesFreshSolvesAtItsNodes) {
  const double pi = std::numbers::pi;
  const Material steel{80e9, 0.25};
  double worst = 0;
  for (const auto& [g, psi, r, theta, beta] :
       {std::array{1.0, 0.4, 1.0, pi / 2, 0.0}, std::array{0.5, 0.6, 2.0, 7 * pi / 32, pi / 6},
        std::array{2.0, 0.2, 0.5, 23 * pi / 32, -pi / 3}, std::array{1.0, 0.0, 3.0, 0.0, 0.0},
        std::array{4.0, 0.8, 3.5, 3 * pi / 4, 4 * pi / 9},
        std::array{0.25, 0.4, 5.0, pi / 4, -7 * pi / 18}, std::array{7.0, 0.4, 2.0, pi / 2, 0.0},
        std::array{10.0, 0.8, 1.0, 7 * pi / 32, pi / 6},
        std::array{3.0, 0.2, 8.0, 9 * pi / 32, -pi / 6}, std::array{0.5, 0.6, 12.0, pi / 2, 0.0}}) {
    const Sdec s{5e-3, 5e-3 / g, psi};
    const double e = error_against_exact({s, creepages_for(s, steel, r, theta, beta), steel});
    EXPECT_LT(e, 1e-5) << "a/b " << g << " psi " << psi << " r " << r;
    worst = std::max(worst, e);
  }
  RecordProperty("worst_node_error_muN", std::to_string(worst));
}

// Between the nodes: 100 points spread over the whole range (a fixed linear congruential
// sequence, tests/support/creep_table_points.hpp: a/b log-uniform in the table's range, psi in
// -0.8 ... 0.8, directions uniform on the sphere, r in 0 ... r_max, nu in 0.25 ... 0.28), against
// fresh exact solves on the table's grid (creep_table_grid). Bound: the table's design target,
// 1 % of mu N (and of mu N c for Mz); the shipped table (16 a/b x 5 psi x 33 theta x 19 beta x
// 20 r, 30 elements across) reaches worst 0.45 % and mean 0.04 % in F on these points, 0.43 %
// and 0.03 % in Mz. Over 1000 points of the same sequence (studies/table_interpolation_study.cpp)
// two miss the target in F: wide patches (a/b 0.24) with the spin's pole in the patch, 1.43 % and
// 1.28 %, where the directions are too coarse (docs/validation.md); Mz within 0.63 %, and above
// a/b 1 F within 0.76 %.
constexpr double kInterpolationError = 0.01;
constexpr double kMeanInterpolationError = 0.002;
constexpr double kMomentInterpolationError = 0.01;
constexpr double kMeanMomentInterpolationError = 0.002;

TEST(CreepTable, InterpolatesBetweenItsNodes) {
  testing::creep_table::PointSequence points;
  double worst = 0, sum = 0, worst_moment = 0, sum_moment = 0;
  constexpr int kPoints = 100;
  for (int i = 0; i < kPoints; ++i) {
    const Point p = points.next();
    const testing::creep_table::TableError e = testing::creep_table::table_error(p);
    expect_measured(e);
    const auto where = [&p] {
      return "a/b " + std::to_string(p.sdec.ellipticity()) + " psi " + std::to_string(p.sdec.psi) +
             " nu " + std::to_string(p.material.nu) + " vx " + std::to_string(p.creepages.vx) +
             " vy " + std::to_string(p.creepages.vy) + " phi " + std::to_string(p.creepages.phi);
    };
    EXPECT_LT(e.force, kInterpolationError) << where();
    EXPECT_LT(e.moment, kMomentInterpolationError) << where();
    worst = std::max(worst, e.force);
    sum += e.force;
    worst_moment = std::max(worst_moment, e.moment);
    sum_moment += e.moment;
  }
  EXPECT_LT(sum / kPoints, kMeanInterpolationError);
  EXPECT_LT(sum_moment / kPoints, kMeanMomentInterpolationError);
  RecordProperty("worst_error_muN", std::to_string(worst));
  RecordProperty("mean_error_muN", std::to_string(sum / kPoints));
  std::printf(
      "creep table over %d points: F worst %.4f, mean %.4f of mu N; Mz worst %.4f, mean "
      "%.4f of mu N c\n",
      kPoints, worst, sum / kPoints, worst_moment, sum_moment / kPoints);
}

// The flank's slender patches (a/b 10 ... 25; CONTACT's flange patches reach a/b 20), which
// the table covers at nu = 0.25 (nodes 12, 14.5, 17.5, 21, 25; with the flank's spin, up to
// r = 50): 40 points of a sequence of their own, at that nu, r up to 50, against fresh exact
// solves on the table's grid. Bound: the table's design target, 1 % of mu N (and of mu N c for
// Mz), as between the other nodes.
TEST(CreepTable, InterpolatesBetweenItsNodesOnSlenderPatches) {
  const CreepTableRange common = creep_table_range(), slender = creep_table_range(0.25);
  ASSERT_GE(slender.a_over_b_max, 25.0);
  testing::creep_table::PointSequence points(777);
  double worst = 0, worst_moment = 0, sum = 0;
  constexpr int kPoints = 40;
  for (int i = 0; i < kPoints; ++i) {
    const Point p =
        points.next({common.a_over_b_max, slender.a_over_b_max, 0.25, 0.25, slender.r_max});
    const testing::creep_table::TableError e = testing::creep_table::table_error(p);
    expect_measured(e);
    EXPECT_LT(e.force, kInterpolationError) << "a/b " << p.sdec.ellipticity();
    EXPECT_LT(e.moment, kMomentInterpolationError) << "a/b " << p.sdec.ellipticity();
    worst = std::max(worst, e.force);
    worst_moment = std::max(worst_moment, e.moment);
    sum += e.force;
  }
  EXPECT_LT(sum / kPoints, kMeanInterpolationError);
  std::printf("slender patches, %d points: F worst %.4f, mean %.4f of mu N; Mz worst %.4f\n",
              kPoints, worst, sum / kPoints, worst_moment);
}

// Near full sliding on a wide patch the spin's pole crosses the patch as the creepages turn, and
// the forces turn faster than the direction nodes resolve: at this point (a/b 0.24, mostly
// longitudinal creepage with some spin, |F| at 0.94 mu N; the worst of the study's 1000) the
// forces interpolated alone missed Mz by 3.8 % of mu N c. Taking out the full-sliding limit's
// interpolation error brings it within the table's target, 1 % (measured 0.03 %), and F within
// 1.5 % (the theta nodes' remaining error here: 1.28 %; both against a fresh exact solve on the
// table's grid). Along the creepage's magnitude the correction fades in continuously: no step in
// F (of mu N) or Mz (of mu N c) between 400 samples from r 0.5 to 8 beyond r 1 is larger than
// 1.5 times the largest below r 1, where the forces grow fastest and the correction is off.
TEST(CreepTable, TakesOutTheFullSlidingLimitsErrorNearFullSliding) {
  const Point p{Sdec{5e-3, 5e-3 / 0.2366, 0.621}, Creepages{8.869e-4, -4.56e-5, 2.828e-2},
                Material{80e9, 0.2542}};
  const testing::creep_table::TableError e = testing::creep_table::table_error(p);
  expect_measured(e);
  EXPECT_LT(e.moment, 0.01);
  EXPECT_LT(e.force, 0.015);

  const double mu_n = kLoad.mu * kLoad.N;
  const double r = creep_table_magnitude(p.sdec, p.creepages, kLoad, p.material);
  const auto at = [&](double rr) {
    const double k = rr / r;
    return creep_table_forces(p.sdec, {p.creepages.vx * k, p.creepages.vy * k, p.creepages.phi * k},
                              kLoad, p.material);
  };
  double steady = 0.0, steepest = 0.0;
  CreepForces last = at(0.5);
  for (int i = 1; i <= 400; ++i) {
    const double rr = 0.5 + 7.5 * i / 400.0;
    const CreepForces f = at(rr);
    const double step = std::max(std::hypot(f.Fx - last.Fx, f.Fy - last.Fy) / mu_n,
                                 std::abs(*f.Mz - *last.Mz) / (mu_n * p.sdec.c()));
    (rr < 1.0 ? steady : steepest) = std::max(rr < 1.0 ? steady : steepest, step);
    last = f;
  }
  EXPECT_GT(steady, 0.0);
  EXPECT_LT(steepest, 1.5 * steady);  // measured 0.0072 against 0.0094; a switch at once: 0.042
}

// Beyond r_max the table answers where the patch is within full_sliding_margin (4 % of mu N)
// of full sliding at r_max, extrapolating towards the full-sliding limit as 1/r. Against fresh
// exact solves on the table's grid at 60 points with r log-uniform in r_max ... 40: bound 1 % of
// mu N, the table's design target (the study's 1000 points: worst 0.49 % in F and 0.65 % of
// mu N c in Mz). The answer is continuous at r_max, tends to the full-sliding limit, and a
// spin-dominated patch, far from full sliding at r_max, stays outside.
TEST(CreepTable, ExtrapolatesTowardsFullSliding) {
  const CreepTableRange range = creep_table_range();
  EXPECT_GT(range.full_sliding_margin, 0.0);
  testing::creep_table::PointSequence beyond(54321);
  const double mu_n = kLoad.mu * kLoad.N;
  int answered = 0;
  double worst = 0.0;
  for (int i = 0; i < 60; ++i) {
    const Point p = beyond.next_beyond(40.0);
    if (!creep_table_covers(p.sdec, p.creepages, kLoad, p.material)) continue;
    const testing::creep_table::TableError e = testing::creep_table::table_error(p);
    expect_measured(e);
    EXPECT_LT(e.force, kInterpolationError)
        << "a/b " << p.sdec.ellipticity() << " psi " << p.sdec.psi;
    EXPECT_LT(e.moment, kMomentInterpolationError) << "a/b " << p.sdec.ellipticity();
    worst = std::max({worst, e.force, e.moment});
    ++answered;
  }
  EXPECT_GE(answered, 15);  // 42 of these 60 when written
  std::printf("creep table beyond r_max: %d of 60 points answered, worst %.4f of mu N\n", answered,
              worst);

  // Rolling with pure longitudinal creepage: continuous through r_max, then towards sliding.
  const Material steel{80e9, 0.25};
  const CreepTableRange at_steel = creep_table_range(steel.nu);
  const Sdec round{5e-3, 5e-3, 0.2};
  const auto along = [&](double r) {
    return creep_table_forces(round, creepages_for(round, steel, r, std::numbers::pi / 2, 0.0),
                              kLoad, steel);
  };
  const double r_edge =
      at_steel.r_max /
      creep_table_magnitude(round, creepages_for(round, steel, 1.0, std::numbers::pi / 2, 0.0),
                            kLoad, steel);
  const CreepForces below = along(r_edge * (1 - 1e-9)), above = along(r_edge * (1 + 1e-9));
  EXPECT_NEAR(below.Fx, above.Fx, 1e-6 * mu_n);
  EXPECT_NEAR(below.Fy, above.Fy, 1e-6 * mu_n);
  const Creepages far = creepages_for(round, steel, 1e5, std::numbers::pi / 2, 0.0);
  const CreepForces limit = full_sliding_sdec(round, far, kLoad, creep_table_grid(round));
  const CreepForces extrapolated = creep_table_forces(round, far, kLoad, steel);
  EXPECT_NEAR(extrapolated.Fx, limit.Fx, 1e-4 * mu_n);  // the 1/r term: r_max/1e5 of its deficit
  EXPECT_NEAR(extrapolated.Fy, limit.Fy, 1e-4 * mu_n);
  // best takes these totals from the table, with and without cells, in one lookup.
  for (const bool cells : {false, true}) {
    SolveOptions options;
    options.fastsim.cell_fields = cells;
    const TangentialSolution best = solve_patch(Method::best, round, far, kLoad, steel, options);
    EXPECT_TRUE(best.from_table) << best.table_outside.value_or("");
    EXPECT_EQ(best.forces.Fx, extrapolated.Fx);
    EXPECT_EQ(best.forces.Fy, extrapolated.Fy);
  }

  // Spin-dominated: the patch is far from full sliding at r_max; the table refuses, saying so.
  const Creepages spin = creepages_for(round, steel, 2 * at_steel.r_max, 0.05, 0.0);
  const std::string why = creep_table_outside(round, spin, kLoad, steel).value_or("(covered)");
  EXPECT_NE(why.find("full sliding"), std::string::npos) << why;
  EXPECT_THROW(creep_table_forces(round, spin, kLoad, steel), InputError);
}

// Mirror y -> -y (psi, vy, phi change sign: Fx stays, Fy and Mz change sign) and reversal of
// all creepages (forces and moment change sign) hold exactly for the exact theory on its symmetric
// grid, and the table applies them exactly: to rounding.
TEST(CreepTable, HasTheSymmetriesOfTheExactTheory) {
  const Material steel{80e9, 0.25};
  const Sdec plus{5e-3, 4e-3, 0.45}, minus{5e-3, 4e-3, -0.45};
  // r 1.3 and, near full sliding, 8, where the full-sliding limit's correction is on.
  for (const double r : {1.3, 8.0}) {
    const Creepages v = creepages_for(plus, steel, r, 1.1, 0.7);
    const CreepForces f = creep_table_forces(plus, v, kLoad, steel);
    const CreepForces mirrored = creep_table_forces(minus, {v.vx, -v.vy, -v.phi}, kLoad, steel);
    const CreepForces reversed = creep_table_forces(plus, {-v.vx, -v.vy, -v.phi}, kLoad, steel);
    const double scale = kLoad.mu * kLoad.N * 1e-12;
    EXPECT_NEAR(mirrored.Fx, f.Fx, scale) << "r " << r;
    EXPECT_NEAR(mirrored.Fy, -f.Fy, scale) << "r " << r;
    EXPECT_NEAR(reversed.Fx, -f.Fx, scale) << "r " << r;
    EXPECT_NEAR(reversed.Fy, -f.Fy, scale) << "r " << r;
    const double moment_scale = scale * plus.c();  // Mz changes sign with Fy under both
    EXPECT_NEAR(*mirrored.Mz, -*f.Mz, moment_scale) << "r " << r;
    EXPECT_NEAR(*reversed.Mz, -*f.Mz, moment_scale) << "r " << r;
    // And against the exact theory directly with psi < 0 and vx < 0.
    EXPECT_LT(error_against_exact({minus, {-v.vx, v.vy, -v.phi}, steel}), kInterpolationError);
  }
  // Zero creepage: zero force.
  const CreepForces zero = creep_table_forces(plus, {0, 0, 0}, kLoad, steel);
  EXPECT_EQ(zero.Fx, 0.0);
  EXPECT_EQ(zero.Fy, 0.0);
  EXPECT_EQ(*zero.Mz, 0.0);
}

// Outside the table: InputError naming the parameter, and creep_table_covers says why.
TEST(CreepTable, RefusesInputOutsideItsRange) {
  const CreepTableRange range = creep_table_range();
  const Material steel{80e9, 0.25};
  const Sdec inside{5e-3, 5e-3, 0.3};
  const Creepages small{1e-4, 0, 0};
  EXPECT_TRUE(creep_table_covers(inside, small, kLoad, steel));
  ASSERT_GT(creep_table_range(steel.nu).a_over_b_max, range.a_over_b_max);
  const Sdec flank{5e-3, 5e-3 / 20.0, 0.3};
  EXPECT_TRUE(creep_table_covers(flank, small, kLoad, steel));
  struct Case {
    Sdec sdec;
    Creepages creepages;
    Material material;
    std::string field;
  };
  const CreepTableRange at_steel = creep_table_range(steel.nu);
  const double too_slender = at_steel.a_over_b_min * 0.9, too_long = at_steel.a_over_b_max * 1.1;
  // A group may reach a/b the others do not (nu = 0.25 covers the flank's patches first): there
  // the patch is covered at that group's nu alone, not between it and the next.
  const Material between{80e9, 0.5 * (range.nu_min + range.nu_max)};
  const double only_at_steel = std::sqrt(range.a_over_b_max * at_steel.a_over_b_max);
  const Case cases[] = {
      {{5e-3, 5e-3 / too_slender, 0.3}, small, steel, "a/b = "},
      {{5e-3, 5e-3 / too_long, 0.3}, small, steel, "a/b = "},
      {{5e-3, 5e-3 / only_at_steel, 0.3}, small, between, "a/b = "},
      {{5e-3, 5e-3, range.psi_max + 0.05}, small, steel, "psi = "},
      {inside, small, {80e9, range.nu_max + 0.02}, "nu = "},
      {inside, creepages_for(inside, steel, at_steel.r_max * 1.05, 0.1, 0.3), steel,
       "normalised creepage"},
  };
  for (const Case& c : cases) {
    EXPECT_FALSE(creep_table_covers(c.sdec, c.creepages, kLoad, c.material)) << c.field;
    const std::string why =
        creep_table_outside(c.sdec, c.creepages, kLoad, c.material).value_or("(covered)");
    EXPECT_NE(why.find(c.field), std::string::npos) << why;
    try {
      creep_table_forces(c.sdec, c.creepages, kLoad, c.material);
      ADD_FAILURE() << "no InputError for " << c.field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("--method best"), std::string::npos) << e.what();
    }
  }
  // Invalid input is an InputError too, as everywhere, whichever entry is asked.
  EXPECT_THROW(creep_table_forces({5e-3, 5e-3, 1.0}, small, kLoad, steel), InputError);
  const Creepages not_a_number{std::nan(""), 0, 0};
  EXPECT_THROW(creep_table_forces(inside, not_a_number, kLoad, steel), InputError);
  EXPECT_THROW(creep_table_lookup(inside, not_a_number, kLoad, steel), InputError);
  EXPECT_THROW(creep_table_outside(inside, not_a_number, kLoad, steel), InputError);
  EXPECT_THROW(creep_table_covers(inside, not_a_number, kLoad, steel), InputError);
  EXPECT_THROW(creep_table_magnitude(inside, not_a_number, kLoad, steel), InputError);
  EXPECT_THROW(creep_table_lookup(inside, {0, std::nan(""), 0}, {-1.0, 0.3}, steel), InputError);
}

}  // namespace
}  // namespace wheelwear::tangential

namespace wheelwear::tangential {
namespace {

// CONTACT's exact theory on 80 x 80 grids (tests/data/contact/b_pure_spin_mx80.csv: pure spin
// at O, nu = 0.25, p0 = 1000 MPa) at every case the table answers (18 of them: the larger
// spins lie beyond r_max, far from full sliding). Bound: the 30 x 30 grid's distance from the
// converged answer (about 1 % of mu N on pure spin) plus the mean interpolation error (0.5 %): 1.5
// % of mu N in |dF|; measured worst 0.63 %, mean 0.37 %.
TEST(CreepTable, AgreesWithContactOnPureSpin) {
  constexpr double kGridAndInterpolation = 0.015;  // [mu N], see above
  // All 18 lie inside today; at least 15 of them must, so that the comparison cannot shrink.
  constexpr int kMinInside = 15;
  int inside = 0;
  double worst = 0, sum = 0;
  for (const testing::contact::PureSpinCase& c : testing::contact::pure_spin_cases()) {
    if (!creep_table_covers(c.patch, c.creepages, c.load, c.material)) continue;
    ++inside;
    const CreepForces f = creep_table_forces(c.patch, c.creepages, c.load, c.material);
    const double e = std::hypot(f.Fx / c.mu_N() - c.Fx_muN, f.Fy / c.mu_N() - c.Fy_muN);
    EXPECT_LT(e, kGridAndInterpolation)
        << c.set << " a/b " << c.g_label << " psi " << c.patch.psi << " phi " << c.creepages.phi;
    worst = std::max(worst, e);
    sum += e;
  }
  EXPECT_GE(inside, kMinInside);
  RecordProperty("inside", std::to_string(inside));
  RecordProperty("worst_muN", std::to_string(worst));
  std::printf("creep table vs CONTACT: %d cases, worst %.4f, mean %.4f of mu N\n", inside, worst,
              sum / std::max(inside, 1));
}

}  // namespace
}  // namespace wheelwear::tangential
