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
};

/// A fitted profile with the record of how it was made.
struct LoadedProfile {
  Profile profile;                ///< the fitted profile
  RawProfile points;              ///< the oriented, cleaned points it was fitted to
  std::size_t points_read = 0;    ///< points the source gave
  OrientationReport orientation;  ///< mirroring and reordering done
  CleaningReport cleaning;        ///< what the cleaning dropped
};

/// Runs the stages on points already read: validate_points, orient, validate_order, clean,
/// validate_geometry, Profile. The body comes from options.read.body, else from the source;
/// throws InputError if neither says, or from any stage.
LoadedProfile prepare_profile(RawProfile raw, const LoadOptions& options = {});

/// read_profile_file() and prepare_profile().
LoadedProfile load_profile(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace wheelwear::profiles
