// The lateral origin of wheel files (LoadOptions::origin): MiniProf puts y = 0 at the flange back,
// the profile frame at the taping line. The reference is the file's own numbers, read here
// independently, and the same S1002 written with either origin.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/internal_face.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::profiles {
namespace {

std::filesystem::path wheel_file(const std::string& name) {
  return testing::data_path("profiles/" + name);
}

LoadedProfile load(const std::string& name, WheelOrigin origin, double distance = 0.070) {
  LoadOptions options;
  options.origin = origin;
  options.taping_line_distance = distance;
  return load_profile(wheel_file(name), options);
}

// The point rows of a MiniProf wheel file [m]: everything after the first empty line.
PointList file_points(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
  }
  PointList out;
  double x = 0.0, y = 0.0;
  while (in >> x >> y) out.emplace_back(x * 1e-3, y * 1e-3);
  return out;
}

using testing::refusal;

TEST(WheelOrigin, BothOriginsLoadToTheSameProfile) {
  const LoadedProfile back = load("s1002_flange_back.whl", WheelOrigin::automatic);
  const LoadedProfile tape = load("s1002_taping_line.whl", WheelOrigin::automatic);
  EXPECT_EQ(back.origin.origin, WheelOrigin::internal_face);
  EXPECT_EQ(back.origin.shift, -0.070);
  EXPECT_EQ(tape.origin.origin, WheelOrigin::taping_line);
  EXPECT_EQ(tape.origin.shift, 0.0);
  EXPECT_TRUE(back.cleaning.warnings.empty());
  EXPECT_TRUE(tape.cleaning.warnings.empty());
  ASSERT_EQ(back.points.points.size(), tape.points.points.size());
  std::size_t points = 0, fit = 0;
  for (std::size_t i = 0; i < back.points.points.size(); ++i, ++points)
    ASSERT_NEAR((back.points.points[i] - tape.points.points[i]).norm(), 0.0, 1e-9) << i;
  EXPECT_NEAR(back.profile.length(), tape.profile.length(), 1e-9);
  for (double s = 0.0; s <= back.profile.length(); s += 0.1e-3, ++fit)
    ASSERT_NEAR((back.profile.position(s) - tape.profile.position(s)).norm(), 0.0, 1e-9) << s;
  const WheelParameters a = wheel_parameters(back.profile);
  const WheelParameters b = wheel_parameters(tape.profile);
  EXPECT_NEAR(a.Sh, b.Sh, 1e-9);
  EXPECT_NEAR(a.Sd, b.Sd, 1e-9);
  EXPECT_NEAR(a.qR, b.qR, 1e-9);
  // Both are the nominal S1002 (h28, e32.5) with the taping line at y = 0.
  EXPECT_NEAR(a.Sh, 0.028, 0.02e-3);
  EXPECT_NEAR(a.Sd, 0.0325, 0.02e-3);
  EXPECT_NEAR(a.running_circle[0], 0.0, 0.01e-3);
  EXPECT_NEAR(*back.profile.z_at(0.0), 0.0, 1e-6);
  EXPECT_GT(points, 300u);
  EXPECT_GT(fit, 1500u);
  std::printf("compared %zu points, %zu fit positions, Sh Sd qR %.4f %.4f %.4f mm\n", points, fit,
              a.Sh * 1e3, a.Sd * 1e3, a.qR * 1e3);
}

TEST(WheelOrigin, InternalFaceMovesTheFilePointsByTheTapingLineDistance) {
  // Reference: the file's numbers read here, minus the distance.
  std::size_t compared = 0;
  for (const double distance : {0.070, 0.0725}) {
    const LoadedProfile back = load("s1002_flange_back.whl", WheelOrigin::automatic, distance);
    const PointList file = file_points(wheel_file("s1002_flange_back.whl"));
    ASSERT_EQ(back.points.points.size(), file.size());
    EXPECT_EQ(back.origin.shift, -distance);
    for (std::size_t i = 0; i < file.size(); ++i, ++compared) {
      ASSERT_NEAR(back.points.points[i][0], file[i][0] - distance, 1e-15) << i;
      ASSERT_EQ(back.points.points[i][1], file[i][1]) << i;
    }
  }
  EXPECT_EQ(compared, 2 * 327u);
}

TEST(WheelOrigin, AFileStartingOnTheBackRoundingIsTakenFromTheFlangeBack) {
  const LoadedProfile wheel = load("s1002_back_rounding.whl", WheelOrigin::automatic);
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::internal_face);
  EXPECT_NE(wheel.origin.reason.find("y = 0.600 mm"), std::string::npos) << wheel.origin.reason;
  // The same S1002 as the whole file, from the rounding on: compare with it on the common part.
  const LoadedProfile whole = load("s1002_taping_line.whl", WheelOrigin::taping_line);
  std::size_t compared = 0;
  for (int k = 0; k <= 240; ++k, ++compared) {
    const double y = -0.065 + 0.5e-3 * k;
    ASSERT_NEAR(*wheel.profile.z_at(y), *whole.profile.z_at(y), 1e-6) << y;
  }
  EXPECT_EQ(compared, 241u);
  // Its first point, on the rounding 0.6 mm from the flange back, lands 69.4 mm from the taping
  // line.
  EXPECT_NEAR(wheel.points.points.front()[0], 0.599997760e-3 - 0.070, 1e-15);
  // No steep back face: the internal face follows from the origin convention, 70 mm from the
  // taping line, not from the first point (which would put Sd 0.6 mm low). Reference: S1002's
  // nominal Sd 32.5 mm, to the 0.02 mm of the generated profile's own check above.
  const InternalFace face = internal_face(wheel.profile);
  EXPECT_FALSE(face.measured);
  EXPECT_EQ(face.y, -0.070);
  EXPECT_NEAR(wheel_parameters(wheel.profile).Sd, 0.0325, 0.02e-3);
}

// S1002 with a measured-like back face: a vertical face from the back arc's vertical tangent
// 20 mm up towards the axle, with 0.02 mm of alternating noise (MiniProf's order), written with
// X = 0 at the face and the first points on a 1 mm rounding that flares 0.8 mm outwards at its
// top. The steep points give the face; the most outward point would not.
TEST(WheelOrigin, TheInternalFaceIsTakenFromTheSteepBackFacePoints) {
  const PointList s1002 = s1002_points({.point_spacing = 0.2e-3});
  RawProfile raw;
  raw.source = "measured_back_face.whl";
  raw.body = Body::wheel;
  const double z_face_end = s1002.front()[1];  // the back arc's vertical tangent
  for (int k = 0; k <= 4; ++k) {               // the flaring rounding at the top
    const double t = 0.25 * k;
    raw.points.emplace_back(-0.8e-3 * (1.0 - t) * (1.0 - t), z_face_end - 21e-3 + 1e-3 * t);
  }
  for (int k = 1; k < 100; ++k)
    raw.points.emplace_back((k % 2 ? 0.02e-3 : -0.02e-3), z_face_end - 20e-3 + 0.2e-3 * k);
  for (const Point& p : s1002) raw.points.emplace_back(p[0] + 0.070, p[1]);
  raw.lines.assign(raw.points.size(), 0);
  LoadOptions options;  // automatic origin: within 5 mm of X = 0, the internal face
  const LoadedProfile wheel = prepare_profile(raw, options);
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::internal_face);
  const InternalFace face = internal_face(wheel.profile);
  EXPECT_TRUE(face.measured) << face.how;
  // The median of the noisy face: within the smoothing's residue of the noise (0.02 mm).
  EXPECT_NEAR(face.y, -0.070, 0.02e-3) << face.how;
  EXPECT_NEAR(wheel.profile.y_min(), -0.0708, 0.05e-3);  // the flare the old rule took
  const WheelParameters p = wheel_parameters(wheel.profile);
  EXPECT_NEAR(p.Sd, 0.0325, 0.03e-3);  // S1002's nominal Sd; the face's noise and the fit's
  EXPECT_NEAR(p.Sh, 0.028, 0.02e-3);
}

TEST(WheelOrigin, AnExplicitWrongOriginMovesAsSetAndWarns) {
  const LoadedProfile tape = load("s1002_taping_line.whl", WheelOrigin::internal_face);
  EXPECT_NEAR(tape.profile.y_min(), -0.140, 2e-6);
  ASSERT_EQ(tape.cleaning.warnings.size(), 1u);
  EXPECT_NE(tape.cleaning.warnings[0].find("--origin auto or taping-line"), std::string::npos)
      << tape.cleaning.warnings[0];
  const LoadedProfile back = load("s1002_flange_back.whl", WheelOrigin::taping_line);
  EXPECT_NEAR(back.profile.y_min(), 0.0, 2e-6);
  ASSERT_EQ(back.cleaning.warnings.size(), 1u);
  EXPECT_NE(back.cleaning.warnings[0].find("--origin auto or internal-face"), std::string::npos)
      << back.cleaning.warnings[0];
}

TEST(WheelOrigin, APartialWheelIsRefusedNamingBothReadings) {
  RawProfile raw;
  raw.source = "partial.whl";
  raw.body = Body::wheel;
  for (const Point& p : s1002_points({.point_spacing = 0.5e-3}))
    if (p[0] > -0.030) raw.points.push_back(p);
  raw.lines.assign(raw.points.size(), 0);
  LoadOptions options;
  options.origin = WheelOrigin::automatic;
  const std::string message = refusal([&] { prepare_profile(raw, options); });
  for (const char* part : {"partial.whl", "y = -29.", "taping line", "internal face",
                           "--origin taping-line or internal-face", "LoadOptions::origin"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
  options.origin = WheelOrigin::taping_line;  // chosen: loads as it is
  EXPECT_NEAR(prepare_profile(raw, options).profile.y_min(), -0.030, 0.5e-3);
}

TEST(WheelOrigin, ABadTapingLineDistanceIsRefused) {
  const std::string message =
      refusal([] { load("s1002_flange_back.whl", WheelOrigin::automatic, 70.0); });
  for (const char* part : {"s1002_flange_back.whl", "70 m", "--taping-line-distance"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
}

TEST(WheelOrigin, OptionNames) {
  for (const WheelOrigin origin :
       {WheelOrigin::automatic, WheelOrigin::taping_line, WheelOrigin::internal_face})
    EXPECT_EQ(parse_wheel_origin(to_string(origin)), origin);
  EXPECT_FALSE(parse_wheel_origin("flange-back"));
}

TEST(WheelOrigin, MeasuredMiniProfWheel) {
  // Car7216_0001r.whl: X = 0 at the flange back (its back face, X = -0.16 ... 0.1 mm).
  LoadOptions as_taping_line;
  as_taping_line.origin = WheelOrigin::taping_line;
  const LoadedProfile kept = load_profile(testing::measured_wheel_file(), as_taping_line);
  const LoadedProfile moved = load_profile(testing::measured_wheel_file());  // automatic
  EXPECT_EQ(moved.origin.origin, WheelOrigin::internal_face);
  // Its one warning is its wavy flank (flank_waviness_test.cpp), none about its origin.
  ASSERT_EQ(moved.cleaning.warnings.size(), 1u);
  EXPECT_NE(moved.cleaning.warnings[0].find("the flank is wavy"), std::string::npos);
  EXPECT_EQ(kept.cleaning.warnings.size(), 1u);  // the rule contradicts the set origin: warned
  EXPECT_NEAR(moved.profile.y_min(), kept.profile.y_min() - 0.070, 1e-9);
  EXPECT_NEAR(moved.profile.y_max(), kept.profile.y_max() - 0.070, 1e-9);
  const WheelParameters a = wheel_parameters(moved.profile), b = wheel_parameters(kept.profile);
  EXPECT_NEAR(a.Sd, b.Sd, 1e-9);
  EXPECT_NEAR(a.Sh, b.Sh, 1e-9);
  EXPECT_NEAR(a.qR, b.qR, 1e-9);
  EXPECT_NEAR(a.running_circle[0], 0.0, 0.2e-3);
  std::printf("Car7216_0001r.whl: origin %s, y %.3f ... %.3f mm, Sd %.3f mm\n",
              std::string(to_string(moved.origin.origin)).c_str(), moved.profile.y_min() * 1e3,
              moved.profile.y_max() * 1e3, a.Sd * 1e3);
}

TEST(WheelOrigin, ContactBenchmarkWheelKeepsItsTapingLine) {
  LoadOptions automatic;
  automatic.origin = WheelOrigin::automatic;
  const LoadedProfile wheel = load_profile(testing::contact_wheel_file(), automatic);
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::taping_line);
  EXPECT_EQ(wheel.origin.shift, 0.0);
  EXPECT_TRUE(wheel.cleaning.warnings.empty());
}

}  // namespace
}  // namespace wheelwear::profiles

namespace wheelwear::profiles {
namespace {

// The file header's values place the wheel: S1002 written as MiniProf for Windows writes it, X
// = 0 at the internal face, with a taping line 72 mm from it (WheelDiameterTaperline) and a
// diameter of 840 mm there (DiameterTaperline). The reference is S1002 itself, shifted by the
// header's 72 mm, and half the header's diameter.
TEST(WheelOrigin, TheHeaderStatesTheTapingLineAndTheNominalRadius) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "wheelwear_header_taping_line.whl";
  {
    std::ofstream out(path);
    out << "ProgramName=MiniProf for Windows\nWheelDiameterTaperline=72.0000\n"
           "DiameterTaperline=840.0000\nColumnDef=X,Y\n\n";
    out.precision(12);
    for (const Point& p : s1002_points({.point_spacing = 0.5e-3}))
      out << (p[0] + 0.072) * 1e3 << ' ' << p[1] * 1e3 << '\n';
  }
  const LoadedProfile wheel = load_profile(path);
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::internal_face);
  EXPECT_NEAR(wheel.origin.shift, -0.072, 1e-15);
  EXPECT_NE(wheel.origin.reason.find("the file header's"), std::string::npos)
      << wheel.origin.reason;
  EXPECT_NEAR(wheel.profile.info().nominal_radius, 0.420, 1e-15);
  EXPECT_NEAR(wheel.profile.info().taping_line_distance, 0.072, 1e-15);
  EXPECT_TRUE(wheel.cleaning.warnings.empty());
  // S1002's taping line lands at y = 0 (12 digits written: 1e-12 m); its vertical flange back,
  // 2 mm from the file's X = 0 as written here, is measured where it is, 70 mm from the taping
  // line, and EN 15313's Sd from it is S1002's nominal 32.5 mm (to its 0.02 mm check above).
  EXPECT_NEAR(*wheel.profile.z_at(0.0), 0.0, 1e-9);
  const InternalFace face = internal_face(wheel.profile);
  EXPECT_TRUE(face.measured) << face.how;
  EXPECT_NEAR(face.y, -0.070, 1e-9) << face.how;
  EXPECT_NEAR(wheel_parameters(wheel.profile).Sd, 0.0325, 0.02e-3);
  // A radius set by the user wins over the header's, with a warning.
  LoadOptions set;
  set.nominal_radius = 0.45;
  const LoadedProfile overridden = load_profile(path, set);
  EXPECT_EQ(overridden.profile.info().nominal_radius, 0.45);
  ASSERT_EQ(overridden.cleaning.warnings.size(), 1u);
  EXPECT_NE(overridden.cleaning.warnings[0].find("420.000 mm"), std::string::npos)
      << overridden.cleaning.warnings[0];
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace wheelwear::profiles
