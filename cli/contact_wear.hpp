#pragma once
// The wear one contact patch does with one contact model: its tangential solution on a FASTSIM
// grid, and the worn depth per metre of running it maps onto the wheel profile (`wheelwear
// wear`, the Python module's wear()).

#include <string>

#include "contact_inputs.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"
#include "wheelwear/wear/wear_distribution.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::cli {

struct ModelWear {
  std::string model;  ///< the contact model's name (tangential::model_name), or "exact"
  tangential::TangentialSolution solution;  ///< with the cells' fields
  wear::WearDistribution distribution;      ///< depth per metre on 0.1 mm bins of wheel arc length
  wear::WearSummary summary;
};

/// Kalker's exact theory on a patch's undeformed distance (`contact --tangential exact`,
/// `wear --exact`).
struct ExactPatchOptions {
  int grid = 40;        ///< elements per side (--exact-grid)
  double margin = 1.3;  ///< the grid over the patch (--exact-margin)
  /// The rolling radius across the patch in the slip (--exact-radius-variation).
  bool radius_variation = false;
};

/// --exact-radius-variation's help (contact, wear).
inline constexpr const char* kRadiusVariationHelp =
    "exact theory: the longitudinal rigid slip follows the wheel's rolling radius across\n"
    "the patch (its departure from the tangent at O, a creepage of up to 2e-3 across a\n"
    "wide conformal patch on a hollow-worn tread), which the planar theory, FASTSIM and\n"
    "CONTACT's planar contact leave out";

/// Refuses a grid outside kMinExactGrid ... kMaxExactGrid and a margin outside 1 ... 5, naming
/// the flag.
void check_exact_patch_options(const ExactPatchOptions& options);

/// Kalker's exact theory on `patch` of `pair` at `in`'s pose, creepages at O `creepages`
/// (wheel_rail_exact.hpp). A patch of a blend is its description's problem, at its whole load,
/// with the load and forces weighted by its share as the other methods' are.
tangential::WheelRailExactSolution exact_patch(const ContactInputs& in,
                                               const contactgeom::WheelRailPair& pair,
                                               const contactgeom::WheelRailPatch& patch,
                                               const tangential::Creepages& creepages,
                                               const ExactPatchOptions& options);

/// The wear `patch` does with Kalker's exact theory on its undeformed distance (exact_patch),
/// its elements worn by `law` and mapped onto the wheel as model_wear maps FASTSIM's cells:
/// the reference the SDEC chain approximates. Model name "exact".
ModelWear exact_wear(const ContactInputs& in, const contactgeom::WheelRailPair& pair,
                     const contactgeom::WheelRailPatch& patch, const wear::WearLaw& law,
                     const ExactPatchOptions& options);

/// The wear law named `law` ("usfd" or "archard"), from the user's table `table` (a CSV of that
/// law's kind) where it is not empty; throws InputError naming --law for another name.
wear::WearLaw wear_law_named(const std::string& law, const std::string& table);

/// The contact model named `model` (tangential::kContactModelNames); throws InputError naming
/// --model and the choices for another name.
tangential::ContactModel contact_model_named(const std::string& model);

/// Refuses a rolling speed that is not positive (--V) and a FASTSIM grid outside 2 ... 1000
/// cells per direction (--cells).
void check_wear_grid(double speed, int cells);

/// `patch` of `pair` worn with `model` and `law` on a cells x cells grid, the creepages and the
/// speed from `in`; `positions` keeps the cells' positions (for a T gamma map).
ModelWear model_wear(const ContactInputs& in, const contactgeom::WheelRailPair& pair,
                     const contactgeom::WheelRailPatch& patch, tangential::ContactModel model,
                     const wear::WearLaw& law, int cells, bool positions);

}  // namespace wheelwear::cli
