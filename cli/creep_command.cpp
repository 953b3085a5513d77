// `wheelwear creep`: creep forces of one SDEC patch with any of the tangential methods.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "creep_request.hpp"
#include "json_writer.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/grid_choice.hpp"
#include "wheelwear/tangential/linear_theory.hpp"
#include "wheelwear/tangential/table_correction.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::cli {

namespace {

struct CreepArgs {
  std::string method = "fastsim-sdec";
  contactgeom::Sdec sdec{std::nan(""), std::nan(""), 0.0};
  tangential::Creepages creepages;
  tangential::ContactLoad load{std::nan(""), 0.3};
  tangential::Material material;
  tangential::FastsimOptions options;
  std::string bound = "parabolic";
  std::string scheme = "kalker";
  std::optional<double> target_error;  // fraction of mu N; chooses nx = ny (grid_choice.hpp)
  int exact_grid = 40;                 // --method exact: elements per side of the grid
  std::string beyond_table = "exact";  // --method best outside the table
  std::string inside_table = "exact";  // --method best inside the table
  bool json = false;
  // Options given on the command line (not their defaults), to refuse those that do not apply.
  const CLI::Option* nx = nullptr;
  const CLI::Option* ny = nullptr;
  const CLI::Option* bound_option = nullptr;
  const CLI::Option* scheme_option = nullptr;
  const CLI::Option* exact_grid_option = nullptr;
  const CLI::Option* beyond_table_option = nullptr;
  const CLI::Option* inside_table_option = nullptr;
};

// The options as given on the command line (a default is "not given": an option that does not
// apply to the method is refused only when the user typed it).
CreepOptions creep_options(const CreepArgs& args) {
  const auto given = [](const CLI::Option* option) { return option && option->count() > 0; };
  CreepOptions o;
  o.method = args.method;
  if (given(args.nx)) o.nx = args.options.nx;
  if (given(args.ny)) o.ny = args.options.ny;
  if (given(args.bound_option)) o.bound = args.bound;
  if (given(args.scheme_option)) o.scheme = args.scheme;
  o.target_error = args.target_error;
  if (given(args.exact_grid_option)) o.exact_grid = args.exact_grid;
  if (given(args.beyond_table_option)) o.beyond_table = args.beyond_table;
  if (given(args.inside_table_option)) o.inside_table = args.inside_table;
  return o;
}

void add_exact_json(JsonObject& out, const tangential::ExactSolution& s,
                    std::optional<int> exact_grid, const tangential::Creepages& creepages) {
  if (exact_grid) out.add("exact_grid", *exact_grid);
  out.add("exact_nx", s.grid.nx)
      .add("exact_ny", s.grid.ny)
      .add("status", tangential::status_name(s.status))
      .add("iterations", s.iterations)
      .add("adhesion_elements", s.adhesion_elements)
      .add("adhesion_fraction", s.contact_elements > 0
                                    ? static_cast<double>(s.adhesion_elements) / s.contact_elements
                                    : 0.0)
      .add("N_grid", s.normal_force)
      .add("frictional_work", s.frictional_work)
      // The work of the rigid slip: what sum |p| |s| dA tends to as the grid is refined (the
      // sum converges to first order only; wear runs use this one).
      .add("rigid_slip_work", tangential::rigid_slip_work(s.forces, creepages));
  if (!s.message.empty()) out.add("message", s.message);
}

void print_exact(const tangential::ExactSolution& s) {
  std::printf("grid     %d x %d elements over 1.02 times the patch\n", s.grid.nx, s.grid.ny);
  std::printf("status   %s after %d iterations%s%s\n", tangential::status_name(s.status),
              s.iterations, s.message.empty() ? "" : ": ", s.message.c_str());
  std::printf("contact  %d elements: %d adhere (%.1f %%), %d slip\n", s.contact_elements,
              s.adhesion_elements,
              s.contact_elements > 0 ? 100.0 * s.adhesion_elements / s.contact_elements : 0.0,
              s.slip_elements);
  std::printf("N grid   %14.6g N   (sum of the element pressures)\n", s.normal_force);
}

void run_creep(const CreepArgs& args) {
  const CreepSolver solver(creep_options(args));
  const tangential::Method method = solver.method();
  std::vector<std::string> implausible;
  check_creep_inputs(args.sdec, args.creepages, args.load, implausible);
  for (const std::string& w : implausible) std::cerr << "wheelwear: warning: " << w << '\n';
  std::optional<tangential::GridChoice> chosen;
  const tangential::TangentialSolution s =
      solver.solve(args.sdec, args.creepages, args.load, args.material, &chosen);
  const tangential::CreepForces& forces = s.forces;
  const bool tabled = method == tangential::Method::table || method == tangential::Method::best;
  // For table and best: which method gave the forces.
  const std::string source = s.from_table ? "table" : s.exact ? "exact" : "fastsim-sdec";
  const std::string table_outside = s.table_outside.value_or("");
  const bool has_cells = s.cells > 0 || (tangential::has_cell_fields(method) && !s.from_table);
  const double mu_n = args.load.mu * args.load.N;
  const std::string flags = forces.flags.describe();
  if (args.json) {
    std::vector<std::string> warnings = implausible;
    if (!flags.empty()) warnings.push_back(flags);
    JsonObject out;
    out.add("method", args.method)
        .add("Fx", forces.Fx)
        .add("Fy", forces.Fy)
        .add("Fx_muN", forces.Fx / mu_n)
        .add("Fy_muN", forces.Fy / mu_n);
    if (forces.Mz) out.add("Mz", *forces.Mz);
    if (has_cells) out.add("cells", s.cells).add("slip_cells", s.slip_cells);
    if (tabled) out.add("source", source);
    if (!table_outside.empty()) out.add("table_outside", table_outside);
    if (chosen) {
      out.add("target_error", *args.target_error)
          .add("nx", chosen->nx)
          .add("ny", chosen->ny)
          .add("predicted_error", chosen->predicted_error);
    }
    if (s.exact) {
      const std::optional<int> n =
          method == tangential::Method::exact
              ? std::optional<int>(solver.options().exact_grid_or_default())
              : std::nullopt;
      add_exact_json(out, *s.exact, n, args.creepages);
    }
    out.add("extrapolated", forces.flags.any()).add_raw("warnings", json_strings(warnings));
    std::cout << out.str() << '\n';
    return;
  }
  std::printf("method   %s\n", args.method.c_str());
  std::printf("Fx       %14.6g N   (Fx/muN = %+.6f)\n", forces.Fx, forces.Fx / mu_n);
  std::printf("Fy       %14.6g N   (Fy/muN = %+.6f)\n", forces.Fy, forces.Fy / mu_n);
  if (forces.Mz) std::printf("Mz       %14.6g N m (about O)\n", *forces.Mz);
  if (s.exact) {
    print_exact(*s.exact);
  } else if (has_cells) {
    std::printf("slip     %d of %d cells\n", s.slip_cells, s.cells);
  }
  if (tabled) std::printf("source   %s\n", source.c_str());
  if (!table_outside.empty()) std::printf("outside  %s\n", table_outside.c_str());
  if (chosen) {
    std::printf("grid     %d x %d cells for --target-error %g (model error %.3g of muN)\n",
                chosen->nx, chosen->ny, *args.target_error, chosen->predicted_error);
  }
  if (!flags.empty()) std::printf("warning  %s\n", flags.c_str());
}

}  // namespace

void add_creep_command(CLI::App& app) {
  auto args = std::make_shared<CreepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "creep",
      "Creep forces of one SDEC contact patch (Liu, Fu & Bruni 2022).\n"
      "The patch is two half-ellipses joined at the initial contact point O: semi-length a\n"
      "along the rolling direction x, semi-width b, shape number psi (psi > 0: the patch\n"
      "reaches further on the +y side of O; psi = 0 is the ellipse). Creepages are at O.\n"
      "Forces act on the wheel and oppose the creepages (positive vx gives negative Fx).\n"
      "Example (the paper's reference case):\n"
      "  wheelwear creep --method fastsim-sdec --a 4.25e-3 --b 4.25e-3 --psi 0.6 \\\n"
      "    --vx 0 --vy 0 --phi 1 --N 37830 --G 80e9 --nu 0.25 --mu 0.35 --json\n"
      "--method exact solves Kalker's exact theory (Kalker 1990; the discretisation of\n"
      "Vollebregt's CONTACT) on the patch with the SDEC pressure prescribed (Eq. 4), as\n"
      "CONTACT's SDEC option does: --exact-grid N x N elements over 1.02 times the patch,\n"
      "adhesion and slip areas from Coulomb friction. It is the reference the FASTSIM methods\n"
      "approximate, and costs more: 40 x 40 about 16 ms, 80 x 80 about 0.13 s (FASTSIM: well\n"
      "under 1 ms). On CONTACT's pure-spin cases 40 x 40 lies within 1 % of muN of CONTACT's\n"
      "80 x 80 answer and 80 x 80 reproduces it to 2e-7. It has no error model, so it refuses\n"
      "--target-error, and it takes neither --nx/--ny nor --bound/--scheme.");
  cmd->add_option(
         "--method", args->method,
         "fastsim-sdec (default), fastsim-eql, fastsim-eqe, fastsim-eqe-shifted,\n"
         "fastsim-elliptic, linear-sdec, she-sdec (Shen-Hedrick-Elkins),\n"
         "exact (Kalker's exact theory, see above; JSON adds status, iterations,\n"
         "adhesion_fraction, adhesion_elements, N_grid, frictional_work, exact_grid;\n"
         "cells and slip_cells count contact and slipping elements),\n"
         "table (the book of exact-theory tables, data/creep_table.h5: Fx, Fy, Mz within 1 % of\n"
         "muN of the exact theory on its grid, but up to 1.9 % in a few directions near full "
         "sliding,\n"
         "in 1-3 us; a/b 0.2-10 (0.2-25 at nu 0.25), |psi| <= 0.8, nu 0.25-0.28,\n"
         "normalised creepage up to 20 (50 at nu 0.25) and beyond it near full sliding;\n"
         "an error outside its range) or best (the most accurate answer for one patch: by\n"
         "default the exact theory on a grid that resolves the patch's long axis, inside\n"
         "and outside the table's range; --inside-table table takes the table's totals\n"
         "where it covers the patch and, as --beyond-table says, the exact theory or\n"
         "fastsim-sdec outside, as runs do; the JSON's \"source\" says which)")
      ->check(CLI::IsMember(core::all_names(tangential::kMethodNames)));
  cmd->add_option("--a", args->sdec.a, "semi-length along x [m]")->required();
  cmd->add_option("--b", args->sdec.b, "semi-width along y [m]")->required();
  cmd->add_option("--psi", args->sdec.psi, "shape number, |psi| < 1 [-]")->capture_default_str();
  cmd->add_option("--vx", args->creepages.vx, "longitudinal creepage at O [-]")
      ->capture_default_str();
  cmd->add_option("--vy", args->creepages.vy, "lateral creepage at O [-]")->capture_default_str();
  cmd->add_option("--phi", args->creepages.phi, "spin creepage [1/m]")->capture_default_str();
  cmd->add_option("--N", args->load.N, "normal force [N]")->required();
  cmd->add_option("--mu", args->load.mu, "friction coefficient [-]")->capture_default_str();
  cmd->add_option("--G", args->material.G, "combined shear modulus [Pa]")->capture_default_str();
  cmd->add_option("--nu", args->material.nu, "Poisson's ratio [-]")->capture_default_str();
  CLI::Option* nx = cmd->add_option("--nx", args->options.nx, "FASTSIM cells along x per strip")
                        ->capture_default_str();
  CLI::Option* ny = cmd->add_option("--ny", args->options.ny, "FASTSIM strips across the width")
                        ->capture_default_str();
  cmd->add_option("--target-error", args->target_error,
                  "instead of --nx/--ny: the cheapest n x n grid whose discretisation error\n"
                  "is at most this fraction of muN against the method's converged answer\n"
                  "(error model C/n^p measured on CONTACT's pure-spin cases,\n"
                  "studies/runtime_error_study.cpp); the JSON then gives nx, ny, predicted_error.\n"
                  "FASTSIM methods only: --method exact refuses it (use --exact-grid)")
      ->excludes(nx)
      ->excludes(ny);
  args->nx = nx;
  args->ny = ny;
  args->bound_option =
      cmd->add_option("--bound", args->bound, "traction bound: parabolic (Eq. 18) or semi-elliptic")
          ->check(CLI::IsMember(core::all_names(tangential::kBoundNames)))
          ->capture_default_str();
  args->scheme_option =
      cmd->add_option("--scheme", args->scheme,
                      "FASTSIM marching: kalker (first order, Kalker 1982) or second-order")
          ->check(CLI::IsMember(core::all_names(tangential::kSchemeNames)))
          ->capture_default_str();
  args->exact_grid_option =
      cmd->add_option("--exact-grid", args->exact_grid,
                      "--method exact: elements per side of the grid, 8 ... 400 (cost grows as\n"
                      "N^2 log N times the iterations: 40 about 16 ms, 80 about 0.13 s)")
          ->capture_default_str();
  args->beyond_table_option =
      cmd->add_option(
             "--beyond-table", args->beyond_table,
             "--method best, for a patch outside the book of tables (a/b below 0.2 or above\n"
             "10, above 25 at nu 0.25, |psi| above 0.8, other nu, spin-dominated creepage\n"
             "beyond the table's):\n"
             "exact (default: Kalker's exact theory, 40 elements across the patch and\n"
             "elements at most twice as long as wide, 0.05-2 s for a/b 0.05 ... 25; within\n"
             "about 0.5 % of muN of its converged answer) or fastsim-sdec (what runs use: well\n"
             "under 1 ms, 2-14 % of muN off on slender or very wide patches)")
          ->check(CLI::IsMember(std::vector<std::string>(std::begin(kBeyondTableChoices),
                                                         std::end(kBeyondTableChoices))));
  args->inside_table_option =
      cmd->add_option(
             "--inside-table", args->inside_table,
             "--method best, for a patch the book of tables covers: exact (default without\n"
             "--beyond-table: the exact theory on the same grid as outside, 10 ms ... 1 s;\n"
             "within 0.5 % of muN of the exact theory on twice as fine a grid, where the\n"
             "table, made on 30 elements across, is up to 1.1 % off) or table (its totals in\n"
             "1-3 us, as runs take them; the default when --beyond-table is given)")
          ->check(CLI::IsMember(std::vector<std::string>(std::begin(kInsideTableChoices),
                                                         std::end(kInsideTableChoices))));
  cmd->add_flag("--json", args->json, "print one JSON object (forces in N, normalised by muN)");
  cmd->callback([args] { run_creep(*args); });
}

}  // namespace wheelwear::cli
