// A wide conformal patch (a hollow-worn wheel, tests/support/hollow_wheel.hpp): where the chain
// of the runs (Hertz-calibrated strips -> SDEC -> FASTSIM-SDEC -> USFD) puts the wear across the
// wheel against the exact chain on the same gap (Kalker's exact normal problem and steady
// rolling on the undeformed distance, wheel_rail_exact, into the same wear law and mapping).
// The bounds are the deviations measured, rounded up: they document what the SDEC
// regularisation loses on such a patch (docs/normal-contact.md, "Wide conformal patches").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/hollow_wheel.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/tangential/exact/exact_fields.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"
#include "wheelwear/tangential/tangential.hpp"
#include "wheelwear/wear/wear_distribution.hpp"
#include "wheelwear/wear/wear_law_tgamma.hpp"

namespace wheelwear::wear {
namespace {

using tangential::Creepages;

constexpr double kLoad = 150e3;  // [N] a heavy-haul wheel (30 t axle)
constexpr double kMu = 0.3;
constexpr double kSpeed = 20.0;  // [m/s]

struct ChainWear {
  WearSummary wear;
  double frictional_work = 0.0;  // [N]
};

// Wear per metre running on 0.1 mm bins of the wheel's arc length about O.
ChainWear wear_of(const tangential::TangentialSolution& s, const contactgeom::WheelRailPatch& p) {
  WearDistribution d = WearDistribution::zeros(p.s_wheel - 40e-3, 0.1e-3, 801);
  const double outside =
      accumulate_wear(*s.fields, kSpeed, TgammaLaw::usfd(), {p.s_wheel, p.rolling_radius}, 1.0, d);
  EXPECT_EQ(outside, 0.0);
  return {summarise(d), s.frictional_work};
}

// The SDEC patch with FASTSIM-SDEC (fastsim) or with the book of tables' exact totals spread
// as FASTSIM-SDEC spreads them (best).
ChainWear sdec_chain(tangential::Method method, const contactgeom::WheelRailPatch& p,
                     const Creepages& creepages) {
  tangential::SolveOptions options;
  options.fastsim.nx = options.fastsim.ny = 50;
  options.fastsim.cell_fields = true;
  return wear_of(tangential::solve_patch(method, p.sdec, creepages, {p.normal_force, kMu},
                                         {80e9, 0.25}, options),
                 p);
}

struct ExactChain {
  ChainWear chain;
  double area = 0.0, pmax = 0.0;
};

ExactChain exact_chain(const contactgeom::WheelRailPair& pair, const contactgeom::WheelRailPatch& p,
                       const Creepages& creepages) {
  tangential::WheelRailExactOptions grid;
  grid.nx = 80;   // 0.24 mm along x over 1.4 times the 14 mm length (40: 0.1 mm off in
                  // the centroid, 1 % in the work)
  grid.ny = 160;  // 0.3 mm across 1.4 times the 37 mm width
  grid.margin = 1.4;
  const tangential::WheelRailExactSolution e =
      tangential::wheel_rail_exact(pair, {}, p, creepages, kMu, grid);
  EXPECT_EQ(e.rolling.status, tangential::ExactStatus::converged) << e.rolling.message;
  const double pmax = *std::max_element(e.rolling.pn.begin(), e.rolling.pn.end());
  return {wear_of(tangential::exact_tangential_solution(e.rolling, creepages), p), e.contact_area,
          pmax};
}

double relative(double value, double reference) {
  return value / reference - 1.0;
}

TEST(ConformalPatch, SdecChainPlacesTheWearOfAWidePatchWhereTheExactChainDoes) {
  const contactgeom::WheelRailPair pair(testing::hollow_worn_s1002(), profiles::rail_60e1());
  contactgeom::WheelRailOptions calibrated;  // the runs' normal method
  calibrated.kp.penetration = contactgeom::KpPenetration::hertz_calibrated;
  const contactgeom::WheelRailContact c =
      contactgeom::solve_wheel_rail(pair, {}, kLoad, calibrated);
  ASSERT_EQ(c.status, contactgeom::WheelRailStatus::ok) << c.message;
  ASSERT_EQ(c.patches.size(), 1u);
  const contactgeom::WheelRailPatch& p = c.patches[0];
  ASSERT_GT(p.measures.width, 30e-3);  // the case is the wide conformal patch it stands for

  // A curving wheel's creepages, and pure spin (a free-rolling wheel on its tread).
  for (const Creepages& creepages : {Creepages{1e-3, 1e-3, 0.1}, Creepages{0.0, 0.0, 0.05}}) {
    const std::string label =
        "vx " + std::to_string(creepages.vx) + " phi " + std::to_string(creepages.phi);
    const ChainWear fastsim = sdec_chain(tangential::Method::fastsim_sdec, p, creepages);
    const ChainWear best = sdec_chain(tangential::Method::best, p, creepages);
    const ExactChain exact = exact_chain(pair, p, creepages);
    const WearSummary& e = exact.chain.wear;
    std::printf(
        "%s: area %+.2f %%, pmax %+.2f %%; centroid %+.3f mm, band %+.2f %%; work fastsim %+.2f "
        "%%, best %+.2f %%; worn volume fastsim %+.2f %%, best %+.2f %%\n",
        label.c_str(), 100 * relative(p.measures.area, exact.area),
        100 * relative(p.pmax, exact.pmax), 1e3 * (fastsim.wear.centroid_s - e.centroid_s),
        100 * relative(fastsim.wear.band_width, e.band_width),
        100 * relative(fastsim.frictional_work, exact.chain.frictional_work),
        100 * relative(best.frictional_work, exact.chain.frictional_work),
        100 * relative(fastsim.wear.volume_per_metre, e.volume_per_metre),
        100 * relative(best.wear.volume_per_metre, e.volume_per_metre));
    // Normal problem (measured -0.5 %, +0.2 %): over this flat gap the calibrated strips
    // carry the load as the exact normal solve does; 5 %, the bound of the flank's sweep.
    EXPECT_LT(std::abs(relative(p.measures.area, exact.area)), 0.05) << label;
    EXPECT_LT(std::abs(relative(p.pmax, exact.pmax)), 0.05) << label;
    // Where the wear lands (best spreads its work as FASTSIM-SDEC does): the centroid within
    // 1 mm across the 37 mm band (measured 0.63 and 0.21 mm), the band within 5 % (-2.8 %,
    // +1.4 %).
    EXPECT_LT(std::abs(fastsim.wear.centroid_s - e.centroid_s), 1e-3) << label;
    EXPECT_LT(std::abs(relative(fastsim.wear.band_width, e.band_width)), 0.05) << label;
    // How much: with the book of tables' exact totals within 5 % (+2.5 %, +0.6 %), both in
    // frictional work and in worn volume; FASTSIM-SDEC alone within 15 % on the curving wheel
    // (-9.1 %) and 35 % under pure spin (-27 %): its spin error over a wide patch.
    const double fastsim_bound = creepages.vx != 0.0 ? 0.15 : 0.35;
    EXPECT_LT(std::abs(relative(fastsim.frictional_work, exact.chain.frictional_work)),
              fastsim_bound)
        << label;
    EXPECT_LT(std::abs(relative(fastsim.wear.volume_per_metre, e.volume_per_metre)), fastsim_bound)
        << label;
    EXPECT_LT(std::abs(relative(best.frictional_work, exact.chain.frictional_work)), 0.05) << label;
    EXPECT_LT(std::abs(relative(best.wear.volume_per_metre, e.volume_per_metre)), 0.05) << label;
  }
}

}  // namespace
}  // namespace wheelwear::wear
