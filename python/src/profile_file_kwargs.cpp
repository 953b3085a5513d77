#include "profile_file_kwargs.hpp"

#include "choices.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace wheelwear::python {

namespace {

void refuse_without_file(bool file, const char* keyword, bool given, const char* what) {
  if (!file && given)
    throw InputError(std::string(keyword) + " applies to " + what +
                     " files only; the standard profile is generated, not read");
}

}  // namespace

cli::ProfileFileArgs profile_file_args(const ProfileFileKwargs& kw, bool wheel_file,
                                       bool rail_file) {
  // The command line's option names, so that an error reads the same from either.
  refuse_without_file(wheel_file, "--origin", kw.origin.has_value(), "wheel");
  refuse_without_file(wheel_file, "--taping-line-distance", kw.taping_line_distance.has_value(),
                      "wheel");
  refuse_without_file(rail_file, "--gauge-side", kw.gauge_side.has_value(), "rail");
  refuse_without_file(wheel_file || rail_file, "--max-drop", kw.max_drop.has_value(), "profile");
  refuse_without_file(wheel_file || rail_file, "--smoothing", kw.smoothing.has_value(),
                      "profile");
  cli::ProfileFileArgs files;
  if (kw.origin) {
    cli::require_choice("--origin", *kw.origin, {"auto", "taping-line", "internal-face"});
    files.origin = *kw.origin;
  }
  files.taping_line_distance = kw.taping_line_distance;
  if (kw.gauge_side) {
    cli::require_choice("--gauge-side", *kw.gauge_side, {"auto", "left", "right"});
    files.gauge_side = *kw.gauge_side;
  }
  if (kw.max_drop) files.max_drop = *kw.max_drop;
  if (kw.smoothing) {
    if (!(*kw.smoothing >= 0.0 && *kw.smoothing <= profiles::kMaxSmoothingLength))
      throw InputError("--smoothing = " + core::format_number(*kw.smoothing) +
                       ": the smoothing length of a profile file's fit must lie in 0 ... 0.005 m "
                       "(2 mm fits a record wavy on the scale of a millimetre)");
    files.smoothing = *kw.smoothing;
  }
  return files;
}

}  // namespace wheelwear::python
