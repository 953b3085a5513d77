#pragma once
/// The one entry point of the tangential problem: a patch, its creepages, the material and a
/// method in; forces, spin moment, status and (on request) per-cell fields out. The command
/// line, the wear run and the vehicle model all call solve_patch; the methods below are named
/// as the command line's `creep --method`.

#include <optional>
#include <string>
#include <string_view>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/solution.hpp"

namespace wheelwear::tangential {

/// How the tangential problem of a patch is solved.
enum class Method {
  fastsim_sdec,         ///< FASTSIM-SDEC (Liu, Fu & Bruni 2022, Eq. 15-18)
  fastsim_eql,          ///< FASTSIM-EQ.L: SDEC region, Kalker's flexibilities of the ellipse
  fastsim_eqe,          ///< FASTSIM-EQ.E: classic FASTSIM on the ellipse a, b centred at O
  fastsim_eqe_shifted,  ///< FASTSIM-EQ.E centred at O' = O + psi b, vx' = vx - phi psi b
  fastsim_elliptic,     ///< classic elliptic FASTSIM on the ellipse a, b (psi ignored)
  linear_sdec,          ///< Kalker's linear theory for the SDEC (Eq. 11-12); totals only
  she_sdec,             ///< Shen-Hedrick-Elkins saturation of linear_sdec; totals only
  table,                ///< the book of exact-theory tables; totals only, refuses outside it
  /// Inside the book of tables its totals and frictional work, spread over the patch as
  /// FASTSIM-SDEC spreads them (table_correction.hpp); FASTSIM-SDEC alone outside.
  best,
  exact,  ///< Kalker's exact theory with the SDEC pressure prescribed (exact_sdec)
};

/// The command line's names, in the order `creep --help` lists them.
inline constexpr core::NameTable<Method, 10> kMethodNames = {{
    {Method::fastsim_sdec, "fastsim-sdec"},
    {Method::fastsim_eql, "fastsim-eql"},
    {Method::fastsim_eqe, "fastsim-eqe"},
    {Method::fastsim_eqe_shifted, "fastsim-eqe-shifted"},
    {Method::fastsim_elliptic, "fastsim-elliptic"},
    {Method::linear_sdec, "linear-sdec"},
    {Method::she_sdec, "she-sdec"},
    {Method::table, "table"},
    {Method::best, "best"},
    {Method::exact, "exact"},
}};

/// "fastsim-sdec", ... (kMethodNames).
std::string_view method_name(Method method);
/// The method named `name` in kMethodNames; std::nullopt when unknown.
std::optional<Method> parse_method(std::string_view name);

/// The FASTSIM variant behind a FASTSIM method, best (fastsim_sdec), or std::nullopt for the
/// methods that do not march strips (linear_sdec, she_sdec, table, exact).
std::optional<FastsimMethod> fastsim_variant(Method method);

/// True when the method returns per-cell fields (every FASTSIM method, best and exact).
bool has_cell_fields(Method method);

/// Discretisation of each method; a method reads only its own part.
struct SolveOptions {
  /// Grid, bound, scheme and fields of the FASTSIM methods and of best; its cell_fields also
  /// asks the exact method for its elements as cells.
  FastsimOptions fastsim;
  /// Grid of the exact method (exact_sdec): nx x ny elements over margin times the patch.
  SdecGridOptions exact_grid;
  ExactSolverOptions exact_solver;  ///< stopping tests of the exact method
  /// best, for a patch outside the book of tables: Kalker's exact theory on aspect_sdec_grid
  /// (its own grid: exact_grid is not used; at least 3000 sweeps allowed; 0.05-2 s a patch for
  /// a/b 0.05 ... 25; for single evaluations) instead of FASTSIM-SDEC (tens of microseconds,
  /// 2-14 % of mu N off the exact theory on patches of a/b 0.05 ... 0.1 and 5 ... 25; for
  /// runs).
  bool exact_beyond_table = false;
  /// best, for a patch the book of tables covers: the exact theory on aspect_sdec_grid as
  /// beyond it (10 ms ... 1 s a patch; within 0.5 % of mu N of the exact theory on twice as
  /// fine a grid, where the table, made on 30 elements across, is up to 1.1 % off: for single
  /// evaluations) instead of the table's totals (1 ... 3 us; for runs).
  bool exact_inside_table = false;

  void validate() const;  ///< throws InputError naming the bad field
};

/// Solves the tangential problem on the patch `sdec` (for fastsim_elliptic the ellipse
/// sdec.a, sdec.b) with creepages at O. Throws InputError on invalid input (|psi| >= 1,
/// a or b <= 0, N <= 0, mu <= 0, NaN, a patch outside the book of tables with Method::table).
TangentialSolution solve_patch(Method method, const contactgeom::Sdec& sdec,
                               const Creepages& creepages, const ContactLoad& load,
                               const Material& material, const SolveOptions& options = {});

/// As above, reusing `solution`'s per-cell storage (no allocation once a grid size has been
/// seen; for loops over many patches).
void solve_patch(Method method, const contactgeom::Sdec& sdec, const Creepages& creepages,
                 const ContactLoad& load, const Material& material, const SolveOptions& options,
                 TangentialSolution& solution);

}  // namespace wheelwear::tangential
