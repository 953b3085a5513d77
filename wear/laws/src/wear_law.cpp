#include "wheelwear/wear/wear_law.hpp"

#include <cmath>
#include <variant>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::wear {

void CellState::validate() const {
  for (const auto& [field, value] :
       {std::pair{"pressure", pressure}, std::pair{"traction", traction}, std::pair{"slip", slip},
        std::pair{"speed", speed}}) {
    require_finite(field, value);
    require(value >= 0.0, field, value, "must be >= 0");
  }
}

std::optional<WearLaw> default_wear_law(std::string_view name) {
  if (name == "usfd") return WearLaw(TgammaLaw::usfd());
  if (name == "archard") return WearLaw(ArchardLaw::kth());
  return std::nullopt;
}

std::string_view law_name(const WearLaw& law) {
  return std::visit([](const auto& l) { return l.name(); }, law);
}

int regime(const WearLaw& law, const CellState& cell) {
  return std::visit([&](const auto& l) { return l.regime(cell); }, law);
}

std::string_view regime_name(const WearLaw& law, int index) {
  return std::visit([&](const auto& l) { return l.regime_name(index); }, law);
}

}  // namespace wheelwear::wear
