#include "wheelwear/tangential/exact/exact_types.hpp"

#include <cmath>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

void ElementGrid::validate() const {
  require(nx >= 1 && nx <= kMaxElementsPerSide, "grid.nx", nx, "needs 1 ... 4096 elements");
  require(ny >= 1 && ny <= kMaxElementsPerSide, "grid.ny", ny, "needs 1 ... 4096 elements");
  require_finite("grid.x_min", x_min);
  require_finite("grid.y_min", y_min);
  require_finite("grid.dx", dx);
  require_finite("grid.dy", dy);
  require(dx > 0.0, "grid.dx", dx, "the element length must be positive (metres)");
  require(dy > 0.0, "grid.dy", dy, "the element width must be positive (metres)");
}

void SdecGridOptions::validate() const {
  require(nx >= 2 && nx <= kMaxElementsPerSide, "nx", nx, "needs 2 ... 4096 elements along x");
  require(ny >= 1 && ny <= kMaxElementsPerSide, "ny", ny, "needs 1 ... 4096 elements along y");
  require_finite("margin", margin);
  require(margin >= 1.0 && margin <= 10.0, "margin", margin,
          "the potential contact area must cover the patch: 1 <= margin <= 10");
  require_finite("shift_x", shift_x);
  require_finite("shift_y", shift_y);
  require(std::abs(shift_x) <= 0.5, "shift_x", shift_x, "must lie in [-0.5, 0.5] elements");
  require(std::abs(shift_y) <= 0.5, "shift_y", shift_y, "must lie in [-0.5, 0.5] elements");
}

void ExactSolverOptions::validate() const {
  require_finite("tolerance", tolerance);
  require(tolerance > 0.0, "tolerance", tolerance, "must be positive");
  require_finite("normal_tolerance", normal_tolerance);
  require(normal_tolerance > 0.0, "normal_tolerance", normal_tolerance, "must be positive");
  require(max_iterations >= 1, "max_iterations", max_iterations, "must be at least 1");
}

namespace {
constexpr core::NameTable<ExactStatus, 3> kStatusNames = {{
    {ExactStatus::converged, "converged"},
    {ExactStatus::not_converged, "not converged"},
    {ExactStatus::no_contact, "no contact"},
}};
}  // namespace

// The table's names are string literals: data() is null-terminated.
const char* status_name(ExactStatus status) {
  return core::name_of(kStatusNames, status).data();
}

}  // namespace wheelwear::tangential
