// Kalker's exact theory from the command line: `wheelwear creep --method exact`,
// `wheelwear contact --creep --tangential exact` and `wheelwear wear --exact` print the
// library's solutions, agree with CONTACT's, and refuse what does not apply to them.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/contact_cases.hpp"
#include "support/reference_profiles.hpp"
#include "support/run_command.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear {
namespace {

using testing::json_number;
using testing::run_wheelwear;

// The paper's reference case under pure spin (CONTACT's set b1, phi = 1 1/m).
const std::string kSpin =
    "creep --method exact --a 4.25e-3 --b 4.25e-3 --psi 0.6 --vx 0 --vy 0 --phi 1.0 --N 37830 "
    "--G 80e9 --nu 0.25 --mu 0.35 --json";

// The command prints exact_sdec's forces on the grid asked for (17 digits: round-trip exact),
// with the solver's outcome.
TEST(CreepExact, PrintsTheLibrarysExactSolution) {
  const auto r = run_wheelwear(kSpin + " --exact-grid 32");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  tangential::SdecGridOptions options;
  options.nx = options.ny = 32;
  const tangential::ExactSolution s = tangential::exact_sdec({4.25e-3, 4.25e-3, 0.6}, {0, 0, 1.0},
                                                             {37830, 0.35}, {80e9, 0.25}, options);
  EXPECT_EQ(json_number(r.out, "Fx"), s.forces.Fx);
  EXPECT_EQ(json_number(r.out, "Fy"), s.forces.Fy);
  EXPECT_EQ(json_number(r.out, "Mz"), *s.forces.Mz);
  EXPECT_EQ(json_number(r.out, "iterations"), s.iterations);
  EXPECT_EQ(json_number(r.out, "exact_grid"), 32);
  EXPECT_EQ(json_number(r.out, "cells"), s.contact_elements);
  EXPECT_EQ(json_number(r.out, "slip_cells"), s.slip_elements);
  EXPECT_EQ(json_number(r.out, "adhesion_fraction"),
            static_cast<double>(s.adhesion_elements) / s.contact_elements);
  EXPECT_NE(r.out.find("\"status\": \"converged\""), std::string::npos) << r.out;
  // The text output names the same outcome.
  const auto text = run_wheelwear(kSpin.substr(0, kSpin.size() - 7) + " --exact-grid 32");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("converged after"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("adhere"), std::string::npos) << text.out;
}

// The default 40 x 40 grid against CONTACT's 80 x 80 solution (b_pure_spin_mx80.csv, b1,
// phi = 1): within 1 % of mu N (the library's 40 x 40 error on these cases, measured 0.6 %,
// exact_contact_reference_test.cpp).
TEST(CreepExact, DefaultGridAgreesWithContact) {
  constexpr double kCoarseGrid = 0.01;  // [mu N], see above
  const auto r = run_wheelwear(kSpin);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int checked = 0;
  for (const testing::contact::PureSpinCase& c : testing::contact::pure_spin_cases()) {
    if (c.set != "b1" || c.creepages.phi != 1.0) continue;
    ++checked;
    EXPECT_NEAR(*json_number(r.out, "Fx_muN"), c.Fx_muN, kCoarseGrid);
    EXPECT_NEAR(*json_number(r.out, "Fy_muN"), c.Fy_muN, kCoarseGrid);
  }
  EXPECT_EQ(checked, 1);
  EXPECT_EQ(json_number(r.out, "exact_grid"), 40);
}

// What does not apply to the exact method is refused on stderr, naming the option.
TEST(CreepExact, RefusesWhatDoesNotApply) {
  auto refused = [](const std::string& args, const std::string& named) {
    const auto r = run_wheelwear(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
  };
  refused(kSpin + " --exact-grid 4", "--exact-grid");
  refused(kSpin + " --exact-grid 100000", "--exact-grid");
  refused(kSpin + " --target-error 1e-3", "--target-error");
  refused(kSpin + " --nx 20", "--nx");
  refused(kSpin + " --scheme second-order", "--scheme");
  refused(kSpin + " --N nan", "N = nan");
  std::string fastsim = kSpin;
  fastsim.replace(fastsim.find("exact"), 5, "fastsim-sdec");
  refused(fastsim + " --exact-grid 40", "--exact-grid");
}

// `contact --creep --tangential exact` on CONTACT's wheel/rail case y_ws = 4 mm: the exact
// keys are wheel_rail_exact's for the printed patch, FASTSIM-SDEC's keys are unchanged.
TEST(ContactExact, AddsTheExactSolutionPerPatch) {
  const std::string profiles = testing::test_data("contact/profiles/");
  const std::string args = "contact --wheel " + profiles + "MBench_S1002_v3.prw --rail " +
                           profiles +
                           "MBench_UIC60_v3.prr --incl 0 --dy -0.004 --load 55000 --E 200e9 "
                           "--nu 0.25 --mu 0.35 --vx 4.6e-4 --vy 1e-3 --phi -0.0238 --creep --json "
                           "--normal-method kik-piotrowski";
  const auto fastsim = run_wheelwear(args);
  const auto exact = run_wheelwear(args + " --tangential exact --exact-grid 36");
  ASSERT_EQ(fastsim.exit_code, 0) << fastsim.err;
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  for (const char* key : {"Fx", "Fy", "Mz", "N", "area"}) {
    ASSERT_TRUE(json_number(fastsim.out, key).has_value()) << key;
    EXPECT_EQ(json_number(exact.out, key), json_number(fastsim.out, key)) << key;
  }
  EXPECT_FALSE(json_number(fastsim.out, "exact_Fx").has_value());

  contactgeom::WheelsetPose pose;
  pose.dy = -0.004;
  const auto contact = contactgeom::solve_wheel_rail(testing::benchmark_pair(), pose, 55000);
  ASSERT_EQ(contact.patches.size(), 1u);
  tangential::WheelRailExactOptions options;
  options.nx = options.ny = 36;
  const tangential::WheelRailExactSolution s = tangential::wheel_rail_exact(
      testing::benchmark_pair(), pose, contact.patches[0], {4.6e-4, 1e-3, -0.0238}, 0.35, options);
  EXPECT_EQ(json_number(exact.out, "exact_Fx"), s.rolling.forces.Fx);
  EXPECT_EQ(json_number(exact.out, "exact_Fy"), s.rolling.forces.Fy);
  EXPECT_EQ(json_number(exact.out, "exact_Mz"), *s.rolling.forces.Mz);
  EXPECT_EQ(json_number(exact.out, "exact_approach"), s.approach);
  EXPECT_EQ(json_number(exact.out, "exact_nx"), 36);
  // The N check: the exact pressure carries the patch's normal force (stopping test 1e-8 N).
  EXPECT_NEAR(*json_number(exact.out, "exact_N"), *json_number(exact.out, "N"),
              1e-6 * *json_number(exact.out, "N"));
  EXPECT_NE(exact.out.find("\"exact_status\": \"converged\""), std::string::npos);
}

TEST(ContactExact, RefusesBadExactOptions) {
  const std::string args = "contact --dy 0 --load 55000 --creep --json";
  for (const std::string& bad : {std::string(" --tangential exact --exact-grid 2"),
                                 std::string(" --tangential exact --exact-margin 0.5"),
                                 std::string(" --tangential ideal")}) {
    const auto r = run_wheelwear(args + bad);
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_FALSE(r.err.empty()) << bad;
  }
  // --tangential needs --creep.
  const auto r = run_wheelwear("contact --dy 0 --load 55000 --tangential exact");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--creep"), std::string::npos) << r.err;
  // The exact method's options without it.
  for (const char* option : {"--exact-grid 40", "--exact-margin 1.5"}) {
    const auto ignored = run_wheelwear(args + " " + option);
    EXPECT_NE(ignored.exit_code, 0) << option;
    EXPECT_NE(ignored.err.find("applies only with --tangential exact"), std::string::npos)
        << ignored.err;
  }
  // The grid too snug for the exact area: the message says how to fix it.
  const auto snug = run_wheelwear(args + " --tangential exact --exact-margin 1");
  EXPECT_NE(snug.exit_code, 0);
  EXPECT_NE(snug.err.find("--exact-margin"), std::string::npos) << snug.err;
}

// `wear --exact` on new S1002/60E1 1:40 at dy 4 mm: the exact chain comes last, as model
// "exact", with wheel_rail_exact's forces for the printed patch and the rigid slip's work of
// them (exact_fields.hpp); the chosen model's keys are unchanged. Where it puts the work is
// tested against CONTACT in tests/wear/wear_contact_reference_test.cpp.
TEST(WearExact, AddsTheExactChainAfterTheModels) {
  const std::string args =
      "wear --dy 0.004 --load 55000 --vx 1e-3 --phi 0.1 --V 20 --mu 0.3 --json";
  const auto sdec = run_wheelwear(args);
  const auto both = run_wheelwear(args + " --exact --exact-grid 30");
  ASSERT_EQ(sdec.exit_code, 0) << sdec.err;
  ASSERT_EQ(both.exit_code, 0) << both.err;
  const std::size_t at = both.out.find("\"model\": \"exact\"");
  ASSERT_NE(at, std::string::npos) << both.out;
  const std::string exact = both.out.substr(at);
  for (const char* key : {"worn_volume_per_metre", "centroid_y_wheel", "frictional_work", "Fx"})
    EXPECT_EQ(json_number(both.out, key), json_number(sdec.out, key)) << key;

  contactgeom::WheelsetPose pose;
  pose.dy = 0.004;
  const contactgeom::WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  contactgeom::WheelRailOptions calibrated;  // the command's default normal method
  calibrated.kp.penetration = contactgeom::KpPenetration::hertz_calibrated;
  const auto contact = contactgeom::solve_wheel_rail(pair, pose, 55000, calibrated);
  ASSERT_EQ(contact.patches.size(), 1u);
  tangential::WheelRailExactOptions options;
  options.nx = options.ny = 30;
  const tangential::Creepages creepages{1e-3, 0.0, 0.1};
  const tangential::ExactSolution s =
      tangential::wheel_rail_exact(pair, pose, contact.patches[0], creepages, 0.3, options).rolling;
  // The same solve on the same patch (the contact found again in this process): equal to
  // rounding.
  EXPECT_NEAR(*json_number(exact, "Fx"), s.forces.Fx, 1e-9 * std::abs(s.forces.Fx));
  EXPECT_NEAR(*json_number(exact, "Fy"), s.forces.Fy, 1e-9 * std::abs(s.forces.Fy));
  const double rigid = tangential::rigid_slip_work(s.forces, creepages);
  EXPECT_NEAR(*json_number(exact, "frictional_work"), rigid, 1e-9 * rigid);
  EXPECT_GT(*json_number(exact, "worn_volume_per_metre"), 0.0);

  // With the rolling radius across the patch: the work is the rigid slip's, its rows' creepage
  // included (row_creepage_work).
  const auto radius = run_wheelwear(args + " --exact --exact-grid 30 --exact-radius-variation");
  ASSERT_EQ(radius.exit_code, 0) << radius.err;
  const std::string varied = radius.out.substr(radius.out.find("\"model\": \"exact\""));
  options.radius_variation = true;
  const tangential::ExactSolution r =
      tangential::wheel_rail_exact(pair, pose, contact.patches[0], creepages, 0.3, options).rolling;
  EXPECT_NE(r.row_creepage_work, 0.0);
  const double varied_work = tangential::rigid_slip_work(r.forces, creepages) + r.row_creepage_work;
  EXPECT_NEAR(*json_number(varied, "frictional_work"), varied_work, 1e-9 * varied_work);
  EXPECT_NE(json_number(varied, "Fx"), json_number(exact, "Fx"));
}

TEST(WearExact, RefusesItsOptionsWithoutIt) {
  const std::string args = "wear --dy 0.004 --load 55000 --vx 1e-3 --json";
  for (const char* option : {"--exact-grid 40", "--exact-margin 1.5", "--exact-radius-variation"}) {
    const auto r = run_wheelwear(args + " " + option);
    EXPECT_NE(r.exit_code, 0) << option;
    EXPECT_NE(r.err.find("applies only with --exact"), std::string::npos) << r.err;
  }
  const auto bad = run_wheelwear(args + " --exact --exact-grid 2");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--exact-grid"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace wheelwear
