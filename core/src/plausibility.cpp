#include "wheelwear/core/plausibility.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::core {

namespace {

// The shortest exact text, with the exponent as a user types it (1e6, not 1e+06).
std::string compact(double value) {
  std::string text = format_number(value);
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::size_t digits = e + 1;
  if (text[digits] == '+') text.erase(digits, 1);
  if (text[digits] == '-') ++digits;
  while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
  return text;
}

std::string named(std::string_view input, double value, std::string_view unit) {
  return std::string(input) + " = " + limit_text(value, unit) + ": ";
}

}  // namespace

std::string limit_text(double value, std::string_view unit) {
  std::string text = compact(value);
  if (!unit.empty() && std::isfinite(value)) (text += ' ') += unit;
  return text;
}

void require_plausible(const PlausibilityLimit& limit, std::string_view input, double value) {
  if (!std::isfinite(value)) throw InputError(named(input, value, {}) + "must be a finite number");
  if (limit.positive && !(value > 0.0))
    throw InputError(named(input, value, limit.unit) + std::string(limit.quantity) +
                     " must be positive");
  const double size = std::abs(value);
  if (size < limit.refuse || (size == limit.refuse && !limit.refuse_at_limit)) return;
  throw InputError(
      named(input, value, limit.unit) + std::string(limit.quantity) +
      (limit.refuse_at_limit ? " of " : " above ") + limit_text(limit.refuse, limit.unit) +
      (limit.refuse_at_limit ? " or more" : "") +
      " are impossible: " + std::string(limit.refuse_reason) + "; " + std::string(limit.fix));
}

std::optional<std::string> plausibility_warning(const PlausibilityLimit& limit,
                                                std::string_view input, double value) {
  if (!(std::abs(value) > limit.warn)) return std::nullopt;
  return named(input, value, limit.unit) + std::string(limit.quantity) + " above " +
         limit_text(limit.warn, limit.unit) +
         " are implausible: " + std::string(limit.warn_reason) + "; " + std::string(limit.fix);
}

void check_plausible(const PlausibilityLimit& limit, std::string_view input, double value,
                     std::vector<std::string>& warnings) {
  require_plausible(limit, input, value);
  if (auto warning = plausibility_warning(limit, input, value)) warnings.push_back(*warning);
}

}  // namespace wheelwear::core
