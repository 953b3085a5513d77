#include "wheelwear/profiles/conical_wheel.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

void ConicalWheelOptions::validate() const {
  require(std::isfinite(conicity) && conicity >= 0.0 && conicity <= 0.5, "conicity", conicity,
          "must lie in 0 ... 0.5");
  require(std::isfinite(nominal_radius) && nominal_radius > 0.0, "nominal radius [m]",
          nominal_radius, "must be positive");
  require(std::isfinite(flange_side) && flange_side < -0.02, "flange-side end [m]", flange_side,
          "must lie below -0.02 (the cone must reach past the contact)");
  require(std::isfinite(field_side) && field_side > 0.02, "field-side end [m]", field_side,
          "must lie above 0.02");
  require(std::isfinite(point_spacing) && point_spacing >= 1e-5 && point_spacing <= 1e-3,
          "point spacing [m]", point_spacing, "must lie in 1e-5 ... 1e-3");
}

Profile conical_wheel(const ConicalWheelOptions& options) {
  options.validate();
  const double length = options.field_side - options.flange_side;
  const auto n = static_cast<int>(std::ceil(length / options.point_spacing));
  PointList points;
  for (int k = 0; k <= n; ++k) {
    const double y = options.flange_side + length * k / n;
    points.emplace_back(y, -options.conicity * y);
  }
  ProfileInfo info{"cone", Body::wheel, options.side, options.nominal_radius};
  info.taping_line_distance = -options.flange_side;
  CurveOptions curve;
  curve.smoothing_length = 0.0;
  return Profile(points, info, curve);
}

}  // namespace wheelwear::profiles
