#include "wheelwear/profiles/profile.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::profiles {

namespace {

SurfaceLookup::Envelope envelope_for(Body body) {
  // z points down: the wheel surface the rail sees is the lowest material, i.e. the largest z;
  // the rail surface the wheel sees is the highest material, the smallest z.
  return body == Body::wheel ? SurfaceLookup::Envelope::max_z : SurfaceLookup::Envelope::min_z;
}

}  // namespace

Profile::Profile(const PointList& points, ProfileInfo info, const CurveOptions& options)
    : info_(std::move(info)), options_(options), curve_(points, options) {
  require(std::isfinite(info_.nominal_radius) && info_.nominal_radius >= 0.0, "nominal radius [m]",
          info_.nominal_radius, "must be finite and >= 0");
  lookup_ = SurfaceLookup(curve_, envelope_for(info_.body));
}

Point Profile::tangent(double s) const {
  return curve_.derivative(s).normalized();
}

Point Profile::normal(double s) const {
  const Point t = tangent(s);
  const Point left(-t[1], t[0]);
  return info_.body == Body::wheel ? left : Point(-left);
}

double Profile::curvature(double s) const {
  // The curve turns towards the +90 deg normal when signed_curvature > 0; the surface is convex
  // where it turns away from the outward normal, i.e. into the material.
  const double k = curve_.signed_curvature(s);
  return info_.body == Body::wheel ? -k : k;
}

std::optional<double> Profile::z_at(double y) const {
  const auto sample = lookup_.at(y);
  if (!sample) return std::nullopt;
  return sample->z;
}

Profile Profile::translated(double dy, double dz) const {
  require_finite("translation dy [m]", dy);
  require_finite("translation dz [m]", dz);
  Profile moved = *this;
  moved.curve_ = curve_.translated(Point(dy, dz));
  moved.lookup_ = SurfaceLookup(moved.curve_, envelope_for(info_.body));
  return moved;
}

}  // namespace wheelwear::profiles
