#pragma once
/// The whole way from a file (or points) to a Profile: read, validate, orient, clean, validate,
/// fit.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "wheelwear/profiles/cleaning.hpp"
#include "wheelwear/profiles/orientation.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/profiles/raw_profile.hpp"
#include "wheelwear/profiles/validation.hpp"

namespace wheelwear::profiles {

/// Options of every stage.
struct LoadOptions {
  ReadOptions read;                ///< unit, columns, body override
  OrientationOptions orientation;  ///< mirroring
  CleaningOptions cleaning;        ///< cleaning thresholds
  ValidationOptions validation;    ///< validation limits
  /// The fit. Default: smoothing length 0.3 mm, which halves wavelengths of 1.9 mm (measurement
  /// noise) and leaves the 12 mm flange tip radius within 0.1%.
  CurveOptions curve{0.3e-3, 0.25e-3};
  std::optional<Side> side{};   ///< overrides the file; default right
  double nominal_radius = 0.0;  ///< wheels: rolling radius at the taping line [m]
  std::string name{};           ///< profile name; default the file name
  /// Rails: depth below the top of rail [m] to which a rail is cropped (crop_rail) when it is
  /// refused whole: validate_order, clean and validate_geometry run on the whole rail first and,
  /// if one of them throws, again on the cropped rail (the report says why it was cropped). 0
  /// never crops. 25 mm lies between the gauge point (14 mm below the top) and the shallowest
  /// gauge-face undercut of real rails (about 30 mm), which fails validate_order. Nothing a wheel
  /// can touch is lost: no accepted wheel/rail contact lies deeper than the flange tip's reach,
  /// 28 mm below the taping line for S1002 when the wheel sits at its gauge point, and S1002 on
  /// 60E1 (upright, 1:40, 1:20) touches no deeper than 12 mm.
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
};

/// Runs the stages on points already read: validate_points, orient, validate_order, clean,
/// validate_geometry (for rails refused whole, again after crop_rail), Profile. The body comes from
/// options.read.body, else from the source; throws InputError if neither says, or from any stage.
/// The report carries the reader's repairs and the crop, and warns of a point count off by one, of
/// a rail without a gauge point (nothing 14 mm below its top on the gauge side: `contact` cannot
/// place it) and of a rail whose field side lies lower (estimate_inclination below -1:200, when
/// mirror_y was automatic: probably mirrored).
LoadedProfile prepare_profile(RawProfile raw, const LoadOptions& options = {});

/// read_profile_file() and prepare_profile().
LoadedProfile load_profile(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace wheelwear::profiles
