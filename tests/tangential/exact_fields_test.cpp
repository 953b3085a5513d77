// The exact theory's solution as per-cell fields for the wear laws (exact_fields.hpp).

#include "wheelwear/tangential/exact/exact_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::tangential {
namespace {

const ContactLoad kLoad{2e4, 0.3};
const Material kSteel{80e9, 0.28};
const contactgeom::Sdec kPatch{5e-3, 3e-3, 0.4};
const Creepages kCreepages{5e-4, -8e-4, 1.0};

ExactSolution solve(int n) {
  SdecGridOptions options;
  options.nx = options.ny = n;
  return exact_sdec(kPatch, kCreepages, kLoad, kSteel, options);
}

// The fields carry the solution unchanged but for one factor on slip and work, which makes the
// work sum to the totals' rigid-slip work (conservation, to rounding); the pressure still sums
// to the grid's normal force.
TEST(ExactFields, CarryTheSolutionWithTheWorkOfItsTotals) {
  const ExactSolution exact = solve(30);
  const TangentialSolution s = exact_tangential_solution(exact, kCreepages);
  EXPECT_EQ(s.forces.Fx, exact.forces.Fx);
  EXPECT_EQ(*s.forces.Mz, *exact.forces.Mz);
  ASSERT_TRUE(s.fields);
  const CellFields& f = *s.fields;
  ASSERT_EQ(f.nx, 30);
  ASSERT_EQ(f.ny, 30);
  double slip_work = 0.0;  // sum |p| |s| dA of the solution's elements
  for (std::size_t k = 0; k < exact.px.size(); ++k)
    slip_work += std::hypot(exact.px[k], exact.py[k]) * std::hypot(exact.sx[k], exact.sy[k]) *
                 exact.grid.area();
  const double factor = s.frictional_work / slip_work;
  double work = 0.0, force = 0.0;
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const auto k = static_cast<std::size_t>(j * f.nx + i);
      const double area = f.dx[static_cast<std::size_t>(j)] * f.dy;
      work += f.work[k] * area;
      force += f.pressure[k] * area;
      EXPECT_EQ(f.px[k], exact.px[k]);
      EXPECT_NEAR(f.slip_norm[k], factor * std::hypot(exact.sx[k], exact.sy[k]),
                  1e-12 * f.slip_norm[k] + 1e-300);
      EXPECT_NEAR(f.y[k], f.strip_y[static_cast<std::size_t>(j)], 1e-15);
    }
  }
  EXPECT_NEAR(work, rigid_slip_work(exact.forces, kCreepages), 1e-12 * work);
  EXPECT_NEAR(force, exact.normal_force, 1e-9 * force);
}

// The factor removes the first-order error of the slip's work: it tends to 1 as the grid is
// refined (measured 0.891 at 20, 0.942 at 40, 0.970 at 80 elements per side for this case),
// at the rate of the element size (the distance from 1 halves when the elements do, within
// 30 %).
TEST(ExactFields, WorkCorrectionVanishesWithTheElementSize) {
  double previous = 0.0;
  for (int n : {20, 40, 80}) {
    const ExactSolution exact = solve(n);
    const double gap =
        std::abs(exact.frictional_work / rigid_slip_work(exact.forces, kCreepages) - 1.0);
    if (previous > 0.0) {
      EXPECT_NEAR(gap / previous, 0.5, 0.15) << "n " << n;
    }
    previous = gap;
  }
}

}  // namespace
}  // namespace wheelwear::tangential
