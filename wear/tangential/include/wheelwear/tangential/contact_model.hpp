#pragma once
/// The five contact models a wear study compares, named the same everywhere (CLI, scenes, HDF5).

#include <array>
#include <optional>
#include <string_view>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::tangential {

/// How a non-elliptic contact is modelled for the tangential problem.
enum class ContactModel {
  sdec,         ///< the SDEC region with FASTSIM-SDEC (Liu, Fu & Bruni 2022)
  eql,          ///< the SDEC region with Kalker's flexibilities of the ellipse a, b (FASTSIM-EQ.L)
  eqe,          ///< the equivalent ellipse a, b centred at O, classic FASTSIM (FASTSIM-EQ.E)
  eqe_shifted,  ///< the equivalent ellipse centred at O' = O + psi b, creepage moved there
  hertz,        ///< the Hertz ellipse from the curvatures at O, centred at O, classic FASTSIM
};

inline constexpr std::array<ContactModel, 5> kContactModels = {
    ContactModel::sdec, ContactModel::eql, ContactModel::eqe, ContactModel::eqe_shifted,
    ContactModel::hertz};

/// The models' names in scenes, on the command line and in files.
inline constexpr core::NameTable<ContactModel, 5> kContactModelNames = {{
    {ContactModel::sdec, "sdec"},
    {ContactModel::eql, "eql"},
    {ContactModel::eqe, "eqe"},
    {ContactModel::eqe_shifted, "eqe-shifted"},
    {ContactModel::hertz, "hertz"},
}};

/// "sdec", "eql", "eqe", "eqe-shifted", "hertz" (kContactModelNames).
std::string_view model_name(ContactModel model);
/// The model named `name`, std::nullopt when unknown.
std::optional<ContactModel> parse_contact_model(std::string_view name);

/// The region and the FASTSIM method (solve_patch) a model solves on, given the patch's SDEC
/// and its Hertz ellipse (semi-axes a along x, b along y; needed by ContactModel::hertz only).
struct ModelPatch {
  Method method = Method::fastsim_sdec;
  contactgeom::Sdec region;
};
ModelPatch model_patch(ContactModel model, const contactgeom::Sdec& sdec,
                       const std::optional<contactgeom::Sdec>& hertz_ellipse);

}  // namespace wheelwear::tangential
