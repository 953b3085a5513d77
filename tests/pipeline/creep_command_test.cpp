// The `wheelwear creep` command: its JSON contract and its handling of bad input.

#include <gtest/gtest.h>

#include "support/run_command.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/grid_choice.hpp"
#include "wheelwear/tangential/linear_theory.hpp"

namespace wheelwear {
namespace {

using testing::json_number;
using testing::run_wheelwear;

const std::string kCase =
    "creep --a 4.25e-3 --b 4.25e-3 --psi 0.6 --vx 0 --vy 0 --phi 1.0 --N 37830 --G 80e9 "
    "--nu 0.25 --mu 0.35 --json";

// The command prints the library's forces (17 significant digits: round-trip exact).
TEST(CreepCommand, PrintsTheLibrarysForcesAsJson) {
  const auto result = run_wheelwear(kCase + " --method fastsim-sdec --nx 30 --ny 20");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  tangential::FastsimOptions options;
  options.nx = 30;
  options.ny = 20;
  const tangential::CreepForces f =
      tangential::fastsim(tangential::FastsimMethod::sdec, {4.25e-3, 4.25e-3, 0.6}, {0, 0, 1.0},
                          {37830, 0.35}, {80e9, 0.25}, options)
          .forces;
  EXPECT_EQ(json_number(result.out, "Fx"), f.Fx);
  EXPECT_EQ(json_number(result.out, "Fy"), f.Fy);
  EXPECT_NEAR(*json_number(result.out, "Fx_muN"), f.Fx / (0.35 * 37830), 1e-15);
  EXPECT_NEAR(*json_number(result.out, "Fy_muN"), f.Fy / (0.35 * 37830), 1e-15);
}

TEST(CreepCommand, EveryMethodAnswersWithTheContractKeys) {
  for (const char* method : {"fastsim-sdec", "fastsim-eql", "fastsim-eqe", "fastsim-eqe-shifted",
                             "fastsim-elliptic", "linear-sdec", "she-sdec", "table", "best"}) {
    const auto result = run_wheelwear(kCase + " --method " + method);
    ASSERT_EQ(result.exit_code, 0) << method << ": " << result.err;
    for (const char* key : {"Fx", "Fy", "Fx_muN", "Fy_muN"})
      EXPECT_TRUE(json_number(result.out, key).has_value()) << method << " lacks " << key;
  }
  const auto linear = run_wheelwear(kCase + " --method linear-sdec");
  const tangential::CreepForces f =
      tangential::linear_sdec_forces({4.25e-3, 4.25e-3, 0.6}, {0, 0, 1.0}, {80e9, 0.25});
  EXPECT_EQ(json_number(linear.out, "Fx"), f.Fx);
}

// --target-error picks the grid of grid_choice.hpp, reports it, and the forces are the
// library's on that grid.
TEST(CreepCommand, TargetErrorChoosesAndReportsTheGrid) {
  const auto result =
      run_wheelwear(kCase + " --method fastsim-sdec --scheme second-order --target-error 1e-3");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const tangential::GridChoice choice = tangential::choose_grid(
      tangential::FastsimMethod::sdec, tangential::FastsimScheme::second_order,
      tangential::TractionBound::parabolic, 1e-3);
  EXPECT_EQ(json_number(result.out, "nx"), choice.nx);
  EXPECT_EQ(json_number(result.out, "ny"), choice.ny);
  EXPECT_EQ(json_number(result.out, "target_error"), 1e-3);
  EXPECT_EQ(json_number(result.out, "predicted_error"), choice.predicted_error);
  EXPECT_EQ(json_number(result.out, "cells"), choice.nx * choice.ny);
  tangential::FastsimOptions options;
  options.nx = choice.nx;
  options.ny = choice.ny;
  options.scheme = tangential::FastsimScheme::second_order;
  const tangential::CreepForces f =
      tangential::fastsim(tangential::FastsimMethod::sdec, {4.25e-3, 4.25e-3, 0.6}, {0, 0, 1.0},
                          {37830, 0.35}, {80e9, 0.25}, options)
          .forces;
  EXPECT_EQ(json_number(result.out, "Fx"), f.Fx);
  EXPECT_EQ(json_number(result.out, "Fy"), f.Fy);
  // Without --target-error the output keeps its keys and adds none.
  const auto plain = run_wheelwear(kCase + " --method fastsim-sdec");
  EXPECT_FALSE(json_number(plain.out, "target_error").has_value());
  EXPECT_FALSE(json_number(plain.out, "nx").has_value());
}

// Bad input: a message on stderr that names the problem, a non-zero exit, nothing on stdout.
TEST(CreepCommand, RejectsBadInputWithAMessage) {
  struct Case {
    std::string arguments, expected_in_message;
  };
  const Case cases[] = {
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --psi 1.0", "psi"},
      {"creep --a 4e-3 --b 4e-3 --N nan", "N = nan"},
      {"creep --a -4e-3 --b 4e-3 --N 1e4", "a = -0.004"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --mu 0", "mu = 0"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --nu 0.7", "nu = 0.7"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --nx 0", "nx = 0"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --method fastsim", "method"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --bogus 1", "--bogus"},
      {"creep --a 4e-3 --b 4e-3", "--N"},
      {"nosuchcommand --help", "unknown command"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --target-error 1e-3 --nx 20", "--target-error"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --target-error 0", "target_error = 0"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --target-error 1e-7", "raise the target"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --target-error 1e-3 --method she-sdec", "has no grid"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --target-error 1e-3 --method table", "has no grid"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --psi 0.9 --vx 1e-4 --method table", "psi = 0.9"},
      {"creep --a 4e-3 --b 4e-3 --N 1e4 --nu 0.4 --vx 1e-4 --method table", "nu = 0.4"},
  };
  for (const Case& c : cases) {
    const auto result = run_wheelwear(c.arguments);
    EXPECT_NE(result.exit_code, 0) << c.arguments;
    EXPECT_NE(result.err.find(c.expected_in_message), std::string::npos)
        << c.arguments << " printed: " << result.err;
    EXPECT_TRUE(result.out.empty()) << c.arguments;
  }
}

// --method table prints the library's interpolated forces; --method best with --inside-table
// table takes the table inside its range and FASTSIM-SDEC (with the given grid) outside, and
// says which in "source".
TEST(CreepCommand, TableAndBestReportTheirSource) {
  const auto table = run_wheelwear(kCase + " --method table");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  const tangential::CreepForces f = tangential::creep_table_forces(
      {4.25e-3, 4.25e-3, 0.6}, {0, 0, 1.0}, {37830, 0.35}, {80e9, 0.25});
  EXPECT_EQ(json_number(table.out, "Fx"), f.Fx);
  EXPECT_EQ(json_number(table.out, "Fy"), f.Fy);
  EXPECT_NE(table.out.find("\"source\": \"table\""), std::string::npos) << table.out;
  EXPECT_FALSE(json_number(table.out, "cells").has_value());

  const auto best = run_wheelwear(kCase + " --method best --inside-table table");
  ASSERT_EQ(best.exit_code, 0) << best.err;
  EXPECT_EQ(json_number(best.out, "Fx"), f.Fx);
  EXPECT_NE(best.out.find("\"source\": \"table\""), std::string::npos) << best.out;

  // psi = 0.9 lies outside the table (|psi| <= 0.8): with --beyond-table fastsim-sdec,
  // FASTSIM-SDEC on the 30 x 20 grid.
  const auto outside = run_wheelwear(
      "creep --a 4.25e-3 --b 4.25e-3 --psi 0.9 --phi 1.0 --N 37830 --mu 0.35 --json "
      "--method best --beyond-table fastsim-sdec --nx 30 --ny 20");
  ASSERT_EQ(outside.exit_code, 0) << outside.err;
  tangential::FastsimOptions options;
  options.nx = 30;
  options.ny = 20;
  const tangential::CreepForces g =
      tangential::fastsim(tangential::FastsimMethod::sdec, {4.25e-3, 4.25e-3, 0.9}, {0, 0, 1.0},
                          {37830, 0.35}, {80e9, 0.25}, options)
          .forces;
  EXPECT_EQ(json_number(outside.out, "Fx"), g.Fx);
  EXPECT_NE(outside.out.find("\"source\": \"fastsim-sdec\""), std::string::npos) << outside.out;
  EXPECT_NE(outside.out.find("psi = 0.9"), std::string::npos) << outside.out;
  EXPECT_TRUE(json_number(outside.out, "slip_cells").has_value());
}

// For one patch best answers with the exact theory on the grid that resolves the patch's long
// axis (aspect_sdec_grid), inside the table's range as outside it: the library's solution to
// the last digit, at a/b = 1 (inside) and, with the table's behaviour asked for, at a/b = 20
// under pure spin (outside, saying why). FASTSIM's options are refused unless FASTSIM is asked
// to answer, and --beyond-table and --inside-table belong to best alone.
// The command's JSON `out` is the library's exact solution of the pure-spin patch on the grid
// that resolves it, nx x ny elements, to the last digit.
void expect_exact_on_resolving_grid(const std::string& out, const contactgeom::Sdec& patch,
                                    double phi, double nx, double ny, double nu = 0.25) {
  const tangential::ExactSolution exact = tangential::exact_sdec(
      patch, {0, 0, phi}, {37830, 0.35}, {80e9, nu}, tangential::aspect_sdec_grid(patch), {});
  EXPECT_EQ(json_number(out, "Fx"), exact.forces.Fx);
  EXPECT_EQ(json_number(out, "Fy"), exact.forces.Fy);
  EXPECT_EQ(json_number(out, "exact_nx"), nx);
  EXPECT_EQ(json_number(out, "exact_ny"), ny);
  EXPECT_NE(out.find("\"source\": \"exact\""), std::string::npos) << out;
}

TEST(CreepCommand, BestSolvesTheExactTheoryOnTheResolvingGrid) {
  const auto inside = run_wheelwear(kCase + " --method best");
  ASSERT_EQ(inside.exit_code, 0) << inside.err;
  expect_exact_on_resolving_grid(inside.out, {4.25e-3, 4.25e-3, 0.6}, 1.0, 40, 40);

  // a/b = 20 at nu = 0.28: beyond the table there (its nu = 0.25 group reaches a/b 25).
  const std::string slender =
      "creep --a 19e-3 --b 0.95e-3 --phi 0.5 --N 37830 --mu 0.35 --nu 0.28 --json --method best";
  const auto best = run_wheelwear(slender + " --inside-table table");
  ASSERT_EQ(best.exit_code, 0) << best.err;
  expect_exact_on_resolving_grid(best.out, {19e-3, 0.95e-3, 0.0}, 0.5, 400, 40, 0.28);
  EXPECT_NE(best.out.find("a/b = 20"), std::string::npos) << best.out;
  EXPECT_FALSE(json_number(best.out, "exact_grid").has_value()) << best.out;

  const std::string round_patch = "creep --a 4.25e-3 --b 4.25e-3 --phi 0.5 --N 37830 ";
  // Each refused command line and the option its message names.
  const std::pair<std::string, std::string> refused[] = {
      {slender + " --nx 30", "--beyond-table"},
      {slender + " --target-error 0.01", "--beyond-table"},
      {round_patch + "--method table --beyond-table exact", "--beyond-table"},
      {slender + " --beyond-table fastsim", "--beyond-table"},
      {slender + " --inside-table exact --beyond-table fastsim-sdec", "--beyond-table"},
      {round_patch + "--method exact --inside-table table", "--inside-table"},
      {slender + " --inside-table fastsim", "--inside-table"}};
  for (const auto& [command, option] : refused) {
    const auto r = run_wheelwear(command);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find(option), std::string::npos) << command << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << command;
  }
}

}  // namespace
}  // namespace wheelwear
