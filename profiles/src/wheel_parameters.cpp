#include "wheelwear/profiles/wheel_parameters.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/internal_face.hpp"

namespace wheelwear::profiles {

namespace {

// Arc length in [a, b] where f changes sign (f(a), f(b) of opposite signs), by bisection to
// round-off.
double bisect(const std::function<double(double)>& f, double a, double b) {
  const bool a_positive = f(a) > 0.0;
  for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
    const double mid = 0.5 * (a + b);
    if ((f(mid) > 0.0) == a_positive)
      a = mid;
    else
      b = mid;
  }
  return 0.5 * (a + b);
}

}  // namespace

void WheelParameterOptions::validate() const {
  require(std::isfinite(taping_line_offset) && taping_line_offset > 0.0, "taping line offset [m]",
          taping_line_offset, "must be > 0");
  require(std::isfinite(sd_height) && sd_height > 0.0, "Sd height [m]", sd_height, "must be > 0");
  require(std::isfinite(qr_height) && qr_height > 0.0, "qR height [m]", qr_height, "must be > 0");
}

WheelParameters wheel_parameters(const Profile& wheel, const WheelParameterOptions& options) {
  options.validate();
  if (wheel.body() != Body::wheel)
    throw InputError("profile " + wheel.info().name +
                     " is a rail: Sh, Sd, qR are wheel parameters");
  WheelParameters out;
  const double h = wheel.curve().knot_spacing();
  const std::vector<double>& s_knots = wheel.curve().knots();
  const auto knots = static_cast<std::ptrdiff_t>(s_knots.size()) - 1;
  auto at = [&](std::ptrdiff_t k) { return wheel.position(s_knots[static_cast<std::size_t>(k)]); };

  // The internal face from its steep points, or by the profile's origin convention.
  const double y_face = internal_face(wheel).y;
  const double y_tape = y_face + options.taping_line_offset;
  const auto tape = wheel.surface_at(y_tape);
  if (!tape)
    throw InputError("profile " + wheel.info().name + " does not reach the running circle " +
                     std::to_string(options.taping_line_offset * 1e3) +
                     " mm from its internal face");
  out.running_circle = Point(y_tape, tape->z);

  // Flange tip: the largest z between the internal face and the running circle.
  const auto tape_knot = std::min(knots, static_cast<std::ptrdiff_t>(std::floor(tape->s / h)));
  std::ptrdiff_t tip = 0;
  for (std::ptrdiff_t k = 0; k <= tape_knot; ++k)
    if (at(k)[1] > at(tip)[1]) tip = k;
  double lo = s_knots[static_cast<std::size_t>(std::max<std::ptrdiff_t>(tip - 1, 0))];
  double hi = s_knots[static_cast<std::size_t>(std::min(tip + 1, knots))];
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {  // golden-section maximum of z(s)
    const double a = hi - 0.618033988749895 * (hi - lo), b = lo + 0.618033988749895 * (hi - lo);
    if (wheel.position(a)[1] > wheel.position(b)[1])
      hi = b;
    else
      lo = a;
  }
  const double s_tip = 0.5 * (lo + hi);
  out.flange_tip = wheel.position(s_tip);
  out.Sh = out.flange_tip[1] - out.running_circle[1];
  if (!(out.Sh > options.sd_height))
    throw InputError("profile " + wheel.info().name + ": flange height " +
                     std::to_string(out.Sh * 1e3) + " mm is too small to measure Sd " +
                     std::to_string(options.sd_height * 1e3) + " mm from the running circle");

  // Flange face points: walk from the tip towards the tread until z falls below the level.
  auto face_point = [&](double level, const char* what) {
    const auto f = [&](double s) { return wheel.position(s)[1] - level; };
    for (double s = s_tip; s < tape->s; s += h) {
      const double next = std::min(s + h, tape->s);
      if (f(next) <= 0.0) return wheel.position(bisect(f, s, next));
    }
    throw InputError("profile " + wheel.info().name + ": no flange face point for " + what);
  };
  out.sd_point = face_point(out.running_circle[1] + options.sd_height, "Sd");
  out.qr_point = face_point(out.flange_tip[1] - options.qr_height, "qR");
  out.internal_face = Point(y_face, out.flange_tip[1]);
  out.Sd = out.sd_point[0] - y_face;
  out.qR = out.sd_point[0] - out.qr_point[0];
  return out;
}

WheelLimits in_service_limits(double diameter) {
  if (!std::isfinite(diameter) || diameter < kSmallestStandardWheel) {
    throw InputError("wheel diameter " + std::to_string(diameter) +
                     " m: EN 15313's in-service limits cover diameters from 0.33 m");
  }
  WheelLimits limits;
  limits.Sh_max = 36e-3;
  limits.qR_min = 6.5e-3;
  if (diameter >= 0.840)
    limits.Sd_min = 22e-3;
  else if (diameter > 0.760)
    limits.Sd_min = 25e-3;
  else
    limits.Sd_min = 27.5e-3;
  return limits;
}

std::vector<std::string> limits_reached(const WheelParameters& parameters,
                                        const WheelLimits& limits) {
  std::vector<std::string> reached;
  auto phrase = [&](const char* name, double value, const char* relation, double limit) {
    char text[96];
    if (std::isnan(value))
      std::snprintf(text, sizeof text, "%s not measurable (worn past its reference points)", name);
    else
      std::snprintf(text, sizeof text, "%s %.3f mm %s %.3f mm", name, value * 1e3, relation,
                    limit * 1e3);
    reached.emplace_back(text);
  };
  // A limit that is NaN is not watched; a parameter that is NaN could not be measured on a
  // profile worn past its reference points, which is past any limit.
  auto past = [](double value, double limit, bool below) {
    if (std::isnan(limit)) return false;
    return std::isnan(value) || (below ? value <= limit : value >= limit);
  };
  if (past(parameters.Sd, limits.Sd_min, true)) phrase("Sd", parameters.Sd, "<=", limits.Sd_min);
  if (past(parameters.Sh, limits.Sh_max, false)) phrase("Sh", parameters.Sh, ">=", limits.Sh_max);
  if (past(parameters.qR, limits.qR_min, true)) phrase("qR", parameters.qR, "<=", limits.qR_min);
  return reached;
}

}  // namespace wheelwear::profiles
