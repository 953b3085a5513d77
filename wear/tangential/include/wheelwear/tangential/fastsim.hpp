#pragma once
/// FASTSIM (Kalker 1982) and its SDEC extension FASTSIM-SDEC (Liu, Fu & Bruni 2022, Eq. 15-18),
/// with the comparators of the paper's Section 5.

#include <optional>
#include <string_view>
#include <vector>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/solution.hpp"

namespace wheelwear::tangential {

/// Which simplified-theory model solves the tangential problem on a patch.
enum class FastsimMethod {
  sdec,         ///< FASTSIM-SDEC: SDEC region, flexibilities L11, L13, L22, L23 of Eq. 17
  eql,          ///< FASTSIM-EQ.L: SDEC region, Kalker's three flexibilities of the ellipse a, b
  eqe,          ///< FASTSIM-EQ.E: classic FASTSIM on the ellipse a, b centred at O
  eqe_shifted,  ///< FASTSIM-EQ.E on the ellipse centred at O' (y0 = psi b), vx' = vx - phi y0
  elliptic,     ///< classic elliptic FASTSIM on the ellipse a, b (psi ignored)
};

/// The traction bound g(x, y) that saturated tractions follow.
enum class TractionBound {
  parabolic,      ///< mu 2N/(pi a^3 b) (x_l^2 - x^2), Eq. 18 (default)
  semi_elliptic,  ///< mu p_n, with p_n of Eq. 4
};

/// How each strip is marched from its leading to its trailing edge.
enum class FastsimScheme {
  /// Kalker's (1982) FASTSIM: explicit steps, traction projected onto the bound at the nodes,
  /// each cell carrying its trailing node's traction. First-order accurate in the cell size.
  kalker,
  /// Second-order marching (after the idea of Vollebregt & Wilders' FASTSIM2, 2011): cell
  /// tractions by the trapezoidal rule, the point where adhesion turns into slip located
  /// inside the cell, and the traction direction in slip advanced by a midpoint rule.
  second_order,
};

/// The names of the bounds and the schemes on the command line and in scenes.
inline constexpr core::NameTable<TractionBound, 2> kBoundNames = {{
    {TractionBound::parabolic, "parabolic"},
    {TractionBound::semi_elliptic, "semi-elliptic"},
}};
inline constexpr core::NameTable<FastsimScheme, 2> kSchemeNames = {{
    {FastsimScheme::kalker, "kalker"},
    {FastsimScheme::second_order, "second-order"},
}};

/// Which per-cell fields a solve with FastsimOptions::cell_fields fills.
enum class CellFieldSet {
  all,  ///< every member of CellFields
  /// What the wear laws and accumulate_wear() read: dx, strip_y, work, slip_norm and pressure.
  /// Kalker's scheme leaves x, y, px, py, sx, sy and slip empty (less to compute and store);
  /// the second-order scheme fills them anyway.
  wear,
};

/// Discretisation and output options.
struct FastsimOptions {
  int nx = 50;  ///< cells along x in every strip, >= 1
  int ny = 50;  ///< strips across the width, >= 1
  TractionBound bound = TractionBound::parabolic;
  FastsimScheme scheme = FastsimScheme::kalker;
  bool cell_fields = false;  ///< also return per-cell tractions, slip and frictional work
  CellFieldSet field_set = CellFieldSet::all;  ///< which fields, when cell_fields

  void validate() const;
};

/// Solves the tangential problem on the patch `sdec` with creepages at O.
/// Throws InputError on invalid input (|psi| >= 1, a or b <= 0, N <= 0, mu <= 0, NaN, ...).
TangentialSolution fastsim(FastsimMethod method, const contactgeom::Sdec& sdec,
                           const Creepages& creepages, const ContactLoad& load,
                           const Material& material, const FastsimOptions& options = {});

/// As above, writing into `solution` and reusing its per-cell storage: no allocation once a
/// grid size has been seen (for loops over many contacts).
void fastsim(FastsimMethod method, const contactgeom::Sdec& sdec, const Creepages& creepages,
             const ContactLoad& load, const Material& material, const FastsimOptions& options,
             TangentialSolution& solution);

/// The method's name as used on the command line and in files ("fastsim-sdec", ...).
std::string_view method_name(FastsimMethod method);
/// Parses a name of method_name(); std::nullopt when unknown.
std::optional<FastsimMethod> parse_fastsim_method(std::string_view name);

}  // namespace wheelwear::tangential
