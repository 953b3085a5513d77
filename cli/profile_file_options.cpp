#include "profile_file_options.hpp"

#include <CLI/CLI.hpp>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::cli {

profiles::ProfileFileOptions ProfileFileArgs::options() const {
  profiles::ProfileFileOptions out;
  const auto parsed = profiles::parse_wheel_origin(origin);
  if (!parsed)
    throw InputError("--origin " + origin + ": must be auto, taping-line or internal-face");
  out.origin = *parsed;
  out.taping_line_distance = taping_line_distance;
  out.max_drop_fraction = max_drop;
  out.smoothing_length = smoothing;
  const auto mirror = profiles::gauge_side_mirror(gauge_side);
  if (!mirror) throw InputError("--gauge-side " + gauge_side + ": must be auto, left or right");
  out.rail_gauge_side = *mirror;
  return out;
}

void ProfileFileArgs::refuse_for_standard(bool standard_wheel, bool standard_rail) const {
  const auto refuse = [](const CLI::Option* option, const char* what) {
    if (option && option->count() > 0)
      throw InputError(option->get_name() + " applies to " + what +
                       " files only; the standard profile is generated, not read");
  };
  if (standard_wheel) {
    refuse(origin_option, "wheel");
    refuse(taping_line_distance_option, "wheel");
  }
  if (standard_rail) refuse(gauge_side_option, "rail");
  if (standard_wheel && standard_rail) {
    refuse(max_drop_option, "profile");
    refuse(smoothing_option, "profile");
  }
}

void add_profile_file_options(CLI::App* cmd, ProfileFileArgs& args) {
  args.origin_option =
      cmd->add_option("--origin", args.origin,
                      "wheel files: the file's lateral origin. auto takes the taping line if\n"
                      "the profile reaches 60 mm or more on the flange side of y = 0, the\n"
                      "internal face (flange back, as MiniProf writes wheels) if its flange-side\n"
                      "end lies within 5 mm of y = 0, and refuses anything else; taping-line or\n"
                      "internal-face say which (the latter moves the wheel by the taping line\n"
                      "distance)")
          ->check(CLI::IsMember({"auto", "taping-line", "internal-face"}))
          ->capture_default_str();
  args.taping_line_distance_option = cmd->add_option(
      "--taping-line-distance", args.taping_line_distance,
      "wheel files: taping line distance from the internal face [m], 0.03 ... 0.11;\n"
      "default the file header's where it states one, else 0.070 (EN 13715)");
  args.max_drop_option =
      cmd->add_option("--max-drop", args.max_drop,
                      "profile files: largest share of points the cleaning may discard (0 ... 1);\n"
                      "merged near-duplicate points do not count")
          ->check(CLI::Range(0.0, 1.0))
          ->capture_default_str();
  args.gauge_side_option =
      cmd->add_option("--gauge-side", args.gauge_side,
                      "rail files: where the file has the gauge face on its lateral axis as\n"
                      "written: left = smaller values, right = larger (MiniProf rails: right),\n"
                      "auto = the end measured deeper; set it when auto mirrors a rail")
          ->check(CLI::IsMember({"auto", "left", "right"}))
          ->capture_default_str();
  args.smoothing_option =
      cmd->add_option(
             "--smoothing", args.smoothing,
             "profile files: smoothing length of the fit [m], 0 ... 0.005; wavelengths of\n"
             "2 pi times it are halved. Longer for a record wavy on the scale of a\n"
             "millimetre (its slope swings along the flank), 0 to pass through the points")
          ->check(CLI::Range(0.0, profiles::kMaxSmoothingLength))
          ->capture_default_str();
}

}  // namespace wheelwear::cli
