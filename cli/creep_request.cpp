#include "creep_request.hpp"

#include <sstream>
#include <utility>

#include "choices.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/plausibility.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::cli {

namespace {

// Refuses the options that do not apply to the method (they would be silently ignored) and
// the grid limits of the exact method.
void check_options(const CreepOptions& o, tangential::Method method) {
  const bool exact = method == tangential::Method::exact;
  const auto refuse = [](bool given, const char* name, const char* why) {
    if (given) throw InputError(std::string(name) + " does not apply to --method exact: " + why);
  };
  if (o.beyond_table && method != tangential::Method::best)
    throw InputError(
        "--beyond-table applies to --method best only: it says what answers "
        "outside the book of tables");
  if (o.beyond_table)
    require_choice("--beyond-table", *o.beyond_table,
                   {std::begin(kBeyondTableChoices), std::end(kBeyondTableChoices)});
  if (o.inside_table && method != tangential::Method::best)
    throw InputError(
        "--inside-table applies to --method best only: it says what answers where the book "
        "of tables covers the patch (--method table is the table alone)");
  if (o.inside_table)
    require_choice("--inside-table", *o.inside_table,
                   {std::begin(kInsideTableChoices), std::end(kInsideTableChoices)});
  if (o.inside_table && o.beyond_table && o.exact_inside_table())
    throw InputError("--beyond-table " + *o.beyond_table +
                     " says what answers outside the book of tables, which --inside-table exact "
                     "does not consult; give --inside-table table with it");
  if (method == tangential::Method::best && o.exact_beyond_table()) {
    // No FASTSIM runs: the exact theory answers (or the table inside its range).
    const char* fastsim_option = o.nx             ? "--nx"
                                 : o.ny           ? "--ny"
                                 : o.target_error ? "--target-error"
                                 : o.bound        ? "--bound"
                                 : o.scheme       ? "--scheme"
                                                  : nullptr;
    if (fastsim_option)
      throw InputError(std::string(fastsim_option) +
                       " sets FASTSIM-SDEC, which --method best runs only with --beyond-table "
                       "fastsim-sdec (by default the exact theory answers)");
  }
  if (method == tangential::Method::best && o.exact_grid)
    throw InputError(
        "--exact-grid applies to --method exact only; --method best solves the exact "
        "theory on its own grid (40 elements across the patch, elements at most twice as "
        "long as wide)");
  if (!exact && o.exact_grid)
    throw InputError("--exact-grid applies to --method exact only; FASTSIM's grid is --nx --ny");
  if (o.target_error && (o.nx || o.ny))
    throw InputError(std::string(o.nx ? "--nx" : "--ny") + " excludes --target-error");
  if (!o.target_error) {
  } else if (exact) {
    std::ostringstream message;
    message << "--target-error " << *o.target_error
            << ": --method exact has no fitted error model; choose its grid with --exact-grid N "
               "(40: within 0.53 % of muN of CONTACT's 80 x 80 answer on its pure-spin "
               "cases; 80, CONTACT's own grid: within 2e-7)";
    throw InputError(message.str());
  } else if (!tangential::fastsim_variant(method)) {
    std::ostringstream message;
    message << "--target-error " << *o.target_error << ": " << o.method
            << " has no grid; use --target-error with a FASTSIM method";
    throw InputError(message.str());
  }
  if (!exact) return;
  refuse(o.nx.has_value(), "--nx", "its grid is --exact-grid");
  refuse(o.ny.has_value(), "--ny", "its grid is --exact-grid");
  refuse(o.bound.has_value(), "--bound", "the exact theory bounds the traction by mu p_n");
  refuse(o.scheme.has_value(), "--scheme", "it is a FASTSIM marching scheme");
  const int grid = o.exact_grid_or_default();
  if (grid < kMinExactGrid || grid > kMaxExactGrid) {
    std::ostringstream message;
    message << "--exact-grid " << grid << ": needs " << kMinExactGrid << " ... " << kMaxExactGrid
            << " elements per side (40: about 16 ms, 80: about 0.13 s)";
    throw InputError(message.str());
  }
}

template <typename Enum, std::size_t N>
Enum named(const core::NameTable<Enum, N>& table, const std::optional<std::string>& given,
           Enum fallback, const char* option) {
  if (!given) return fallback;
  require_choice(option, *given, core::all_names(table));
  return *core::value_named(table, *given);
}

}  // namespace

CreepSolver::CreepSolver(CreepOptions options) : options_(std::move(options)) {
  require_choice("--method", options_.method, core::all_names(tangential::kMethodNames));
  method_ = *tangential::parse_method(options_.method);
  check_options(options_, method_);
  tangential::FastsimOptions& fastsim = base_.fastsim;
  if (options_.nx) fastsim.nx = *options_.nx;
  if (options_.ny) fastsim.ny = *options_.ny;
  fastsim.bound = named(tangential::kBoundNames, options_.bound, fastsim.bound, "--bound");
  fastsim.scheme = named(tangential::kSchemeNames, options_.scheme, fastsim.scheme, "--scheme");
  // The exact theory on 1.02 times the patch (CONTACT's SDEC option).
  base_.exact_grid.nx = base_.exact_grid.ny = options_.exact_grid_or_default();
  base_.exact_beyond_table = options_.exact_beyond_table();
  base_.exact_inside_table = method_ == tangential::Method::best && options_.exact_inside_table();
}

void check_creep_inputs(const contactgeom::Sdec& sdec, const tangential::Creepages& creepages,
                        const tangential::ContactLoad& load, std::vector<std::string>& warnings) {
  core::check_plausible(core::kSemiAxisLimit, "--a", sdec.a, warnings);
  core::check_plausible(core::kSemiAxisLimit, "--b", sdec.b, warnings);
  core::check_plausible(core::kWheelLoadLimit, "--N", load.N, warnings);
  core::check_plausible(core::kFrictionLimit, "--mu", load.mu, warnings);
  core::check_plausible(core::kCreepageLimit, "--vx", creepages.vx, warnings);
  core::check_plausible(core::kCreepageLimit, "--vy", creepages.vy, warnings);
}

tangential::TangentialSolution CreepSolver::solve(
    const contactgeom::Sdec& sdec, const tangential::Creepages& creepages,
    const tangential::ContactLoad& load, const tangential::Material& material,
    std::optional<tangential::GridChoice>* chosen) const {
  tangential::SolveOptions options = base_;
  // best answers from the table where it covers the patch: no FASTSIM grid to choose then.
  if (options_.target_error &&
      !(method_ == tangential::Method::best &&
        (base_.exact_inside_table ||
         tangential::creep_table_covers(sdec, creepages, load, material)))) {
    tangential::GridChoice grid;
    try {
      grid = tangential::choose_grid(*tangential::fastsim_variant(method_), options.fastsim.scheme,
                                     options.fastsim.bound, *options_.target_error);
    } catch (const InputError& e) {
      throw InputError(std::string("--target-error: ") + e.what());
    }
    options.fastsim.nx = grid.nx;
    options.fastsim.ny = grid.ny;
    if (chosen) *chosen = grid;
  }
  return tangential::solve_patch(method_, sdec, creepages, load, material, options);
}

}  // namespace wheelwear::cli
