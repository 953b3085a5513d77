#include "wheelwear/core/input_error.hpp"

#include <cmath>
#include <sstream>

namespace wheelwear {

void require(bool condition, std::string_view field, double value, std::string_view constraint) {
  if (condition) return;
  std::ostringstream message;
  message.precision(9);
  message << field << " = " << value << ": " << constraint;
  throw InputError(message.str());
}

void require_finite(std::string_view field, double value) {
  require(std::isfinite(value), field, value, "must be a finite number");
}

}  // namespace wheelwear
