#pragma once
// The wear one contact patch does with one contact model: its tangential solution on a FASTSIM
// grid, and the worn depth per metre of running it maps onto the wheel profile (`wheelwear
// wear`, the Python module's wear()).

#include <string>

#include "contact_inputs.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/wear/wear_distribution.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::cli {

struct ModelWear {
  tangential::ContactModel model;
  tangential::TangentialSolution solution;  ///< with the cells' fields
  wear::WearDistribution distribution;      ///< depth per metre on 0.1 mm bins of wheel arc length
  wear::WearSummary summary;
};

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
