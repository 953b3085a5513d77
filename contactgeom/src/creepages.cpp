#include "wheelwear/contactgeom/creepages.hpp"

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

void Creepages::validate() const {
  require_finite("vx", vx);
  require_finite("vy", vy);
  require_finite("phi", phi);
}

}  // namespace wheelwear::contactgeom
