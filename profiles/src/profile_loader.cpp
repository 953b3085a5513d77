#include "wheelwear/profiles/profile_loader.hpp"

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_io.hpp"

namespace wheelwear::profiles {

LoadedProfile prepare_profile(RawProfile raw, const LoadOptions& options) {
  const std::optional<Body> body = options.read.body ? options.read.body : raw.body;
  if (!body)
    throw InputError(raw.source +
                     ": cannot tell whether this is a wheel or a rail profile; set the body");
  const std::size_t read = raw.points.size();
  validate_points(raw, options.validation);
  OrientationReport orientation = orient(raw, *body, options.orientation);
  validate_order(raw, *body, options.validation);
  CleaningReport cleaning = clean(raw, *body, options.cleaning);
  validate_geometry(raw, options.validation);
  ProfileInfo info;
  info.name =
      options.name.empty() ? std::filesystem::path(raw.source).filename().string() : options.name;
  info.body = *body;
  info.side = options.side.value_or(raw.side.value_or(Side::right));
  info.nominal_radius = options.nominal_radius;
  Profile profile(raw.points, info, options.curve);
  return LoadedProfile{std::move(profile), std::move(raw), read, std::move(orientation),
                       std::move(cleaning)};
}

LoadedProfile load_profile(const std::filesystem::path& path, const LoadOptions& options) {
  return prepare_profile(read_profile_file(path, options.read), options);
}

}  // namespace wheelwear::profiles
