// `wheelwear creep`: creep forces of one SDEC patch with any of the tangential methods.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "wheelwear/core/input_error.hpp"
#include "json_writer.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/grid_choice.hpp"
#include "wheelwear/tangential/linear_theory.hpp"
#include "wheelwear/tangential/table_correction.hpp"

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
  bool json = false;
  // Options given on the command line (not their defaults), to refuse those that do not apply.
  const CLI::Option* nx = nullptr;
  const CLI::Option* ny = nullptr;
  const CLI::Option* bound_option = nullptr;
  const CLI::Option* scheme_option = nullptr;
  const CLI::Option* exact_grid_option = nullptr;
};

// `--method exact`: Kalker's exact theory on the SDEC patch with its prescribed pressure
// (exact_sdec), on exact_grid x exact_grid elements over 1.02 times the patch (CONTACT's SDEC
// option). Refuses the options of the FASTSIM methods, which would be silently ignored.
tangential::ExactSolution solve_exact(const CreepArgs& args) {
  auto refuse = [](const CLI::Option* option, const char* why) {
    if (option && option->count() > 0)
      throw InputError(option->get_name() + " does not apply to --method exact: " + why);
  };
  if (args.target_error) {
    std::ostringstream message;
    message << "--target-error " << *args.target_error
            << ": --method exact has no fitted error model; choose its grid with --exact-grid N "
               "(40: within 0.53 % of muN of CONTACT's 80 x 80 answer on its pure-spin "
               "cases; 80, CONTACT's own grid: within 2e-7)";
    throw InputError(message.str());
  }
  refuse(args.nx, "its grid is --exact-grid");
  refuse(args.ny, "its grid is --exact-grid");
  refuse(args.bound_option, "the exact theory bounds the traction by mu p_n");
  refuse(args.scheme_option, "it is a FASTSIM marching scheme");
  if (args.exact_grid < kMinExactGrid || args.exact_grid > kMaxExactGrid) {
    std::ostringstream message;
    message << "--exact-grid " << args.exact_grid << ": needs " << kMinExactGrid << " ... "
            << kMaxExactGrid << " elements per side (40: about 16 ms, 80: about 0.13 s)";
    throw InputError(message.str());
  }
  tangential::ExactOptions options;
  options.nx = options.ny = args.exact_grid;
  return tangential::exact_sdec(args.sdec, args.creepages, args.load, args.material, options);
}

void run_creep(const CreepArgs& args) {
  tangential::CreepForces forces;
  int cells = 0, slip_cells = 0;
  const bool linear = args.method == "linear-sdec" || args.method == "she-sdec";
  const bool tabled = args.method == "table" || args.method == "best";
  std::optional<tangential::GridChoice> chosen;
  // For table and best: which method gave the forces ("table" or "fastsim-sdec"), and why the
  // table could not.
  std::string source, table_outside;
  const bool exact = args.method == "exact";
  std::optional<tangential::ExactSolution> exact_solution;
  if (!exact && args.exact_grid_option && args.exact_grid_option->count() > 0)
    throw InputError("--exact-grid applies to --method exact only; FASTSIM's grid is --nx --ny");
  if ((linear || args.method == "table") && args.target_error) {
    std::ostringstream message;
    message << "--target-error " << *args.target_error << ": " << args.method
            << " has no grid; use --target-error with a FASTSIM method";
    throw InputError(message.str());
  }
  bool use_table = args.method == "table";
  if (args.method == "best") {
    use_table = tangential::creep_table_covers(args.sdec, args.creepages, args.load, args.material,
                                         &table_outside);
  }
  if (exact) {
    exact_solution = solve_exact(args);
    forces = exact_solution->forces;
    cells = exact_solution->contact_elements;
    slip_cells = exact_solution->slip_elements;
  } else if (linear) {
    args.sdec.validate();
    args.load.validate();
    forces = args.method == "linear-sdec"
                 ? tangential::linear_sdec_forces(args.sdec, args.creepages, args.material)
                 : tangential::she_sdec_forces(args.sdec, args.creepages, args.material, args.load);
  } else if (use_table) {
    forces = tangential::creep_table_forces(args.sdec, args.creepages, args.load, args.material);
    source = "table";
  } else {
    const std::string fastsim_name = tabled ? std::string("fastsim-sdec") : args.method;
    if (tabled) source = fastsim_name;
    const auto method = tangential::parse_fastsim_method(fastsim_name);
    if (!method) throw InputError("--method " + args.method + ": unknown method");
    tangential::FastsimOptions options = args.options;
    options.bound = args.bound == "semi-elliptic" ? tangential::TractionBound::semi_elliptic
                                                  : tangential::TractionBound::parabolic;
    options.scheme = args.scheme == "second-order" ? tangential::FastsimScheme::second_order
                                                   : tangential::FastsimScheme::kalker;
    if (args.target_error) {
      try {
        chosen = tangential::choose_grid(*method, options.scheme, options.bound, *args.target_error);
      } catch (const InputError& e) {
        throw InputError(std::string("--target-error: ") + e.what());
      }
      options.nx = chosen->nx;
      options.ny = chosen->ny;
    }
    const tangential::TangentialSolution solution =
        tangential::fastsim(*method, args.sdec, args.creepages, args.load, args.material, options);
    forces = solution.forces;
    cells = solution.cells;
    slip_cells = solution.slip_cells;
  }
  const bool has_cells = !linear && !use_table;
  const double mu_n = args.load.mu * args.load.N;
  const std::string warnings = forces.flags.describe();
  if (args.json) {
    JsonObject out;
    out.add("method", args.method)
        .add("Fx", forces.Fx)
        .add("Fy", forces.Fy)
        .add("Fx_muN", forces.Fx / mu_n)
        .add("Fy_muN", forces.Fy / mu_n);
    if (forces.has_Mz) out.add("Mz", forces.Mz);
    if (has_cells) out.add("cells", cells).add("slip_cells", slip_cells);
    if (tabled) out.add("source", source);
    if (!table_outside.empty()) out.add("table_outside", table_outside);
    if (chosen) {
      out.add("target_error", *args.target_error)
          .add("nx", chosen->nx)
          .add("ny", chosen->ny)
          .add("predicted_error", chosen->predicted_error);
    }
    if (exact_solution) {
      const tangential::ExactSolution& s = *exact_solution;
      out.add("exact_grid", args.exact_grid)
          .add("status", tangential::status_name(s.status))
          .add("iterations", s.iterations)
          .add("adhesion_elements", s.adhesion_elements)
          .add("adhesion_fraction",
               s.contact_elements > 0
                   ? static_cast<double>(s.adhesion_elements) / s.contact_elements
                   : 0.0)
          .add("N_grid", s.normal_force)
          .add("frictional_work", s.frictional_work)
          // The work of the rigid slip: what sum |p| |s| dA tends to as the grid is refined
          // (the sum converges to first order only; wear runs use this one).
          .add("rigid_slip_work", tangential::rigid_slip_work(s.forces, args.creepages));
      if (!s.message.empty()) out.add("message", s.message);
    }
    out.add("extrapolated", forces.flags.any()).add("warnings", warnings);
    std::cout << out.str() << '\n';
    return;
  }
  std::printf("method   %s\n", args.method.c_str());
  std::printf("Fx       %14.6g N   (Fx/muN = %+.6f)\n", forces.Fx, forces.Fx / mu_n);
  std::printf("Fy       %14.6g N   (Fy/muN = %+.6f)\n", forces.Fy, forces.Fy / mu_n);
  if (forces.has_Mz) std::printf("Mz       %14.6g N m (about O)\n", forces.Mz);
  if (exact_solution) {
    const tangential::ExactSolution& s = *exact_solution;
    std::printf("grid     %d x %d elements over 1.02 times the patch\n", args.exact_grid,
                args.exact_grid);
    std::printf("status   %s after %d iterations%s%s\n", tangential::status_name(s.status), s.iterations,
                s.message.empty() ? "" : ": ", s.message.c_str());
    std::printf("contact  %d elements: %d adhere (%.1f %%), %d slip\n", s.contact_elements,
                s.adhesion_elements,
                s.contact_elements > 0 ? 100.0 * s.adhesion_elements / s.contact_elements : 0.0,
                s.slip_elements);
    std::printf("N grid   %14.6g N   (sum of the element pressures)\n", s.normal_force);
  } else if (has_cells) {
    std::printf("slip     %d of %d cells\n", slip_cells, cells);
  }
  if (tabled) std::printf("source   %s\n", source.c_str());
  if (!table_outside.empty()) std::printf("outside  %s\n", table_outside.c_str());
  if (chosen) {
    std::printf("grid     %d x %d cells for --target-error %g (model error %.3g of muN)\n",
                chosen->nx, chosen->ny, *args.target_error, chosen->predicted_error);
  }
  if (!warnings.empty()) std::printf("warning  %s\n", warnings.c_str());
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
  cmd->add_option("--method", args->method,
                  "fastsim-sdec (default), fastsim-eql, fastsim-eqe, fastsim-eqe-shifted,\n"
                  "fastsim-elliptic, linear-sdec, she-sdec (Shen-Hedrick-Elkins),\n"
                  "exact (Kalker's exact theory, see above; JSON adds status, iterations,\n"
                  "adhesion_fraction, adhesion_elements, N_grid, frictional_work, exact_grid;\n"
                  "cells and slip_cells count contact and slipping elements),\n"
                  "table (the built-in book of exact-theory tables: Fx, Fy, Mz within 1 % of\n"
                  "muN of the exact theory in about 1 us; a/b 0.2-5, |psi| <= 0.8, nu\n"
                  "0.25-0.28; an error outside its range) or best (the table inside its\n"
                  "range, fastsim-sdec outside; the JSON's \"source\" says which)")
      ->check(
          CLI::IsMember({"fastsim-sdec", "fastsim-eql", "fastsim-eqe", "fastsim-eqe-shifted",
                         "fastsim-elliptic", "linear-sdec", "she-sdec", "table", "best", "exact"}));
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
          ->check(CLI::IsMember({"parabolic", "semi-elliptic"}))
          ->capture_default_str();
  args->scheme_option =
      cmd->add_option("--scheme", args->scheme,
                      "FASTSIM marching: kalker (first order, Kalker 1982) or second-order")
          ->check(CLI::IsMember({"kalker", "second-order"}))
          ->capture_default_str();
  args->exact_grid_option =
      cmd->add_option("--exact-grid", args->exact_grid,
                      "--method exact: elements per side of the grid, 8 ... 400 (cost grows as\n"
                      "N^2 log N times the iterations: 40 about 16 ms, 80 about 0.13 s)")
          ->capture_default_str();
  cmd->add_flag("--json", args->json, "print one JSON object (forces in N, normalised by muN)");
  cmd->callback([args] { run_creep(*args); });
}

}  // namespace wheelwear::cli
