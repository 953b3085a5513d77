#pragma once
// One SDEC patch's creep forces as the front ends ask for them (`wheelwear creep`, the Python
// module's creep()): the method by name, the options a user gave, their checks, and the solve.
// Both front ends go through here, so that they refuse the same inputs with the same words and
// give the same numbers.

#include <optional>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/sdec_regularisation.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/grid_choice.hpp"
#include "wheelwear/tangential/solution.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::cli {

/// Elements per side of --exact-grid (creep, contact): below 8 a patch's edge is a quarter of
/// its width; 400 x 400 takes tens of seconds.
inline constexpr int kMinExactGrid = 8;
inline constexpr int kMaxExactGrid = 400;

/// What --beyond-table may name.
inline constexpr const char* kBeyondTableChoices[] = {"exact", "fastsim-sdec"};
/// What --inside-table may name.
inline constexpr const char* kInsideTableChoices[] = {"exact", "table"};

/// The method and the options a user gave (an empty optional: not given, the default applies).
struct CreepOptions {
  std::string method = "fastsim-sdec";
  std::optional<int> nx, ny;           ///< FASTSIM cells along x and strips across y
  std::optional<std::string> bound;    ///< "parabolic" (default) or "semi-elliptic"
  std::optional<std::string> scheme;   ///< "kalker" (default) or "second-order"
  std::optional<double> target_error;  ///< fraction of mu N: chooses nx = ny (grid_choice.hpp)
  std::optional<int> exact_grid;       ///< method exact: elements per side (default 40)
  /// Method best, for a patch outside the book of tables: "exact" (default; Kalker's exact
  /// theory on a grid resolving the patch's long axis) or "fastsim-sdec" (as runs do).
  std::optional<std::string> beyond_table;
  /// Method best, for a patch the book of tables covers: "exact" (the exact theory on the same
  /// grid as outside it: the most accurate answer for one patch) or "table" (its totals, as
  /// runs take them). Default: "exact", but "table" where --beyond-table is given (which asks
  /// for the table's behaviour at its edge).
  std::optional<std::string> inside_table;

  int exact_grid_or_default() const { return exact_grid.value_or(40); }
  bool exact_beyond_table() const { return beyond_table.value_or("exact") == "exact"; }
  bool exact_inside_table() const {
    return inside_table ? *inside_table == "exact" : !beyond_table.has_value();
  }
};

/// Throws InputError for an impossible patch, load or creepage (core/plausibility.hpp) and
/// appends the warnings for implausible ones to `warnings`.
void check_creep_inputs(const contactgeom::Sdec& sdec, const tangential::Creepages& creepages,
                        const tangential::ContactLoad& load, std::vector<std::string>& warnings);

/// The options checked once for many patches: the method, and the solve options for a patch.
class CreepSolver {
 public:
  /// Throws InputError for an unknown method or an option that does not apply to it.
  explicit CreepSolver(CreepOptions options);

  tangential::Method method() const { return method_; }
  const CreepOptions& options() const { return options_; }

  /// One patch, its inputs checked by check_creep_inputs() first; `chosen` is set where
  /// --target-error chose the grid. Throws InputError where the method cannot take the patch
  /// (the table outside its range, say).
  tangential::TangentialSolution solve(
      const contactgeom::Sdec& sdec, const tangential::Creepages& creepages,
      const tangential::ContactLoad& load, const tangential::Material& material,
      std::optional<tangential::GridChoice>* chosen = nullptr) const;

 private:
  CreepOptions options_;
  tangential::Method method_;
  tangential::SolveOptions base_;  // without a grid chosen by target_error
};

}  // namespace wheelwear::cli
