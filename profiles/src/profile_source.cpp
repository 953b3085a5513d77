#include "wheelwear/profiles/profile_source.hpp"

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::profiles {

namespace {

bool is_builtin_rail(const std::string& spec) {
  return spec == "60E1" || spec == "UIC60";
}

// Cants a rail profile towards the track centre by `angle` about its top of rail, as the
// generated 60E1 is canted: the crown turns towards the gauge side (-y), the field side rises.
profiles::Profile canted(const profiles::Profile& rail, double angle) {
  const profiles::Point top = profiles::top_of_rail(rail).point;
  const double c = std::cos(angle), s = std::sin(angle);
  profiles::PointList points = rail.resample(0.1e-3);
  for (auto& p : points) {
    const profiles::Point d = p - top;
    p = top + profiles::Point(c * d[0] + s * d[1], -s * d[0] + c * d[1]);
  }
  profiles::ProfileInfo info = rail.info();
  info.name += " canted";
  profiles::CurveOptions curve = rail.curve_options();
  curve.smoothing_length = 0.0;  // the points are already smooth: no second smoothing
  return profiles::Profile(points, info, curve);
}

}  // namespace

double default_inclination(const std::string& spec) {
  return is_builtin_rail(spec) ? std::atan(1.0 / 40.0) : 0.0;
}

LoadOptions ProfileFileOptions::load_options(Body body) const {
  LoadOptions options;
  options.read.body = body;
  options.origin = origin;
  options.taping_line_distance = taping_line_distance;
  options.cleaning.max_drop_fraction = max_drop_fraction;
  options.curve.smoothing_length = smoothing_length;
  if (body == Body::rail) options.orientation.mirror_y = rail_gauge_side;
  return options;
}

namespace {

profiles::Profile loaded(const std::string& spec, const std::optional<std::string>& text,
                         const LoadOptions& options, std::vector<std::string>* warnings) {
  LoadedProfile file =
      text ? prepare_profile(
                 parse_profile_text(*text, spec, detect_format(spec, *text), options.read), options)
           : profiles::load_profile(spec, options);
  if (warnings)
    warnings->insert(warnings->end(), file.cleaning.warnings.begin(), file.cleaning.warnings.end());
  return std::move(file.profile);
}

}  // namespace

profiles::Profile wheel_profile(const std::string& spec, std::optional<double> radius,
                                const ProfileFileOptions& files,
                                std::vector<std::string>* warnings) {
  if (radius)
    require(*radius > 0.1 && *radius < 2.0, "wheel radius", *radius, "must lie in 0.1 ... 2 m");
  if (spec == "S1002") {
    profiles::S1002Options options;
    options.nominal_radius = radius.value_or(kDefaultWheelRadius);
    return profiles::s1002(options);
  }
  profiles::LoadOptions options = files.load_options(Body::wheel);
  options.nominal_radius = radius;
  options.fallback_nominal_radius = kDefaultWheelRadius;
  return loaded(spec, files.text, options, warnings);
}

profiles::Profile rail_profile(const std::string& spec, std::optional<double> inclination,
                               const ProfileFileOptions& files,
                               std::vector<std::string>* warnings) {
  const double angle = inclination.value_or(default_inclination(spec));
  require(std::isfinite(angle) && std::abs(angle) <= 0.1, "rail inclination", angle,
          "must lie in -0.1 ... 0.1 rad (1:40 is 0.025, 1:20 is 0.05)");
  if (is_builtin_rail(spec)) {
    require(angle >= 0.0, "rail inclination", angle,
            "the built-in 60E1 is canted towards the track centre (>= 0)");
    profiles::Rail60E1Options options;
    options.inclination = angle;
    return profiles::rail_60e1(options);
  }
  const profiles::Profile rail = loaded(spec, files.text, files.load_options(Body::rail), warnings);
  return angle == 0.0 ? rail : canted(rail, angle);
}

}  // namespace wheelwear::profiles
