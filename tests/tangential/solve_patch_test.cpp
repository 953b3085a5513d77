// The entry point solve_patch: every method name, the dispatch to each method's own solver,
// the frictional work of best and exact against the power balance of the rigid slip, the
// fallback of best outside the book of tables, and a reused solution that keeps nothing stale.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/linear_theory.hpp"
#include "wheelwear/tangential/table_correction.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::tangential {
namespace {

// The paper's reference patch (a = 4.25 mm, psi = 0.6) with combined creepage, p0 = 1000 MPa.
const contactgeom::Sdec kPatch{4.25e-3, 3.0e-3, 0.6};
const Creepages kCreep{4e-4, -3e-4, 0.8};
const ContactLoad kLoad{2.0 / 3.0 * 1e9 * 3.14159265358979 * 4.25e-3 * 3.0e-3, 0.35};
const Material kSteel{80e9, 0.25};

SolveOptions small_grids(bool cells) {
  SolveOptions o;
  o.fastsim.nx = o.fastsim.ny = 20;
  o.fastsim.cell_fields = cells;
  o.exact_grid.nx = o.exact_grid.ny = 20;
  return o;
}

TEST(SolvePatch, EveryMethodNameRoundTrips) {
  int compared = 0;
  for (const auto& [method, name] : kMethodNames) {
    EXPECT_EQ(parse_method(name), method) << name;
    EXPECT_EQ(method_name(method), name);
    EXPECT_EQ(has_cell_fields(method),
              fastsim_variant(method).has_value() || method == Method::exact)
        << name;
    ++compared;
  }
  EXPECT_EQ(compared, 10);
  EXPECT_FALSE(parse_method("fastsim").has_value());
}

// Each method answers what its own solver answers, bit for bit: the entry point adds nothing.
TEST(SolvePatch, DispatchesToEachMethodsSolver) {
  const SolveOptions o = small_grids(false);
  int compared = 0;
  for (const auto& [method, name] : kMethodNames) {
    const TangentialSolution s = solve_patch(method, kPatch, kCreep, kLoad, kSteel, o);
    CreepForces expected;
    if (const auto variant = fastsim_variant(method); variant && method != Method::best) {
      expected = fastsim(*variant, kPatch, kCreep, kLoad, kSteel, o.fastsim).forces;
    } else if (method == Method::linear_sdec) {
      expected = linear_sdec_forces(kPatch, kCreep, kSteel);
    } else if (method == Method::she_sdec) {
      expected = she_sdec_forces(kPatch, kCreep, kSteel, kLoad);
    } else if (method == Method::exact) {
      expected = exact_sdec(kPatch, kCreep, kLoad, kSteel, o.exact_grid, o.exact_solver).forces;
    } else {  // table, best inside the table
      expected = creep_table_forces(kPatch, kCreep, kLoad, kSteel);
      EXPECT_TRUE(s.from_table) << name;
    }
    EXPECT_EQ(s.forces.Fx, expected.Fx) << name;
    EXPECT_EQ(s.forces.Fy, expected.Fy) << name;
    EXPECT_EQ(s.forces.Mz, expected.Mz) << name;
    EXPECT_EQ(s.status, SolveStatus::ok) << name;
    ++compared;
  }
  EXPECT_EQ(compared, 10);
}

// In steady rolling the elastic part of the slip does no net work, so the frictional work is
// the rigid slip's, -(Fx vx + Fy vy + Mz phi): best and exact report exactly that, with cells
// (their sum) and without (rounding of the cells' sum: 1e-12 relative).
TEST(SolvePatch, BestAndExactWorkIsTheRigidSlipsWork) {
  int compared = 0;
  for (const Method method : {Method::best, Method::exact})
    for (const bool cells : {false, true}) {
      const TangentialSolution s =
          solve_patch(method, kPatch, kCreep, kLoad, kSteel, small_grids(cells));
      const double rigid = rigid_slip_work(s.forces, kCreep);
      ASSERT_GT(rigid, 0.0);
      EXPECT_NEAR(s.frictional_work, rigid, 1e-12 * rigid) << method_name(method) << cells;
      EXPECT_EQ(s.fields.has_value(), cells) << method_name(method);
      if (cells) {
        double sum = 0.0;
        const CellFields& f = *s.fields;
        for (int j = 0; j < f.ny; ++j)
          for (int i = 0; i < f.nx; ++i)
            sum += f.work[static_cast<std::size_t>(j * f.nx + i)] *
                   f.dx[static_cast<std::size_t>(j)] * f.dy;
        EXPECT_NEAR(sum, rigid, 1e-12 * rigid) << method_name(method);
      }
      ++compared;
    }
  EXPECT_EQ(compared, 4);
}

// Outside the table (|psi| beyond its range) best is FASTSIM-SDEC and says why.
TEST(SolvePatch, BestOutsideTheTableIsFastsimSdecWithItsReason) {
  const contactgeom::Sdec outside{4.25e-3, 3.0e-3, 0.95};
  const SolveOptions o = small_grids(true);
  const TangentialSolution best = solve_patch(Method::best, outside, kCreep, kLoad, kSteel, o);
  const TangentialSolution plain =
      solve_patch(Method::fastsim_sdec, outside, kCreep, kLoad, kSteel, o);
  EXPECT_FALSE(best.from_table);
  ASSERT_TRUE(best.table_outside.has_value());
  EXPECT_NE(best.table_outside->find("psi"), std::string::npos) << *best.table_outside;
  EXPECT_EQ(best.forces.Fx, plain.forces.Fx);
  EXPECT_EQ(best.forces.Fy, plain.forces.Fy);
  EXPECT_EQ(best.frictional_work, plain.frictional_work);
}

// One solution reused across methods (as a loop over patches does) keeps nothing of the last.
TEST(SolvePatch, ReusedSolutionKeepsNothingStale) {
  TangentialSolution s;
  solve_patch(Method::exact, kPatch, kCreep, kLoad, kSteel, small_grids(true), s);
  ASSERT_TRUE(s.exact.has_value());
  ASSERT_TRUE(s.fields.has_value());
  solve_patch(Method::linear_sdec, kPatch, kCreep, kLoad, kSteel, small_grids(true), s);
  EXPECT_FALSE(s.exact.has_value());
  EXPECT_FALSE(s.fields.has_value());
  EXPECT_FALSE(s.from_table);
  EXPECT_EQ(s.cells, 0);
  EXPECT_EQ(s.frictional_work, 0.0);
  solve_patch(Method::best, kPatch, kCreep, kLoad, kSteel, small_grids(false), s);
  EXPECT_TRUE(s.from_table);
  solve_patch(Method::fastsim_eql, kPatch, kCreep, kLoad, kSteel, small_grids(true), s);
  EXPECT_FALSE(s.from_table);
  EXPECT_FALSE(s.table_outside.has_value());
  EXPECT_TRUE(s.fields.has_value());
  EXPECT_EQ(s.cells, 400);
  const TangentialSolution fresh =
      solve_patch(Method::fastsim_eql, kPatch, kCreep, kLoad, kSteel, small_grids(true));
  EXPECT_EQ(s.forces.Fx, fresh.forces.Fx);
  EXPECT_EQ(s.frictional_work, fresh.frictional_work);
}

// An exact solve capped at two iterations is a status, not an error.
TEST(SolvePatch, UnconvergedExactSolveIsAStatus) {
  SolveOptions o = small_grids(false);
  o.exact_solver.max_iterations = 2;
  const TangentialSolution s = solve_patch(Method::exact, kPatch, kCreep, kLoad, kSteel, o);
  EXPECT_EQ(s.status, SolveStatus::not_converged);
  EXPECT_EQ(status_name(s.status), "not converged");
  EXPECT_FALSE(s.message.empty());
}

}  // namespace
}  // namespace wheelwear::tangential
