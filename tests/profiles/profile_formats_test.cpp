// Every supported format with its own axes and origin (docs/profiles.md): S1002 and 60E1 written
// here in each, by hand and not with the library's writers, load to the same profile as the
// generated one. And a file that says it is a wheel is not taken for a rail, nor the reverse.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/miniprof_format.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::profiles {
namespace {

// Written values carry 12 significant digits: values below 150 mm are rounded by at most
// 5e-10 mm = 5e-13 m, so the points read back lie within 1e-12 m of those written.
constexpr double kPointTolerance = 1e-12;
// The fit is linear in the points with a gain of order one (smoothing averages, interpolation
// reproduces), so fitted positions agree to well within 1e-9 m: 2000 times the rounding.
constexpr double kFitTolerance = 1e-9;

// A value [m] as a file writes it: 12 significant digits, in mm (or in m when `metres`).
std::string num(double metres, bool in_metres = false) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", in_metres ? metres : metres * 1e3);
  return text;
}

struct WrittenFile {
  std::string name;     // file name; its extension picks the reader
  std::string content;  // the whole file
};

// S1002 (profile frame: taping line at y = 0, z down) in every wheel format.
std::vector<WrittenFile> wheel_files(const PointList& p) {
  std::vector<WrittenFile> files;
  std::string csv = "# S1002, taping line at y = 0\ny_mm,z_mm\n", txt, dat;
  for (const Point& q : p) {
    csv += num(q[0]) + "," + num(q[1]) + "\n";
    txt += num(q[0]) + "\t" + num(q[1]) + "\n";             // no header: unit from magnitudes
    dat += num(q[0], true) + " " + num(q[1], true) + "\n";  // metres
  }
  files.push_back({"s1002.csv", csv});
  files.push_back({"s1002.txt", txt});
  files.push_back({"s1002.dat", dat});

  const std::string simpack_head =
      "header.begin\n  version = 1\n  type = 1\nheader.end\nspline.begin\n  units.len.f = 1000\n";
  std::string prw = simpack_head + "  point.begin\n";
  for (const Point& q : p) prw += "    " + num(q[0]) + "  " + num(q[1]) + "\n";
  files.push_back({"s1002.prw", prw + "  point.end\nspline.end\n"});
  // y towards the flange back, put right by mirror.y as in CONTACT's MBench_S1002_v3.prw, and the
  // rows from the field side, reversed by inversion.
  std::string mirrored = simpack_head + "  mirror.y = 1\n  inversion = 1\n  point.begin\n";
  for (auto q = p.rbegin(); q != p.rend(); ++q)
    mirrored += "    " + num(-(*q)[0]) + "  " + num((*q)[1]) + "\n";
  files.push_back({"s1002_mirrored.prw", mirrored + "  point.end\nspline.end\n"});

  // MiniProf: X from the internal face (70 mm from the taping line), Y towards the flange tip.
  std::string old_layout =
      "#MINIWHEELPROF\ns1002.whl\nMINIPROF 2020\nStock.......: S1002\n\" 32.5 28 10.8\n"
      "(Sd/Sh/qR)\n\n";
  for (const Point& q : p) old_layout += num(q[0] + 0.070) + " " + num(q[1]) + "\n";
  files.push_back({"s1002.whl", old_layout});
  // The key=value layout of MiniProf for Windows, rows from the field side.
  std::string windows =
      "ProgramName=MiniProf for Windows\nColumnDef=X,Y\nXYPoints=" + std::to_string(p.size()) +
      "\n\n";
  for (auto q = p.rbegin(); q != p.rend(); ++q)
    windows += num((*q)[0] + 0.070) + " " + num((*q)[1]) + "\n";
  files.push_back({"s1002_windows.whl", windows});
  return files;
}

// 60E1 at 1:40 (profile frame: top of rail at the origin, gauge face at -y, z down) in every
// rail format.
std::vector<WrittenFile> rail_files(const PointList& p) {
  std::vector<WrittenFile> files;
  std::string csv = "y_mm,z_mm\n";
  for (const Point& q : p) csv += num(q[0]) + "," + num(q[1]) + "\n";
  files.push_back({"60e1.csv", csv});
  std::string prr =
      "header.begin\n  type = 0\nheader.end\nspline.begin\n  units.len.f = 1000\n  point.begin\n";
  for (const Point& q : p) prr += "    " + num(q[0]) + "  " + num(q[1]) + "\n";
  files.push_back({"60e1.prr", prr + "  point.end\nspline.end\n"});
  // MiniProf: X towards the gauge face, Y up, rows from the field side (as avg_HR.BAN).
  std::string ban =
      "Filename=60e1.ban\nXYPoints=" + std::to_string(p.size()) + "\nColumnDef=X,Y\n\n";
  for (auto q = p.rbegin(); q != p.rend(); ++q) ban += num(-(*q)[0]) + " " + num(-(*q)[1]) + "\n";
  files.push_back({"60e1.ban", ban});
  return files;
}

// Positions at equal arc length, every 0.1 mm; returns how many were compared.
std::size_t expect_same_curve(const Profile& a, const Profile& b, const std::string& what) {
  EXPECT_NEAR(a.length(), b.length(), kFitTolerance) << what;
  std::size_t compared = 0;
  for (double s = 0.0; s <= a.length(); s += 0.1e-3, ++compared)
    EXPECT_NEAR((a.position(s) - b.position(s)).norm(), 0.0, kFitTolerance) << what << " s = " << s;
  return compared;
}

// The loaded (oriented, cleaned, moved) points against those written; returns the count.
std::size_t expect_same_points(const PointList& loaded, const PointList& written,
                               const std::string& what) {
  EXPECT_EQ(loaded.size(), written.size()) << what;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < std::min(loaded.size(), written.size()); ++i, ++compared)
    EXPECT_NEAR((loaded[i] - written[i]).norm(), 0.0, kPointTolerance) << what << " point " << i;
  return compared;
}

using testing::refusal;

TEST(ProfileFormats, S1002LoadsIdenticallyFromEveryWheelFormat) {
  const auto dir = testing::scratch_dir();
  LoadOptions options;
  options.read.body = Body::wheel;
  options.origin = WheelOrigin::automatic;  // each file's origin by the rule
  const PointList points = s1002_points();
  const Profile reference = s1002({}, options.curve);  // the same points, fitted alike
  const WheelParameters nominal = wheel_parameters(reference);
  std::size_t point_checks = 0, curve_checks = 0, parameter_checks = 0;
  std::vector<LoadedProfile> loaded;
  for (const WrittenFile& file : wheel_files(points)) {
    testing::write_text(dir / file.name, file.content);
    loaded.push_back(load_profile(dir / file.name, options));
    const LoadedProfile& wheel = loaded.back();
    const bool miniprof = file.name.ends_with(".whl");
    EXPECT_EQ(wheel.origin.origin, miniprof ? WheelOrigin::internal_face : WheelOrigin::taping_line)
        << file.name;
    EXPECT_TRUE(wheel.cleaning.warnings.empty()) << file.name;
    EXPECT_EQ(wheel.cleaning.dropped(), 0u) << file.name;
    point_checks += expect_same_points(wheel.points.points, points, file.name);
    curve_checks += expect_same_curve(wheel.profile, reference, file.name);
    curve_checks += expect_same_curve(wheel.profile, loaded.front().profile, file.name);
    const WheelParameters en15313 = wheel_parameters(wheel.profile);
    EXPECT_NEAR(en15313.Sh, nominal.Sh, kFitTolerance) << file.name;
    EXPECT_NEAR(en15313.Sd, nominal.Sd, kFitTolerance) << file.name;
    EXPECT_NEAR(en15313.qR, nominal.qR, kFitTolerance) << file.name;
    EXPECT_NEAR(en15313.running_circle[0], 0.0, kFitTolerance) << file.name;
    parameter_checks += 4;
  }
  // And the shared result is S1002 h28 e32.5 (EN 13715) with its taping line at y = 0. The fit
  // smooths over 0.3 mm (LoadOptions::curve), which moves the flange face by well under 1 um:
  // 2e-6 m on Sh and Sd stays 10 times below the 0.02 mm resolution of EN 15313 gauges.
  EXPECT_NEAR(nominal.Sh, 0.028, 2e-6);
  EXPECT_NEAR(nominal.Sd, 0.0325, 2e-6);
  EXPECT_EQ(loaded.size(), 7u);
  EXPECT_EQ(point_checks, 7 * points.size());
  EXPECT_GT(curve_checks, 7u * 2u * 1600u);
  EXPECT_EQ(parameter_checks, 7u * 4u);
  std::printf(
      "wheel formats: %zu files, %zu point, %zu curve, %zu EN 15313 comparisons; Sh %.5f "
      "Sd %.5f qR %.5f mm\n",
      loaded.size(), point_checks, curve_checks, parameter_checks, nominal.Sh * 1e3,
      nominal.Sd * 1e3, nominal.qR * 1e3);
}

TEST(ProfileFormats, S1002FromEveryWheelFormatFollowsTheStandardsCurve) {
  // Independent of the generator: the EN 13715 sections (s1002_nominal_z) on the tread and flange,
  // loaded with interpolation so that only the representation's error remains, measured along
  // the normal (the height difference times the cosine of the nominal slope, which the 70 deg
  // flange face would otherwise triple): below 1e-7 m, twice the 5e-8 m that curve.hpp gives for
  // a curvature jump of 1/13 mm, the largest of S1002 (its flange root, y = -38.4 mm).
  const auto dir = testing::scratch_dir();
  LoadOptions options;
  options.read.body = Body::wheel;
  options.origin = WheelOrigin::automatic;
  options.curve.smoothing_length = 0.0;
  std::size_t compared = 0;
  double largest = 0.0;
  for (const WrittenFile& file : wheel_files(s1002_points())) {
    testing::write_text(dir / file.name, file.content);
    const Profile wheel = load_profile(dir / file.name, options).profile;
    for (int k = 0; k <= 259; ++k, ++compared) {
      const double y = std::min(-0.0695 + 0.5e-3 * k, 0.060), h = 1e-6;
      const double slope = (s1002_nominal_z(std::min(y + h, 0.060)) - s1002_nominal_z(y - h)) /
                           (std::min(y + h, 0.060) - (y - h));
      const double normal = (*wheel.z_at(y) - s1002_nominal_z(y)) / std::hypot(1.0, slope);
      ASSERT_NEAR(normal, 0.0, 1e-7) << file.name << " y = " << y;
      largest = std::max(largest, std::abs(normal));
    }
  }
  EXPECT_EQ(compared, 7u * 260u);
  std::printf(
      "S1002 from 7 formats against EN 13715: %zu heights, largest normal distance %.2g m\n",
      compared, largest);
}

TEST(ProfileFormats, Rail60E1LoadsIdenticallyFromEveryRailFormat) {
  const auto dir = testing::scratch_dir();
  LoadOptions options;
  options.read.body = Body::rail;
  const PointList points = rail_60e1_points();
  const Profile reference = rail_60e1({}, options.curve);
  const ProfilePoint gauge = gauge_point(reference), top = top_of_rail(reference);
  std::size_t point_checks = 0, curve_checks = 0, datum_checks = 0;
  for (const WrittenFile& file : rail_files(points)) {
    testing::write_text(dir / file.name, file.content);
    const LoadedProfile rail = load_profile(dir / file.name, options);
    EXPECT_TRUE(rail.cleaning.warnings.empty()) << file.name;
    EXPECT_EQ(rail.cleaning.crop.cropped(), 0u) << file.name;
    EXPECT_EQ(rail.orientation.mirrored_y, file.name.ends_with(".ban")) << file.name;
    EXPECT_EQ(rail.orientation.mirrored_z, file.name.ends_with(".ban")) << file.name;
    point_checks += expect_same_points(rail.points.points, points, file.name);
    curve_checks += expect_same_curve(rail.profile, reference, file.name);
    // Where `contact` puts the rail: its gauge point and top, the same as the reference's.
    EXPECT_NEAR((gauge_point(rail.profile).point - gauge.point).norm(), 0.0, kFitTolerance);
    EXPECT_NEAR((top_of_rail(rail.profile).point - top.point).norm(), 0.0, kFitTolerance);
    datum_checks += 2;
  }
  // The shared result has its top at the origin (rail_60e1_points), to the fit's smoothing.
  EXPECT_NEAR(top.point.norm(), 0.0, 1e-6);
  EXPECT_EQ(point_checks, 3 * points.size());
  EXPECT_GT(curve_checks, 3u * 800u);
  EXPECT_EQ(datum_checks, 6u);
  std::printf("rail formats: %zu point, %zu curve, %zu datum comparisons\n", point_checks,
              curve_checks, datum_checks);
}

// A file that says it is a wheel is refused as a rail, and the reverse, naming the file, what it
// says it is and what to give; files that say nothing take the body they are given.
TEST(ProfileFormats, AMiniProfWheelIsNotTakenForARail) {
  const auto old_layout = testing::data_path("profiles/s1002_flange_back.whl");
  LoadOptions rail;
  rail.read.body = Body::rail;
  EXPECT_EQ(refusal([&] { load_profile(old_layout, rail); }),
            old_layout.string() +
                ":1: the file says it is a wheel profile (#MINIWHEELPROF: a MiniProf wheel "
                "export), but a rail profile is expected here; give a rail profile file "
                "(MiniProf exports rails as .ban files)");
  // A key=value export says it only by its name.
  const auto windows = testing::data_path("profiles/s1002_miniprof_windows.whl");
  EXPECT_EQ(refusal([&] { load_profile(windows, rail); }),
            windows.string() +
                ": the file says it is a wheel profile (extension .whl: a MiniProf wheel export), "
                "but a rail profile is expected here; give a rail profile file (MiniProf exports "
                "rails as .ban files), or rename this file to .ban if it does hold a rail");
  // "#MINIWHEELPROF" wins over another name, as before.
  const auto dir = testing::scratch_dir();
  testing::write_text(dir / "wheel.ban", testing::read_text(old_layout));
  EXPECT_EQ(read_profile_file(dir / "wheel.ban").body, Body::wheel);
  EXPECT_NE(refusal([&] {
              read_profile_file(dir / "wheel.ban", rail.read);
            }).find("wheel.ban:1: the file says it is a wheel profile (#MINIWHEELPROF"),
            std::string::npos);
  // As a wheel, said or not, it loads.
  LoadOptions wheel;
  wheel.read.body = Body::wheel;
  EXPECT_EQ(load_profile(old_layout, wheel).profile.body(), Body::wheel);
  EXPECT_EQ(load_profile(windows).profile.body(), Body::wheel);
}

TEST(ProfileFormats, AMiniProfRailIsNotTakenForAWheel) {
  const auto ban = testing::data_path("profiles/rail_base.ban");
  ReadOptions wheel;
  wheel.body = Body::wheel;
  EXPECT_EQ(refusal([&] { read_profile_file(ban, wheel); }),
            ban.string() +
                ": the file says it is a rail profile (extension .ban: a MiniProf rail export), "
                "but a wheel profile is expected here; give a wheel profile file (MiniProf exports "
                "wheels as .whl files), or rename this file to .whl if it does hold a wheel");
  // The measured rail too (extension in capitals).
  EXPECT_NE(refusal([&] {
              read_profile_file(testing::measured_rail_file(), wheel);
            }).find("avg_HR.BAN: the file says it is a rail profile (extension .ban"),
            std::string::npos);
  ReadOptions rail;
  rail.body = Body::rail;
  EXPECT_EQ(read_profile_file(ban, rail).body, Body::rail);
}

TEST(ProfileFormats, WheelwearsMiniProfRailKeepsItsBodyUnderAWheelsName) {
  // format_miniprof writes "# body: rail": that line, not the .whl name, says what it is.
  const auto dir = testing::scratch_dir();
  write_profile_file(dir / "rail.whl", rail_60e1_points({.point_spacing = 1e-3}), Body::rail);
  const RawProfile raw = read_profile_file(dir / "rail.whl");
  EXPECT_EQ(raw.body, Body::rail);
  EXPECT_EQ(raw.body_line, 5);
  ReadOptions wheel;
  wheel.body = Body::wheel;
  EXPECT_EQ(refusal([&] { read_profile_file(dir / "rail.whl", wheel); }),
            (dir / "rail.whl").string() +
                ":5: the file says it is a rail profile, but a wheel profile is expected here; "
                "give a wheel profile file (MiniProf exports wheels as .whl files)");
  // Two lines that disagree are refused.
  EXPECT_EQ(refusal([] { parse_miniprof("#MINIWHEELPROF\n# body: rail\n\n1 2\n3 4\n", "x", ""); }),
            "x:2: the file says it is a rail profile, but line 1 says wheel");
}

TEST(ProfileFormats, FilesThatStateNoBodyTakeTheOneGiven) {
  // Columns carry no body (unless wheelwear's "# body:"), nor does MiniProf content under another
  // name, nor a Simpack file without "type".
  const std::vector<std::pair<std::string, std::string>> files = {
      {"points.csv", "y_mm,z_mm\n-10,1\n0,0\n10,1\n20,3\n"},
      {"points.txt", "XYPoints=4\nColumnDef=X,Y\n\n-10 1\n0 0\n10 1\n20 3\n"},
      {"points.prw",
       "spline.begin\n point.begin\n -10 1\n 0 0\n 10 1\n 20 3\n point.end\n"
       "spline.end\n"},
  };
  std::size_t compared = 0;
  for (const auto& [name, content] : files) {
    for (const Body body : {Body::wheel, Body::rail}) {
      ReadOptions options;
      options.body = body;
      const RawProfile raw =
          parse_profile_text(content, name, detect_format(name, content), options);
      EXPECT_EQ(raw.body, body) << name;
      EXPECT_EQ(raw.body_line, 0) << name;
      EXPECT_TRUE(raw.body_evidence.empty()) << name;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 6u);
}

}  // namespace
}  // namespace wheelwear::profiles
