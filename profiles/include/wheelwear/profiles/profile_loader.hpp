#pragma once
/// The whole way from a file (or points) to a Profile: read, validate, orient, clean, validate,
/// fit.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "wheelwear/profiles/cleaning.hpp"
#include "wheelwear/profiles/orientation.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/profiles/raw_profile.hpp"
#include "wheelwear/profiles/validation.hpp"

namespace wheelwear::profiles {

/// Where a wheel file puts its lateral origin. The loaded wheel always has its taping line at
/// y = 0 (profile.hpp); a file whose origin is the internal face (flange back), as MiniProf writes
/// wheels (.whl, and .prw made from them), is moved by LoadOptions::taping_line_distance.
///
/// The automatic rule, on the oriented, cleaned points (flange towards -y):
/// - the profile reaches kTapingLineReach (60 mm) or more on the flange side of y = 0: the origin
///   is the taping line (a whole wheel reaches 70 mm there, S1002 included; nothing else can);
/// - its flange-side end lies within kInternalFaceTolerance (5 mm) of y = 0: the origin is the
///   internal face (the back face's rounding and measuring noise stay well within 5 mm);
/// - anything else is refused, naming both readings and the option that chooses one.
/// The taping-line distance is LoadOptions::taping_line_distance where set, else the file
/// header's (MiniProf `WheelDiameterTaperline`, RawProfile::taping_line_distance), else 70 mm.
enum class WheelOrigin {
  automatic,      ///< by the rule above
  taping_line,    ///< the file's y = 0 is the taping line: kept
  internal_face,  ///< the file's y = 0 is the internal face: moved by -taping_line_distance
};

/// Flange-side reach from y = 0 [m] from which the automatic rule takes the taping line.
inline constexpr double kTapingLineReach = 0.060;
/// Distance of the flange-side end from y = 0 [m] within which it takes the internal face.
inline constexpr double kInternalFaceTolerance = 0.005;
/// Taping line from the internal face [m] (EN 13715) when neither the user nor the file says.
inline constexpr double kDefaultTapingLineDistance = 0.070;

/// "auto", "taping-line" or "internal-face" to WheelOrigin; nullopt for anything else.
std::optional<WheelOrigin> parse_wheel_origin(std::string_view text);
/// "auto", "taping-line" or "internal-face".
std::string_view to_string(WheelOrigin origin);

/// Which lateral origin a wheel file was read with, and why.
struct OriginReport {
  WheelOrigin origin = WheelOrigin::taping_line;  ///< taping_line or internal_face (never auto)
  double shift = 0.0;  ///< added to the file's y [m]: 0, or -taping_line_distance
  std::string reason;  ///< why this origin, with the flange-side end as read [mm]
};

/// Options of every stage.
struct LoadOptions {
  ReadOptions read;                ///< unit, columns, body override
  OrientationOptions orientation;  ///< mirroring
  CleaningOptions cleaning;        ///< cleaning thresholds
  ValidationOptions validation;    ///< validation limits
  /// The fit. Default: smoothing length 0.3 mm, which halves wavelengths of 1.9 mm (measurement
  /// noise) and leaves the 12 mm flange tip radius within 0.1%.
  CurveOptions curve{0.3e-3, 0.25e-3};
  std::optional<Side> side{};  ///< overrides the file; default right
  /// Wheels: rolling radius at the taping line [m]; default half the wheel diameter the file's
  /// header states, else fallback_nominal_radius.
  std::optional<double> nominal_radius{};
  double fallback_nominal_radius = 0.0;  ///< [m]; 0: not known
  std::string name{};                    ///< profile name; default the file name
  /// Wheels: the file's lateral origin (WheelOrigin; rails ignore it): by default the automatic
  /// rule; a set origin that the rule contradicts is used with a warning.
  WheelOrigin origin = WheelOrigin::automatic;
  /// Wheels: taping line distance from the internal face [m] for WheelOrigin::internal_face,
  /// 0.03 ... 0.11; default the file header's, else kDefaultTapingLineDistance.
  std::optional<double> taping_line_distance{};
  /// Rails: depth below the top of rail [m] to which a rail is cropped (crop_rail) when it is
  /// refused whole: validate_order, clean and validate_geometry run on the whole rail first and,
  /// if one of them throws, again on the cropped rail (the report says why it was cropped), and
  /// if that is refused too, once more with the undercuts of the head's lips shadowed
  /// (shadow_lip; CleaningReport::lip). 0 never crops nor shadows: the rail is taken as it is. 25
  /// mm lies between the gauge point (14 mm below the top) and the shallowest gauge-face undercut
  /// of real rails (about 30 mm), which fails validate_order. Nothing a wheel can touch is lost: no
  /// accepted wheel/rail contact lies deeper than the flange tip's reach, 28 mm below the taping
  /// line for S1002 when the wheel sits at its gauge point, and S1002 on 60E1 (upright, 1:40, 1:20)
  /// touches no deeper than 12 mm.
  double crop_depth = 0.025;
  /// Crop every rail to crop_depth, not only those refused whole. Off by default: cropping
  /// changes nothing a wheel can touch, but it moves the start of the fitted curve and with it
  /// the curve's knots, which shifts the fit by up to a micrometre.
  bool crop_always = false;
};

/// A fitted profile with the record of how it was made.
struct LoadedProfile {
  Profile profile;                ///< the fitted profile
  RawProfile points;              ///< the oriented, cleaned points it was fitted to
  std::size_t points_read = 0;    ///< points the source gave
  OrientationReport orientation;  ///< mirroring and reordering done
  CleaningReport cleaning;        ///< what the reader accepted, the crop, the cleaning, warnings
  OriginReport origin;            ///< wheels: the lateral origin used and why
};

/// Runs the stages on points already read: validate_points, orient, validate_order, clean,
/// validate_geometry (for rails refused whole, again after crop_rail), for wheels the lateral
/// origin (WheelOrigin: the points are moved so that the taping line is at y = 0), Profile. The
/// body comes from options.read.body, else from the source; throws InputError if neither says, or
/// from any stage. The report carries the reader's repairs and the crop, and warns of a point count
/// off by one, of a rail without a gauge point (nothing 14 mm below its top on the gauge side:
/// `contact` cannot place it) and of a rail whose field side lies lower (estimate_inclination below
/// -1:200, when mirror_y was automatic: probably mirrored).
LoadedProfile prepare_profile(RawProfile raw, const LoadOptions& options = {});

/// read_profile_file() and prepare_profile().
LoadedProfile load_profile(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace wheelwear::profiles
