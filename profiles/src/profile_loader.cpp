#include "wheelwear/profiles/profile_loader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "flank_waviness.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::profiles {

namespace {

constexpr core::NameTable<WheelOrigin, 3> kOriginNames = {{
    {WheelOrigin::automatic, "auto"},
    {WheelOrigin::taping_line, "taping-line"},
    {WheelOrigin::internal_face, "internal-face"},
}};

// An estimated inclination below minus this (1:200) means the field side lies lower.
constexpr double kMirroredInclination = 1.0 / 200.0;

// A rail whose gauge side does not reach the gauge measuring depth has no gauge point, and
// `contact` cannot place it; say so while the file is at hand, with the likely cause.
std::optional<std::string> gauge_point_warning(const Profile& rail, const RawProfile& raw,
                                               const OrientationReport& orientation) {
  const TrackGeometry track;
  try {
    gauge_point(rail, track.gauge_measuring_depth);
    return std::nullopt;
  } catch (const InputError&) {
  }
  const double reach = rail.position(0.0)[1] - top_of_rail(rail).point[1];
  const int line = raw.lines.empty() ? 0 : raw.lines.front();
  std::string message =
      raw.source + (line > 0 ? ":" + std::to_string(line) : std::string()) +
      ": no gauge point: the gauge side (the profile's -y end" +
      (orientation.mirrored_y ? ", the file's larger lateral values"
                              : ", the file's smaller lateral values") +
      ") reaches " + core::format_mm(reach, 1) + " below the top of rail, less than the " +
      core::format_mm(track.gauge_measuring_depth, 1) +
      " where the gauge is measured, so `contact` cannot place this rail. If "
      "the gauge face is at the file's other end, set the gauge side "
      "(--gauge-side of profile, contact and wear, the scene's [rail] gauge_side, "
      "LoadOptions::orientation.mirror_y)";
  return message;
}

// Rails are laid canted towards the track centre, so a profile whose field side lies lower was
// probably oriented the wrong way round by the automatic rule (a rail measured deeper on its
// field side, as switch rails can be).
std::optional<std::string> mirrored_rail_warning(const Profile& rail, const RawProfile& raw,
                                                 const OrientationReport& orientation) {
  const auto inclination = estimate_inclination(rail);
  if (!inclination || inclination->angle > -kMirroredInclination) return std::nullopt;
  std::ostringstream message;
  message.precision(3);
  message << raw.source << ": the field side lies lower than the gauge side (estimated "
          << "inclination " << inclination->angle
          << " rad, about 1:" << std::lround(1.0 / std::abs(std::tan(inclination->angle)))
          << "), but rails are canted towards the track centre: the gauge face is probably at "
          << "the file's other end (" << (orientation.mirrored_y ? "smaller" : "larger")
          << " lateral values; the automatic rule takes the end measured deeper). Set the gauge "
          << "side if so (--gauge-side " << (orientation.mirrored_y ? "left" : "right")
          << ", the scene's [rail] gauge_side, LoadOptions::orientation.mirror_y)";
  return message.str();
}

// The automatic rule's verdict (WheelOrigin) on oriented points: `evidence` is the flange-side end
// and the criterion it meets; no origin when it meets neither.
struct OriginVerdict {
  std::optional<WheelOrigin> origin;
  std::string evidence;
};

OriginVerdict automatic_origin(const RawProfile& raw) {
  double end = raw.points.front()[0];
  for (const Point& p : raw.points) end = std::min(end, p[0]);
  const std::string at = "its flange-side end lies at y = " + core::format_mm(end, 3);
  if (end <= -kTapingLineReach)
    return {WheelOrigin::taping_line, at + ", " + core::format_mm(kTapingLineReach, 1) +
                                          " or more on the flange side of y = 0"};
  if (std::abs(end) <= kInternalFaceTolerance)
    return {WheelOrigin::internal_face,
            at + ", within " + core::format_mm(kInternalFaceTolerance, 1) + " of y = 0"};
  return {std::nullopt, at + ", neither " + core::format_mm(kTapingLineReach, 1) +
                            " or more on the flange side of y = 0 (origin at the taping line) "
                            "nor within " +
                            core::format_mm(kInternalFaceTolerance, 1) +
                            " of y = 0 (origin at the internal face, as MiniProf writes wheels)"};
}

std::string origin_name(WheelOrigin origin) {
  return origin == WheelOrigin::taping_line ? "the taping line"
                                            : "the internal face (flange back, as MiniProf "
                                              "writes wheels)";
}

// The taping line distance: as set, else the file header's, else EN 13715's 70 mm.
double taping_line_distance(const RawProfile& raw, const LoadOptions& options) {
  return options.taping_line_distance.value_or(
      raw.taping_line_distance.value_or(kDefaultTapingLineDistance));
}

// A value set by the user that the file's header contradicts: used, with a warning.
void warn_if_header_differs(const RawProfile& raw, const char* what, std::optional<double> set,
                            std::optional<double> header, const char* option,
                            std::vector<std::string>& warnings) {
  if (!set || !header || std::abs(*set - *header) <= 1e-6) return;
  warnings.push_back(raw.source + ": " + what + " " + core::format_mm(*set, 3) + " as set (" +
                     option + ") differs from the file header's " + core::format_mm(*header, 3) +
                     "; the set value is used");
}

// Decides the wheel's origin (LoadOptions::origin) and moves the points so that the taping line
// is at y = 0. A disagreement with the automatic rule is a warning: a wrong origin puts the
// rolling radius 70 mm off, on the back face or the field side, without any other symptom.
OriginReport place_wheel_origin(RawProfile& raw, const LoadOptions& options,
                                std::vector<std::string>& warnings) {
  const double distance = taping_line_distance(raw, options);
  if (!(std::isfinite(distance) && distance >= 0.03 && distance <= 0.11))
    throw InputError(raw.source + ": taping line distance from the internal face " +
                     core::format_number(distance) +
                     " m must lie in 0.03 ... 0.11 m (EN 13715: 0.070); set profile "
                     "--taping-line-distance or LoadOptions::taping_line_distance in metres");
  const OriginVerdict verdict = automatic_origin(raw);
  OriginReport report;
  if (options.origin == WheelOrigin::automatic) {
    if (!verdict.origin)
      throw InputError(raw.source +
                       ": cannot tell the wheel's lateral origin: " + verdict.evidence +
                       ". Choose it: profile --origin taping-line or internal-face "
                       "(with --taping-line-distance, default 70 mm), LoadOptions::origin");
    report.origin = *verdict.origin;
    report.reason = "automatic: " + verdict.evidence + ", so the file's origin is " +
                    origin_name(report.origin);
  } else {
    report.origin = options.origin;
    report.reason = "as set (profile --origin, LoadOptions::origin)";
    if (verdict.origin && *verdict.origin != options.origin)
      warnings.push_back(raw.source + ": the file's lateral origin is taken as " +
                         origin_name(options.origin) +
                         " as set (profile --origin, "
                         "LoadOptions::origin), but " +
                         verdict.evidence + ", which means " + origin_name(*verdict.origin) +
                         ": the taping line and the rolling radius are then misplaced. Set "
                         "--origin auto or " +
                         std::string(to_string(*verdict.origin)));
  }
  warn_if_header_differs(
      raw, "taping line distance", options.taping_line_distance, raw.taping_line_distance,
      "--taping-line-distance, the scene's [wheel] taping_line_distance_m", warnings);
  if (report.origin == WheelOrigin::internal_face) {
    report.shift = -distance;
    report.reason += std::string("; taping line ") + core::format_mm(distance, 3) +
                     " from the internal face (" +
                     (options.taping_line_distance ? "as set"
                      : raw.taping_line_distance   ? "the file header's"
                                                   : "EN 13715's default") +
                     ")";
    report.reason +=
        "; moved by " + core::format_mm(report.shift, 3) + " to put the taping line at y = 0";
    for (Point& p : raw.points) p[0] += report.shift;
  }
  return report;
}

}  // namespace

std::optional<WheelOrigin> parse_wheel_origin(std::string_view text) {
  return core::value_named(kOriginNames, text);
}

std::string_view to_string(WheelOrigin origin) {
  return core::name_of(kOriginNames, origin);
}

LoadedProfile prepare_profile(RawProfile raw, const LoadOptions& options) {
  const std::optional<Body> body = options.read.body ? options.read.body : raw.body;
  if (!body)
    throw InputError(raw.source +
                     ": cannot tell whether this is a wheel or a rail profile; set the body");
  const std::size_t read = raw.points.size();
  validate_points(raw, options.validation);
  OrientationReport orientation = orient(raw, *body, options.orientation);
  // The stages after orientation; a rail refused whole is cropped and tried again (LoadOptions).
  const auto clean_and_check = [&](RawProfile& points) {
    validate_order(points, *body, options.validation);
    CleaningReport report = clean(points, *body, options.cleaning);
    validate_geometry(points, options.validation);
    return report;
  };
  CleaningReport cleaning;
  if (*body == Body::rail) check_crop_depth(options.crop_depth);  // before anything is tried
  if (*body == Body::rail && options.crop_depth > 0.0) {
    if (options.crop_always) {
      const CropReport crop = crop_rail(raw, options.crop_depth, options.cleaning);
      cleaning = clean_and_check(raw);
      cleaning.crop = crop;
    } else {
      RawProfile whole = raw;
      try {
        cleaning = clean_and_check(whole);
        raw = std::move(whole);
      } catch (const InputError& refused) {
        // Cropped to what a wheel can touch, and then, if still refused, with the underside of
        // a lip shadowed (cleaning.hpp): the first that passes is taken.
        CropReport crop = crop_rail(raw, options.crop_depth, options.cleaning);
        crop.reason = refused.what();
        std::string error = refused.what();
        if (crop.cropped() > 0) {
          RawProfile cropped = raw;
          try {
            cleaning = clean_and_check(cropped);
            raw = std::move(cropped);
            cleaning.crop = crop;
            error.clear();
          } catch (const InputError& again) {
            error = crop.reason == again.what()
                        ? crop.reason + " (also after " + crop.summary() + ")"
                        : std::string(again.what()) + " (after " + crop.summary() +
                              ", needed because the whole profile was refused: " + crop.reason +
                              ")";
          }
        }
        if (!error.empty()) {
          RawProfile shadowed = raw;
          LipReport lip = shadow_lip(shadowed, options.crop_depth);
          lip.reason = error;
          if (lip.hidden == 0) throw InputError(error);
          try {
            cleaning = clean_and_check(shadowed);
          } catch (const InputError&) {
            throw InputError(error);  // the lip was not why: the first error says what is
          }
          raw = std::move(shadowed);
          if (crop.cropped() > 0) cleaning.crop = crop;
          cleaning.lip = lip;
        }
      }
    }
  } else {
    cleaning = clean_and_check(raw);
  }
  OriginReport origin;
  if (*body == Body::wheel) origin = place_wheel_origin(raw, options, cleaning.warnings);
  cleaning.reading = raw.repairs;
  for (const ReadRepair& repair : raw.repairs)
    if (repair.warning) cleaning.warnings.push_back(repair.message);
  ProfileInfo info;
  info.name =
      options.name.empty() ? std::filesystem::path(raw.source).filename().string() : options.name;
  info.body = *body;
  info.side = options.side.value_or(raw.side.value_or(Side::right));
  if (*body == Body::wheel) {
    const std::optional<double> header_radius =
        raw.wheel_diameter ? std::optional<double>(0.5 * *raw.wheel_diameter) : std::nullopt;
    warn_if_header_differs(raw, "nominal rolling radius", options.nominal_radius, header_radius,
                           "--wheel-radius or profile --radius, the scene's [wheel] radius_m",
                           cleaning.warnings);
    info.nominal_radius =
        options.nominal_radius.value_or(header_radius.value_or(options.fallback_nominal_radius));
    info.taping_line_distance = taping_line_distance(raw, options);
  }
  Profile profile(raw.points, info, options.curve);
  if (*body == Body::wheel)
    if (const auto warning =
            detail::wavy_flank_warning(profile, raw.source, options.curve.smoothing_length))
      cleaning.warnings.push_back(*warning);
  if (*body == Body::rail) {
    if (const auto warning = gauge_point_warning(profile, raw, orientation))
      cleaning.warnings.push_back(*warning);
    if (options.orientation.mirror_y == Mirror::automatic)
      if (const auto warning = mirrored_rail_warning(profile, raw, orientation))
        cleaning.warnings.push_back(*warning);
  }
  return LoadedProfile{std::move(profile),     std::move(raw),      read,
                       std::move(orientation), std::move(cleaning), std::move(origin)};
}

LoadedProfile load_profile(const std::filesystem::path& path, const LoadOptions& options) {
  return prepare_profile(read_profile_file(path, options.read), options);
}

}  // namespace wheelwear::profiles
