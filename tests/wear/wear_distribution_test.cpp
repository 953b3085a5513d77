// Wear of one contact mapped onto the wheel profile: conservation, linearity, and where the
// wear lands for the SDEC and the equivalent-ellipse models.

#include "wheelwear/wear/wear_distribution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::wear {

// The patches these tests wear are solved by the tangential library.
using namespace wheelwear::tangential;
namespace {

using contactgeom::Sdec;

const Material kSteel{80e9, 0.25};
constexpr double kSpeed = 20.0;  // m/s

TangentialSolution solve(FastsimMethod method, const Sdec& patch, const Creepages& v,
                         const ContactLoad& load, int n = 60) {
  FastsimOptions options;
  options.nx = options.ny = n;
  options.cell_fields = true;
  return fastsim(method, patch, v, load, kSteel, options);
}

WearDistribution grid() {
  return WearDistribution::zeros(-15e-3, 0.1e-3, 301);
}

// The mapping moves each strip's worn area into the bins it overlaps: the distribution holds
// exactly the worn area of the cells (to rounding).
TEST(WearDistribution, ConservesTheWornArea) {
  const Sdec patch{5e-3, 4e-3, 0.5};
  const ContactLoad load{60e3, 0.3};
  for (const WearLaw& law : {*default_wear_law("usfd"), *default_wear_law("archard")}) {
    const TangentialSolution s = solve(FastsimMethod::sdec, patch, {2e-3, 1e-3, 1.5}, load);
    WearDistribution w = grid();
    const double outside = accumulate_wear(*s.fields, kSpeed, law, {0.0, 0.46}, 1.0, w);
    const double cells = cell_wear_area(*s.fields, kSpeed, law, 0.46);
    EXPECT_GT(cells, 0.0);
    EXPECT_EQ(outside, 0.0);
    EXPECT_NEAR(w.area() / cells, 1.0, 1e-12) << law_name(law);
  }
}

// The wear field set carries everything accumulate_wear() reads: the same distribution.
TEST(WearDistribution, WearFieldSetGivesTheSameWear) {
  const Sdec patch{5e-3, 4e-3, 0.4};
  const ContactLoad load{60e3, 0.3};
  FastsimOptions options;
  options.nx = 50;
  options.ny = 45;
  options.cell_fields = true;
  for (const WearLaw& law : {*default_wear_law("usfd"), *default_wear_law("archard")}) {
    options.field_set = CellFieldSet::all;
    const TangentialSolution all =
        fastsim(FastsimMethod::sdec, patch, {2e-3, 1e-3, 1.5}, load, kSteel, options);
    options.field_set = CellFieldSet::wear;
    const TangentialSolution wear =
        fastsim(FastsimMethod::sdec, patch, {2e-3, 1e-3, 1.5}, load, kSteel, options);
    WearDistribution a = grid(), w = grid();
    accumulate_wear(*all.fields, kSpeed, law, {0.0, 0.46}, 1.0, a);
    accumulate_wear(*wear.fields, kSpeed, law, {0.0, 0.46}, 1.0, w);
    ASSERT_GT(a.area(), 0.0);
    for (std::size_t k = 0; k < a.depth.size(); ++k) {
      // Both sets run the same arithmetic: equal to a few roundings.
      EXPECT_NEAR(w.depth[k], a.depth[k], 1e-12 * a.depth[k]) << law_name(law) << " bin " << k;
    }
  }
}

// Pure rolling wears nothing; the weight (share of running distance) scales the wear exactly.
TEST(WearDistribution, NoCreepNoWearAndLinearInDistance) {
  const Sdec patch{5e-3, 4e-3, 0.3};
  const ContactLoad load{60e3, 0.3};
  const WearLaw law = *default_wear_law("usfd");
  WearDistribution rolling = grid();
  accumulate_wear(*solve(FastsimMethod::sdec, patch, {}, load).fields, kSpeed, law, {0.0, 0.46},
                  1.0, rolling);
  EXPECT_EQ(rolling.area(), 0.0);

  const TangentialSolution s = solve(FastsimMethod::sdec, patch, {3e-3, 0, 0.5}, load);
  WearDistribution once = grid(), twice = grid();
  accumulate_wear(*s.fields, kSpeed, law, {0.0, 0.46}, 1.0, once);
  accumulate_wear(*s.fields, kSpeed, law, {0.0, 0.46}, 2.0, twice);
  for (std::size_t k = 0; k < once.depth.size(); ++k)
    EXPECT_NEAR(twice.depth[k], 2.0 * once.depth[k], 1e-15 + 1e-12 * once.depth[k]);
}

// In the USFD law's first regime (K = 5.3 T gamma/A) the wear is proportional to the frictional
// work; in full sliding that is mu N |vx| per metre rolled, so wear vanishes with friction.
TEST(WearDistribution, VanishesWithFriction) {
  const Sdec patch{5e-3, 4e-3, 0.3};
  const WearLaw law = *default_wear_law("usfd");
  auto area = [&](double mu) {
    WearDistribution w = grid();
    accumulate_wear(*solve(FastsimMethod::sdec, patch, {0.05, 0, 0}, {60e3, mu}).fields, kSpeed,
                    law, {0.0, 0.46}, 1.0, w);
    return w.area();
  };
  const double a1 = area(0.02), a2 = area(0.01);
  // Nearly full sliding at both: proportional to mu up to the thin adhesion zone at the leading
  // edge, whose share of the patch changes with mu by less than 1e-3.
  EXPECT_NEAR(a1 / a2, 2.0, 2e-3);
  EXPECT_LT(area(1e-9), 1e-6 * a1);
}

// Where the wear lands. In full sliding under vx, with a law linear in T gamma, a strip wears
// in proportion to the integral of the parabolic bound over its length, i.e. to x_l(y)^3.
// Over the SDEC's two half-ellipses (semi-widths b(1 +- psi)) the centroid of x_l^3 lies
// 32 psi b / (15 pi) from O towards +y; the centred ellipse puts it at O, the shifted one at
// psi b. On the wheel the arc length runs against +y.
TEST(WearDistribution, LocatesWearAsTheContactModelPlacesThePatch) {
  const double b = 4e-3, psi = 0.6;
  const Sdec patch{5e-3, b, psi};
  const ContactLoad load{60e3, 0.02};  // low friction keeps T gamma/A in the linear regime
  const Creepages sliding{0.05, 0, 0};
  const WearLaw law = *default_wear_law("usfd");
  auto centroid = [&](FastsimMethod m) {
    WearDistribution w = grid();
    accumulate_wear(*solve(m, patch, sliding, load, 120).fields, kSpeed, law, {0.0, 0.46}, 1.0, w);
    return summarise(w).centroid_s;
  };
  const double cell = 2 * b / 120;  // a strip: the mapping's resolution
  EXPECT_NEAR(centroid(FastsimMethod::sdec), -32 * psi * b / (15 * std::numbers::pi), cell);
  EXPECT_NEAR(centroid(FastsimMethod::eql), -32 * psi * b / (15 * std::numbers::pi), cell);
  EXPECT_NEAR(centroid(FastsimMethod::eqe), 0.0, cell);
  EXPECT_NEAR(centroid(FastsimMethod::eqe_shifted), -psi * b, cell);
}

// For an ellipse (psi = 0) every model puts the wear at the same place.
TEST(WearDistribution, AllModelsAgreeOnASymmetricEllipse) {
  const Sdec ellipse{5e-3, 4e-3, 0.0};
  const ContactLoad load{60e3, 0.3};
  const WearLaw law = *default_wear_law("usfd");
  // Within one strip of the 60 across 2b: the resolution of the strip grid.
  const double one_strip = 2 * ellipse.b / 60;  // [m]
  double first = 0.0;
  bool have_first = false;
  for (FastsimMethod m : {FastsimMethod::sdec, FastsimMethod::eql, FastsimMethod::eqe,
                          FastsimMethod::eqe_shifted, FastsimMethod::elliptic}) {
    WearDistribution w = grid();
    accumulate_wear(*solve(m, ellipse, {3e-3, 0, 0}, load).fields, kSpeed, law, {0.0, 0.46}, 1.0,
                    w);
    const double c = summarise(w).centroid_s;
    if (!have_first) {
      first = c;
      have_first = true;
    }
    EXPECT_NEAR(c, first, one_strip) << method_name(m);
    EXPECT_NEAR(c, 0.0, one_strip) << method_name(m);
  }
}

TEST(WearDistribution, ReportsWearOutsideItsGridAndRejectsBadInput) {
  const Sdec patch{5e-3, 4e-3, 0.0};
  const TangentialSolution s = solve(FastsimMethod::sdec, patch, {3e-3, 0, 0}, {60e3, 0.3});
  const WearLaw law = *default_wear_law("usfd");
  WearDistribution narrow = WearDistribution::zeros(0.0, 0.1e-3, 10);
  const double outside = accumulate_wear(*s.fields, kSpeed, law, {0.0, 0.46}, 1.0, narrow);
  EXPECT_NEAR(outside + narrow.area(), cell_wear_area(*s.fields, kSpeed, law, 0.46), 1e-20);
  EXPECT_GT(outside, 0.0);
  WearDistribution w = grid();
  EXPECT_THROW(accumulate_wear(*s.fields, -1.0, law, {0.0, 0.46}, 1.0, w), InputError);
  EXPECT_THROW(accumulate_wear(*s.fields, kSpeed, law, {0.0, 0.0}, 1.0, w), InputError);
  EXPECT_THROW(w.add(narrow, 1.0), InputError);
}

}  // namespace
}  // namespace wheelwear::wear
