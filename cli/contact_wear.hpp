#pragma once
// The wear one contact patch does with one contact model: its tangential solution on a FASTSIM
// grid, and the worn depth per metre of running it maps onto the wheel profile (`wheelwear
// wear`, the Python module's wear()).

#include "contact_inputs.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace wheelwear::cli {

struct ModelWear {
  tangential::ContactModel model;
  tangential::TangentialSolution solution;  ///< with the cells' fields
  wear::WearDistribution distribution;      ///< depth per metre on 0.1 mm bins of wheel arc length
  wear::WearSummary summary;
};

/// `patch` of `pair` worn with `model` and `law` on a cells x cells grid, the creepages and the
/// speed from `in`; `positions` keeps the cells' positions (for a T gamma map).
ModelWear model_wear(const ContactInputs& in, const contactgeom::WheelRailPair& pair,
                     const contactgeom::WheelRailPatch& patch, tangential::ContactModel model,
                     const wear::WearLaw& law, int cells, bool positions);

}  // namespace wheelwear::cli
