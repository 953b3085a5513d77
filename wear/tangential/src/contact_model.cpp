#include "wheelwear/tangential/contact_model.hpp"

#include <utility>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

std::string_view model_name(ContactModel model) {
  return core::name_of(kContactModelNames, model);
}

std::optional<ContactModel> parse_contact_model(std::string_view name) {
  return core::value_named(kContactModelNames, name);
}

ModelPatch model_patch(ContactModel model, const contactgeom::Sdec& sdec,
                       const std::optional<contactgeom::Sdec>& hertz_ellipse) {
  switch (model) {
    case ContactModel::sdec:
      return {Method::fastsim_sdec, sdec};
    case ContactModel::eql:
      return {Method::fastsim_eql, sdec};
    case ContactModel::eqe:
      return {Method::fastsim_eqe, sdec};
    case ContactModel::eqe_shifted:
      return {Method::fastsim_eqe_shifted, sdec};
    case ContactModel::hertz:
      if (!hertz_ellipse) {
        throw InputError(
            "contact model hertz: no Hertz ellipse at this contact (the relative lateral "
            "curvature at O is not positive); use another model");
      }
      return {Method::fastsim_elliptic, *hertz_ellipse};
  }
  return {Method::fastsim_sdec, sdec};
}

}  // namespace wheelwear::tangential
