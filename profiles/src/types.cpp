#include "wheelwear/profiles/types.hpp"

namespace wheelwear::profiles {

std::string_view to_string(Body body) {
  return body == Body::wheel ? "wheel" : "rail";
}

std::string_view to_string(Side side) {
  return side == Side::left ? "left" : "right";
}

}  // namespace wheelwear::profiles
