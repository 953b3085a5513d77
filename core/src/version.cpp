#include "wheelwear/core/version.hpp"

namespace wheelwear::core {

const char* version() {
  return WHEELWEAR_VERSION;
}

}  // namespace wheelwear::core
