#include "wheelwear/contactgeom/strip_influence.hpp"

#include <limits>

#include "strip_kernel.hpp"

namespace wheelwear::contactgeom {

double line_influence(double c, double y) {
  if (c <= 0.0) return 0.0;
  if (y == 0.0) return std::numeric_limits<double>::infinity();
  return detail::line_kernel(c, y);
}

double strip_influence(double c, double y1, double y2) {
  return detail::strip_kernel(c, y1, y2);
}

}  // namespace wheelwear::contactgeom
