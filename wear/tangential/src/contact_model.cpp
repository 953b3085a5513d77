#include "wheelwear/tangential/contact_model.hpp"

#include <utility>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

namespace {
constexpr core::NameTable<ContactModel, 5> kNames = {{
    {ContactModel::sdec, "sdec"},
    {ContactModel::eql, "eql"},
    {ContactModel::eqe, "eqe"},
    {ContactModel::eqe_shifted, "eqe-shifted"},
    {ContactModel::hertz, "hertz"},
}};
}  // namespace

std::string_view model_name(ContactModel model) { return core::name_of(kNames, model); }

std::optional<ContactModel> parse_contact_model(std::string_view name) {
  return core::value_named(kNames, name);
}

ModelPatch model_patch(ContactModel model, const contactgeom::Sdec& sdec,
                       const std::optional<contactgeom::Sdec>& hertz_ellipse) {
  switch (model) {
    case ContactModel::sdec:
      return {FastsimMethod::sdec, sdec};
    case ContactModel::eql:
      return {FastsimMethod::eql, sdec};
    case ContactModel::eqe:
      return {FastsimMethod::eqe, sdec};
    case ContactModel::eqe_shifted:
      return {FastsimMethod::eqe_shifted, sdec};
    case ContactModel::hertz:
      if (!hertz_ellipse) {
        throw InputError(
            "contact model hertz: no Hertz ellipse at this contact (the relative lateral "
            "curvature at O is not positive); use another model");
      }
      return {FastsimMethod::elliptic, *hertz_ellipse};
  }
  return {FastsimMethod::sdec, sdec};
}

}  // namespace wheelwear::tangential
