// `wheelwear profile`: generate or read a wheel/rail profile, clean it, resample it, summarise it.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "json_writer.hpp"
#include "output_path.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/internal_face.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::cli {

namespace {

namespace pr = wheelwear::profiles;

struct ProfileArgs {
  std::string wheel, rail, out, side = "right", unit = "auto", inclination = "1:40";
  std::string gauge_side = "auto";
  std::string origin{pr::to_string(pr::LoadOptions{}.origin)};
  std::optional<double> taping_line_distance;
  bool info = false, json = false, overwrite = false;
  double spacing = 0.5e-3;
  double smoothing = 0.3e-3;
  double max_drop = 0.2;
  double crop_depth = pr::LoadOptions{}.crop_depth;
  pr::S1002Options s1002;
  CLI::Option* flange_height = nullptr;
  CLI::Option* flange_thickness = nullptr;
  CLI::Option* radius = nullptr;
  CLI::Option* inclination_option = nullptr;
  CLI::Option* crop_depth_option = nullptr;
  CLI::Option* gauge_side_option = nullptr;
  CLI::Option* origin_option = nullptr;
  CLI::Option* taping_line_distance_option = nullptr;
};

// Below this estimated inclination a measured rail looks level (1:200).
constexpr double kLevelInclination = 1.0 / 200.0;

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

pr::LoadedProfile make_profile(const ProfileArgs& args) {
  if (args.wheel.empty() == args.rail.empty())
    throw InputError("give exactly one of --wheel (S1002 or a file) and --rail (60E1 or a file)");
  require(std::isfinite(args.spacing) && args.spacing >= 1e-5 && args.spacing <= 5e-3,
          "--spacing [m]", args.spacing, "must be in [1e-5, 5e-3]");
  const pr::Side side = args.side == "left" ? pr::Side::left : pr::Side::right;
  const bool wheel = !args.wheel.empty();
  const std::string& what = wheel ? args.wheel : args.rail;
  const bool standard =
      wheel ? upper(what) == "S1002" : (upper(what) == "60E1" || upper(what) == "UIC60");
  if (!(wheel && standard)) {
    for (const CLI::Option* option : {args.flange_height, args.flange_thickness})
      if (option->count() > 0)
        throw InputError(option->get_name() + " applies to --wheel S1002 only");
  }
  if (!(!wheel && standard) && args.inclination_option->count() > 0)
    throw InputError("--inclination applies to --rail 60E1 only");
  if (!wheel || standard) {
    for (const CLI::Option* option : {args.origin_option, args.taping_line_distance_option})
      if (option->count() > 0)
        throw InputError(option->get_name() + " applies to wheel files only (--wheel FILE)");
  }
  if (wheel || standard) {
    for (const CLI::Option* option : {args.crop_depth_option, args.gauge_side_option})
      if (option->count() > 0)
        throw InputError(option->get_name() + " applies to rail files only (--rail FILE)");
  }

  pr::LoadOptions options;
  options.side = side;
  options.cleaning.max_drop_fraction = args.max_drop;
  options.read.body = wheel ? pr::Body::wheel : pr::Body::rail;
  if (standard) {
    // Generated from the definition: nothing to smooth.
    options.curve.smoothing_length = 0.0;
    pr::RawProfile raw;
    raw.body = options.read.body;
    if (wheel) {
      pr::S1002Options s = args.s1002;
      s.side = side;
      raw.source = "S1002";
      raw.points = pr::s1002_points(s);
      options.nominal_radius = s.nominal_radius;
    } else {
      pr::Rail60E1Options r;
      r.side = side;
      r.inclination = core::parse_inclination(args.inclination, "--inclination");
      raw.source = "60E1";
      raw.points = pr::rail_60e1_points(r);
    }
    options.name = raw.source;
    options.crop_depth = 0.0;  // the definition's own extent
    raw.lines.assign(raw.points.size(), 0);
    return pr::prepare_profile(std::move(raw), options);
  }
  options.crop_depth = args.crop_depth;
  options.crop_always = args.crop_depth_option->count() > 0;
  const auto mirror = pr::gauge_side_mirror(args.gauge_side);
  if (!mirror)
    throw InputError("--gauge-side " + args.gauge_side + ": must be left, right or auto");
  options.orientation.mirror_y = *mirror;
  const auto origin = pr::parse_wheel_origin(args.origin);
  if (!origin)
    throw InputError("--origin " + args.origin + ": must be auto, taping-line or internal-face");
  options.origin = *origin;
  options.taping_line_distance = args.taping_line_distance;
  const auto unit = pr::parse_length_unit(args.unit);
  if (!unit) throw InputError("--unit " + args.unit + ": must be auto, mm or m");
  options.read.unit = *unit;
  options.curve.smoothing_length = args.smoothing;
  if (wheel && args.radius->count() > 0) options.nominal_radius = args.s1002.nominal_radius;
  return pr::load_profile(what, options);
}

// "1:40.6", or "level" below 1:10000.
std::string ratio(double angle) {
  if (std::abs(std::tan(angle)) < 1e-4) return "level";
  char text[48];
  std::snprintf(text, sizeof text, "1:%.1f", 1.0 / std::abs(std::tan(angle)));
  return text;
}

void run_profile(const ProfileArgs& args) {
  refuse_existing(args.out, "--out", args.overwrite);
  const pr::LoadedProfile loaded = make_profile(args);
  const pr::Profile& profile = loaded.profile;
  const pr::PointList points = profile.resample(args.spacing);
  const bool file_rail =
      !args.rail.empty() && upper(args.rail) != "60E1" && upper(args.rail) != "UIC60";
  const bool file_wheel = !args.wheel.empty() && upper(args.wheel) != "S1002";
  std::optional<pr::InclinationEstimate> inclination;
  if (profile.body() == pr::Body::rail) inclination = pr::estimate_inclination(profile);
  std::vector<std::string> warnings = loaded.cleaning.warnings;
  if (file_rail && inclination && std::abs(inclination->angle) < kLevelInclination)
    warnings.push_back(
        loaded.points.source + ": the rail looks level (estimated inclination " +
        (ratio(inclination->angle) == "level" ? std::string("below 1:10000")
                                              : ratio(inclination->angle)) +
        ", less than 1:200). Measured rails usually carry their inclination, but `contact --incl` "
        "defaults to 0 for files: if this profile is in the rail's own upright frame, give "
        "contact --incl the track's rail inclination (0.025 for 1:40)");
  if (!args.out.empty()) {
    pr::CsvWriteOptions csv;
    csv.name = profile.info().name;
    csv.body = profile.body();
    csv.side = profile.side();
    pr::write_csv(args.out, points, csv);
  }
  if (!args.out.empty() && !args.info && !args.json) {
    for (const std::string& warning : warnings)
      std::cerr << "wheelwear: warning: " << warning << '\n';
    return;
  }

  // Curvature extremes at the output points.
  const double step = profile.length() / static_cast<double>(points.size() - 1);
  double k_min = std::numeric_limits<double>::infinity(), k_max = -k_min;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double k = profile.curvature(step * static_cast<double>(i));
    k_min = std::min(k_min, k);
    k_max = std::max(k_max, k);
  }
  std::optional<pr::WheelParameters> parameters;
  if (profile.body() == pr::Body::wheel) parameters = pr::wheel_parameters(profile);
  std::optional<pr::ProfilePoint> gauge;
  const pr::ProfilePoint top =
      profile.body() == pr::Body::rail ? pr::top_of_rail(profile) : pr::ProfilePoint{};
  if (profile.body() == pr::Body::rail) {
    try {
      gauge = pr::gauge_point(profile);
    } catch (const InputError&) {
      // A partial rail profile need not reach 14 mm below its top; then there is no gauge point.
    }
  }
  const auto& cleaning = loaded.cleaning;

  if (args.json) {
    JsonObject steps;
    for (const auto& s : cleaning.steps) steps.add(s.name, static_cast<int>(s.dropped));
    std::vector<std::string> repairs, warning_texts;
    for (const auto& r : cleaning.reading) {
      JsonObject repair;
      repair.add("name", r.name).add("count", static_cast<int>(r.count)).add("message", r.message);
      repairs.push_back(repair.str());
    }
    for (const std::string& w : warnings) warning_texts.push_back("\"" + json_escape(w) + "\"");
    JsonObject out;
    out.add("name", profile.info().name)
        .add("body", std::string(pr::to_string(profile.body())))
        .add("side", std::string(pr::to_string(profile.side())))
        .add("points_read", static_cast<int>(loaded.points_read))
        .add("points_kept", static_cast<int>(cleaning.kept_points))
        .add("points_cropped", static_cast<int>(cleaning.crop.cropped()))
        .add("points_merged", static_cast<int>(cleaning.merged()))
        .add("points_dropped", static_cast<int>(cleaning.discarded()))
        .add_raw("dropped_by_step", steps.str())
        .add_raw("read_repairs", json_array(repairs))
        .add_raw("warnings", json_array(warning_texts))
        .add("kinks", static_cast<int>(cleaning.kinks.size()))
        .add("length", profile.length())
        .add("y_min", profile.y_min())
        .add("y_max", profile.y_max())
        .add("curvature_min", k_min)
        .add("curvature_max", k_max);
    if (file_wheel)
      out.add("origin", std::string(pr::to_string(loaded.origin.origin)))
          .add("origin_shift", loaded.origin.shift)
          .add("origin_reason", loaded.origin.reason);
    if (profile.body() == pr::Body::wheel) {
      const pr::InternalFace face = pr::internal_face(profile);
      out.add("internal_face_y", face.y)
          .add("internal_face", face.how)
          .add("nominal_radius", profile.info().nominal_radius)
          .add("taping_line_distance", profile.info().taping_line_distance);
    }
    if (parameters)
      out.add("Sh", parameters->Sh).add("Sd", parameters->Sd).add("qR", parameters->qR);
    if (profile.body() == pr::Body::rail) {
      out.add("top_y", top.point[0]).add("top_z", top.point[1]);
      if (gauge) out.add("gauge_point_y", gauge->point[0]).add("gauge_point_z", gauge->point[1]);
      if (inclination) out.add("inclination", inclination->angle);
      if (cleaning.crop.cropped() > 0) out.add("crop_depth", cleaning.crop.depth);
      if (cleaning.lip.hidden > 0)
        out.add("lip_shadowed_points", static_cast<int>(cleaning.lip.hidden))
            .add("lip", cleaning.lip.summary());
    }
    std::cout << out.str() << '\n';
    return;
  }
  std::printf("profile    %s (%s, %s side)\n", profile.info().name.c_str(),
              std::string(pr::to_string(profile.body())).c_str(),
              std::string(pr::to_string(profile.side())).c_str());
  std::printf("points     %s; %zu read, %zu merged, %zu dropped\n", cleaning.summary().c_str(),
              loaded.points_read, cleaning.merged(), cleaning.discarded());
  for (const auto& repair : cleaning.reading)  // warnings are printed below
    if (!repair.warning) std::printf("read       %s\n", repair.message.c_str());
  if (cleaning.crop.cropped() > 0) {
    std::printf("crop       %s\n", cleaning.crop.summary().c_str());
    if (!cleaning.crop.reason.empty())
      std::printf("crop       needed: whole, the profile was refused: %s\n",
                  cleaning.crop.reason.c_str());
  }
  if (cleaning.lip.hidden > 0) {
    std::printf("lip        %s\n", cleaning.lip.summary().c_str());
    std::printf("lip        needed: %s\n", cleaning.lip.reason.c_str());
  }
  for (const auto& kink : cleaning.kinks)
    std::printf("kink       line %d at (%.3f, %.3f) mm: turns %.0f deg\n", kink.line,
                kink.point[0] * 1e3, kink.point[1] * 1e3, kink.angle_deg);
  if (file_wheel)
    std::printf("origin     %s: %s\n", std::string(pr::to_string(loaded.origin.origin)).c_str(),
                loaded.origin.reason.c_str());
  std::printf("y range    %.3f ... %.3f mm (arc length %.3f mm)\n", profile.y_min() * 1e3,
              profile.y_max() * 1e3, profile.length() * 1e3);
  if (profile.body() == pr::Body::wheel) {
    std::printf("face       internal face %s\n", pr::internal_face(profile).how.c_str());
    if (profile.info().nominal_radius > 0.0)
      std::printf("radius     %.2f mm nominal rolling radius at the taping line\n",
                  profile.info().nominal_radius * 1e3);
  }
  std::printf("curvature  min %.4g 1/m, max %.4g 1/m (positive = convex)\n", k_min, k_max);
  if (parameters) {
    std::printf("Sh         %.3f mm\n", parameters->Sh * 1e3);
    std::printf("Sd         %.3f mm\n", parameters->Sd * 1e3);
    std::printf("qR         %.3f mm\n", parameters->qR * 1e3);
  }
  if (profile.body() == pr::Body::rail) {
    std::printf("top        (%.3f, %.3f) mm\n", top.point[0] * 1e3, top.point[1] * 1e3);
    if (gauge)
      std::printf("gauge pt   (%.3f, %.3f) mm (14 mm below the top)\n", gauge->point[0] * 1e3,
                  gauge->point[1] * 1e3);
    else
      std::printf("gauge pt   none: the gauge side does not reach 14 mm below the top\n");
    if (inclination)
      std::printf("incl.      %s (%.4f rad%s), estimated from the crown\n",
                  ratio(inclination->angle).c_str(), inclination->angle,
                  ratio(inclination->angle) == "level" ? ""
                  : inclination->angle > 0.0           ? ", gauge side lower"
                                                       : ", field side lower");
  }
  for (const std::string& warning : warnings) std::printf("warning    %s\n", warning.c_str());
  if (!args.out.empty())
    std::printf("written    %s (%zu points, y z in mm)\n", args.out.c_str(), points.size());
}

}  // namespace

void add_profile_command(CLI::App& app) {
  auto args = std::make_shared<ProfileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "profile",
      "Generate or read a wheel or rail profile, clean and validate it, fit it with a smooth\n"
      "curve and write it resampled and/or summarise it.\n"
      "Frame: y lateral, positive towards the field side (flange and gauge face at -y); z\n"
      "vertical, positive downwards. Generated profiles: origin at the taping line (S1002) or\n"
      "the top of rail (60E1). Files keep their origin; their axes are oriented automatically.\n"
      "Wheel files whose origin is the flange back (MiniProf) are moved to the taping line\n"
      "with --origin (auto decides from the profile's extent).\n"
      "Files: plain y z text/CSV (header optional), SIMPACK/CONTACT .prw/.prr, MiniProf\n"
      ".whl/.ban (not .mpt). Bad input gives a message naming file, line and problem, and exit\n"
      "code 2; an existing --out file is replaced only with --overwrite, and then only by a\n"
      "complete new one.\n"
      "A rail file refused whole is cropped to --crop-depth below its top and tried again;\n"
      "--info reports what the reading accepted, the crop, the estimated rail inclination\n"
      "and warnings.\n"
      "Examples:\n"
      "  wheelwear profile --wheel S1002 --info --json\n"
      "  wheelwear profile --rail 60E1 --inclination 1:20 --out rail.csv\n"
      "  wheelwear profile --wheel measured.whl --out wheel.csv --info");
  cmd->add_option("--wheel", args->wheel, "S1002 (EN 13715) or a wheel profile file");
  cmd->add_option("--rail", args->rail, "60E1 (UIC60 head, EN 15302 arcs) or a rail profile file");
  cmd->add_option("--out", args->out,
                  "write the cleaned, resampled profile as CSV: header y_mm,z_mm, values in mm");
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing --out file");
  cmd->add_flag("--info", args->info,
                "print a summary: points kept/dropped, y range, curvature extremes, and Sh, Sd,\n"
                "qR (EN 15313) for wheels (the default when --out is not given)");
  cmd->add_flag("--json", args->json,
                "print the summary as one JSON object, SI units (m, 1/m); wheels have Sh, Sd, qR");
  cmd->add_option("--side", args->side, "side of the track: left or right")
      ->check(CLI::IsMember({"left", "right"}))
      ->capture_default_str();
  cmd->add_option("--spacing", args->spacing, "arc-length spacing of the output points [m]")
      ->capture_default_str();
  cmd->add_option("--smoothing", args->smoothing,
                  "files: smoothing length [m], 0 ... 0.005; wavelengths of 2*pi times it are\n"
                  "halved, 0 interpolates (generated profiles are never smoothed)")
      ->check(CLI::Range(0.0, profiles::kMaxSmoothingLength))
      ->capture_default_str();
  cmd->add_option("--unit", args->unit,
                  "plain-text files: auto (from the header or the magnitudes), mm or m")
      ->check(CLI::IsMember({"auto", "mm", "m"}))
      ->capture_default_str();
  cmd->add_option("--max-drop", args->max_drop,
                  "fail if the cleaning drops more than this fraction of the points (merged\n"
                  "near-duplicates do not count)")
      ->capture_default_str();
  args->crop_depth_option =
      cmd->add_option("--crop-depth", args->crop_depth,
                      "rail files: depth below the top of rail [m] to crop the ends to. By\n"
                      "default only a rail refused whole (a gauge face receding below 25 mm) is\n"
                      "cropped; given, every rail is. 0 never crops, else 0.014 ... 0.2")
          ->capture_default_str();
  args->gauge_side_option =
      cmd->add_option("--gauge-side", args->gauge_side,
                      "rail files: where the file has the gauge face on its lateral axis as\n"
                      "written: left = smaller values, right = larger (MiniProf rails: right),\n"
                      "auto = the end measured deeper; set it when auto mirrors a rail")
          ->check(CLI::IsMember({"auto", "left", "right"}))
          ->capture_default_str();
  args->origin_option =
      cmd->add_option("--origin", args->origin,
                      "wheel files: the file's lateral origin. taping-line keeps it;\n"
                      "internal-face (the flange back, as MiniProf writes wheels) moves the\n"
                      "wheel by --taping-line-distance; auto takes the taping line if the\n"
                      "profile reaches 60 mm or more on the flange side of y = 0, the internal\n"
                      "face if its flange-side end lies within 5 mm of y = 0, else refuses")
          ->check(CLI::IsMember({"auto", "taping-line", "internal-face"}))
          ->capture_default_str();
  args->taping_line_distance_option =
      cmd->add_option("--taping-line-distance", args->taping_line_distance,
                      "wheel files: taping line distance from the internal face [m] for\n"
                      "--origin internal-face/auto, 0.03 ... 0.11; default the file header's\n"
                      "where it states one, else 0.070 (EN 13715)");
  args->flange_height =
      cmd->add_option("--flange-height", args->s1002.flange_height,
                      "S1002 flange height Sh [m], 0.028 ... 0.032 (EN 13715 h28 ... h32)")
          ->capture_default_str();
  args->flange_thickness =
      cmd->add_option("--flange-thickness", args->s1002.flange_thickness,
                      "S1002 flange thickness Sd [m], 0.028 ... 0.0325 (EN 13715 e28 ... e32.5)")
          ->capture_default_str();
  args->radius = cmd->add_option("--radius", args->s1002.nominal_radius,
                                 "wheels: nominal rolling radius at the taping line [m] (recorded)")
                     ->capture_default_str();
  args->inclination_option = cmd->add_option("--inclination", args->inclination,
                                             "60E1 rail inclination: 1:N or a slope tan(theta) "
                                             "(1:40 = 0.025), none")
                                 ->capture_default_str();
  cmd->callback([args] {
    ProfileArgs run = *args;
    if (run.out.empty()) run.info = true;
    run_profile(run);
  });
}

}  // namespace wheelwear::cli
