#pragma once
/// The wear laws as one interchangeable model: a std::variant of the T gamma law (default: USFD)
/// and the Archard law (default: the KTH map). A caller dispatches once per patch (std::visit,
/// or depths_per_passage() below) and the per-cell call inside is inlined: no virtual call and
/// no allocation per cell.

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <variant>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/wear/wear_law_archard.hpp"
#include "wheelwear/wear/wear_law_state.hpp"
#include "wheelwear/wear/wear_law_tgamma.hpp"

namespace wheelwear::wear {

/// A wear law: the T gamma law or the Archard law, each with its own table and parameters.
using WearLaw = std::variant<TgammaLaw, ArchardLaw>;

/// Names of the built-in laws on the command line and in files: "usfd", "archard".
inline constexpr std::array<std::string_view, 2> kWearLawNames = {"usfd", "archard"};

/// The built-in law named `name` ("usfd": TgammaLaw::usfd(), "archard": ArchardLaw::kth()) with
/// the default density and hardness; std::nullopt for any other name.
std::optional<WearLaw> default_wear_law(std::string_view name);

/// The law's name (TgammaLaw::name() or ArchardLaw::name()).
std::string_view law_name(const WearLaw& law);

/// Index of the regime the cell falls in; -1 for an invalid state.
int regime(const WearLaw& law, const CellState& cell);
/// Name of regime `index` of the law.
std::string_view regime_name(const WearLaw& law, int index);

/// Depth [m] one passage through a cell of length dx [m] removes; one dispatch per call, so
/// prefer depths_per_passage() or std::visit around a loop for many cells.
inline double depth_per_passage(const WearLaw& law, const CellState& cell, double dx) {
  return std::visit([&](const auto& l) { return l.depth_per_passage(cell, dx); }, law);
}

/// Depths [m] of a strip of cells of common length dx [m], one dispatch for the whole strip.
/// @param depth  output; throws InputError unless depth.size() == cells.size()
inline void depths_per_passage(const WearLaw& law, std::span<const CellState> cells, double dx,
                               std::span<double> depth) {
  require(depth.size() == cells.size(), "depth.size()", static_cast<double>(depth.size()),
          "must equal cells.size()");
  std::visit([&](const auto& l) { l.depths_per_passage(cells, dx, depth); }, law);
}

/// The same for cells given as columns (CellColumns).
/// @param depth  output; throws InputError unless depth.size() == cells.work.size() and the
///               three columns have that size too
inline void depths_per_passage(const WearLaw& law, const CellColumns& cells, double dx,
                               std::span<double> depth) {
  require(depth.size() == cells.work.size(), "depth.size()", static_cast<double>(depth.size()),
          "must equal the number of cells");
  require(cells.pressure.size() == depth.size() && cells.slip.size() == depth.size(),
          "cells.pressure.size()", static_cast<double>(cells.pressure.size()),
          "the columns pressure, work and slip must have the same size");
  std::visit([&](const auto& l) { l.depths_per_passage(cells, dx, depth); }, law);
}

}  // namespace wheelwear::wear
