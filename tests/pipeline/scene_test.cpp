// Scenes: what a valid scene reads into, and a table of bad scenes, each with its own message.

#include "wheelwear/pipeline/scene.hpp"

#include <H5Cpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <vector>

#include "support/run_command.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

constexpr const char* kState =
    "[[load_collective.state]]\n"
    "dy_m = 0.002\nyaw_rad = 1e-3\nload_left_N = 60e3\nload_right_N = 50e3\nspeed_m_s = 30\n";

class SceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wheelwear_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(SceneTest, ReadsEveryKeyInSiUnits) {
  const Scene s = parse_scene(
      "title = \"t\"\n"
      "[wheel]\nprofile = \"S1002\"\nradius_m = 0.45\norigin = \"internal-face\"\n"
      "taping_line_distance_m = 0.0715\nmax_drop = 0.3\n"
      "[rail]\nprofile = \"60E1\"\ninclination = 0.05\nmax_drop = 0.1\ngauge_side = \"right\"\n"
      "[track]\ngauge_m = 1.432\nback_to_back_m = 1.358\n"
      "[material]\nyoungs_modulus_Pa = 210e9\npoisson = 0.3\n"
      "[contact]\nmodel = \"eqe-shifted\"\nfriction = 0.4\ngrid_nx = 12\ngrid_ny = 14\n"
      "scheme = \"second-order\"\nstrip_width_m = 1e-4\nvirtual_penetration = 0.5\n"
      "normal_method = \"hertz-calibrated\"\n"
      "[wear]\nlaw = \"archard\"\n"
      "[run]\ndistance_m = 1000\nstep_distance_m = 100\nmax_depth_step_m = 1e-5\n"
      "smoothing_length_m = 1e-3\nwheels = \"separate\"\n"
      "[output]\nstate_summaries = false\ntgamma_maps = true\n" +
          std::string(kState),
      dir_);
  EXPECT_EQ(s.title, "t");
  EXPECT_DOUBLE_EQ(s.wheel_radius.value(), 0.45);
  EXPECT_EQ(s.wheel_file.origin, profiles::WheelOrigin::internal_face);
  EXPECT_DOUBLE_EQ(s.wheel_file.taping_line_distance.value(), 0.0715);
  EXPECT_DOUBLE_EQ(s.wheel_file.max_drop_fraction, 0.3);
  EXPECT_DOUBLE_EQ(s.rail_file.max_drop_fraction, 0.1);
  EXPECT_EQ(s.rail_file.rail_gauge_side, profiles::Mirror::flip);
  ASSERT_TRUE(s.rail_inclination.has_value());
  EXPECT_NEAR(*s.rail_inclination, std::atan(0.05), 1e-15);
  // As the commands take it: "1:20" is the same slope; a bare 20 is refused.
  const Scene one_in = parse_scene("[rail]\ninclination = \"1:20\"\n" + std::string(kState), dir_);
  EXPECT_EQ(*one_in.rail_inclination, std::atan(1.0 / 20.0));
  EXPECT_THROW(parse_scene("[rail]\ninclination = \"20\"\n" + std::string(kState), dir_),
               InputError);
  EXPECT_DOUBLE_EQ(s.gauge, 1.432);
  EXPECT_DOUBLE_EQ(s.back_to_back, 1.358);
  EXPECT_DOUBLE_EQ(s.youngs_modulus, 210e9);
  EXPECT_DOUBLE_EQ(s.poisson, 0.3);
  EXPECT_EQ(s.model, tangential::ContactModel::eqe_shifted);
  EXPECT_DOUBLE_EQ(s.friction, 0.4);
  EXPECT_EQ(s.grid_nx, 12);
  EXPECT_EQ(s.grid_ny, 14);
  EXPECT_EQ(s.scheme, tangential::FastsimScheme::second_order);
  EXPECT_EQ(s.normal_method, contactgeom::KpPenetration::hertz_calibrated);
  EXPECT_EQ(parse_scene(std::string(kState), dir_).normal_method,
            contactgeom::KpPenetration::hertz_calibrated);  // the default
  EXPECT_EQ(s.wear_law, "archard");
  EXPECT_DOUBLE_EQ(s.distance, 1000.0);
  EXPECT_DOUBLE_EQ(s.step_distance, 100.0);
  EXPECT_DOUBLE_EQ(s.max_depth_step, 1e-5);
  EXPECT_TRUE(s.separate_wheels);
  EXPECT_FALSE(s.state_summaries);
  EXPECT_TRUE(s.tgamma_maps);
  ASSERT_EQ(s.states.size(), 1u);
  EXPECT_DOUBLE_EQ(s.states[0].dy, 0.002);
  EXPECT_DOUBLE_EQ(s.states[0].load_left, 60e3);
  EXPECT_DOUBLE_EQ(s.states[0].load_right, 50e3);
  EXPECT_DOUBLE_EQ(s.states[0].speed, 30.0);
}

TEST_F(SceneTest, CollectiveFromCsvWithOptionalColumnsAndCreepages) {
  write("states.csv",
        "# a comment\n"
        "section,dy_m,axle_load_N,speed_m_s,lateral_force_left_N,vx_left,vy_left,spin_left_1_m,"
        "weight\n"
        "tangent,0.001,110e3,40,,,,,3\n"
        "curve,0.007,110e3,20,30e3,0.001,-0.002,0.5,1\n");
  const Scene s = parse_scene("[load_collective]\nfile = \"states.csv\"\n", dir_);
  ASSERT_EQ(s.states.size(), 2u);
  EXPECT_EQ(s.states[0].label, "tangent");
  EXPECT_DOUBLE_EQ(s.states[0].load_left, 55e3);  // the axle load is split evenly
  EXPECT_FALSE(s.states[0].lateral_force_left.has_value());
  EXPECT_FALSE(s.states[0].creepages_left.has_value());
  ASSERT_TRUE(s.states[1].lateral_force_left.has_value());
  EXPECT_DOUBLE_EQ(*s.states[1].lateral_force_left, 30e3);
  ASSERT_TRUE(s.states[1].creepages_left.has_value());
  EXPECT_DOUBLE_EQ(s.states[1].creepages_left->phi, 0.5);
  EXPECT_DOUBLE_EQ(s.states[0].weight, 3.0);
  EXPECT_EQ(s.states[1].line, 4);
}

TEST_F(SceneTest, CollectiveFromHdf5AsAMultibodyExportWritesIt) {
  // One 1-D dataset per column in the file's root group; NaN leaves an optional value unset.
  const fs::path file = dir_ / "states.h5";
  {
    H5::H5File h5(file.string(), H5F_ACC_TRUNC);
    auto column = [&](const char* name, std::vector<double> values) {
      const hsize_t n = values.size();
      H5::DataSet set = h5.createDataSet(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(1, &n));
      set.write(values.data(), H5::PredType::NATIVE_DOUBLE);
    };
    column("dy_m", {0.001, 0.007});
    column("axle_load_N", {110e3, 120e3});
    column("speed_m_s", {40, 20});
    column("lateral_force_left_N", {NAN, 30e3});
    column("weight", {2, 1});
  }
  const Scene s = parse_scene("[load_collective]\nfile = \"states.h5\"\n", dir_);
  ASSERT_EQ(s.states.size(), 2u);
  EXPECT_DOUBLE_EQ(s.states[1].dy, 0.007);
  EXPECT_DOUBLE_EQ(s.states[1].load_right, 60e3);
  EXPECT_FALSE(s.states[0].lateral_force_left.has_value());
  ASSERT_TRUE(s.states[1].lateral_force_left.has_value());
  EXPECT_DOUBLE_EQ(*s.states[1].lateral_force_left, 30e3);
  EXPECT_DOUBLE_EQ(s.states[0].weight, 2.0);

  // A truncated file is an input error naming the file, not a crash.
  const fs::path broken = dir_ / "broken.h5";
  fs::copy_file(file, broken);
  fs::resize_file(broken, fs::file_size(broken) / 3);
  try {
    parse_scene("[load_collective]\nfile = \"broken.h5\"\n", dir_);
    FAIL() << "a truncated HDF5 file was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("broken.h5"), std::string::npos) << error.what();
  }
}

// Every file a scene names comes through its reader, once, and the scene keeps its bytes: what
// a run stores and a resumed run reads instead of the disk (none of these paths exist).
TEST_F(SceneTest, EveryFileNamedIsReadOnceThroughTheReaderAndKept) {
  const fs::path data = fs::path(WHEELWEAR_TEST_DATA);
  const std::map<std::string, fs::path> sources = {
      {"/stored/wheel.whl", data / "profiles" / "s1002_taping_line.whl"},
      {"/stored/rail.ban", data / "profiles" / "rail_base.ban"},
      {"/stored/usfd.csv", data / ".." / ".." / "data" / "wear" / "usfd.csv"},
      {"/stored/coach.toml", data / ".." / ".." / "data" / "vehicles" / "default.toml"},
      {"/stored/line.toml", data / ".." / ".." / "data" / "routes" / "default.toml"}};
  std::map<std::string, int> reads;
  const SceneFileReader reader = [&](const fs::path& path) -> std::optional<std::string> {
    ++reads[path.string()];
    const auto it = sources.find(path.string());
    if (it == sources.end()) return std::nullopt;
    return core::read_text_file(it->second);
  };
  const Scene s = parse_scene(
      "[wheel]\nprofile = \"wheel.whl\"\n[rail]\nprofile = \"rail.ban\"\n"
      "[wear]\nlaw_table = \"usfd.csv\"\n[vehicle]\nfile = \"coach.toml\"\n"
      "[route]\nfile = \"line.toml\"\n",
      "/stored", reader);
  ASSERT_EQ(s.inputs.size(), sources.size());
  for (const SceneInput& in : s.inputs) {
    ASSERT_TRUE(sources.count(in.path)) << in.path;
    EXPECT_EQ(in.content, core::read_text_file(sources.at(in.path))) << in.path;
    EXPECT_EQ(reads[in.path], 1) << in.path;
  }
  std::map<std::string, std::string> keys;
  for (const SceneInput& in : s.inputs) keys[in.path] = in.key;
  EXPECT_EQ(keys["/stored/wheel.whl"], "wheel.profile");
  EXPECT_EQ(keys["/stored/line.toml"], "route.file");
  // The profiles are built from the kept bytes, not from their (missing) files.
  EXPECT_NO_THROW(StateKernel{s});
  EXPECT_NO_THROW(profiles::wheel_profile(s.wheel_profile, s.wheel_radius, s.wheel_file));
  ASSERT_TRUE(s.vehicle_run.has_value());
  EXPECT_EQ(s.vehicle_run->route.sections.size(), vehicle::default_route().sections.size());
}

// The built-in scene is the built-in coach on the built-in route, worn over 10^5 km with the
// per-step work data/scenes/default.toml states (docs/vehicle.md, "The default scene").
TEST(DefaultScene, IsTheVehicleOnTheDefaultRouteOverAHundredThousandKilometres) {
  const Scene s = default_scene();
  ASSERT_TRUE(s.vehicle_run.has_value());
  EXPECT_TRUE(s.states.empty());
  const VehicleRun& v = *s.vehicle_run;
  EXPECT_EQ(v.route.sections.size(), vehicle::default_route().sections.size());
  EXPECT_EQ(v.vehicle.mass(), vehicle::default_vehicle().mass());
  EXPECT_EQ(s.distance, 100e6);
  EXPECT_EQ(s.max_depth_step, 0.3e-3);
  EXPECT_EQ(v.resolve_depth, 0.0);  // the vehicle solved at every step
  EXPECT_TRUE(v.time_domain.enabled);
  EXPECT_EQ(v.time_domain.tangent_length, 100.0);
  EXPECT_EQ(v.time_domain.sample_distance, 2.0);
  EXPECT_TRUE(s.limits.stop);
  EXPECT_EQ(s.wheel_profile, "S1002");
  EXPECT_EQ(s.rail_profile, "60E1");
}

TEST(FrozenCollectiveScene, HasAThousandStatesOfTangentAndCurves) {
  const Scene s = frozen_collective_scene();
  EXPECT_GE(s.states.size(), 1000u);
  int tangent = 0, curves = 0, flange = 0;
  for (const auto& state : s.states) {
    (state.curve_radius == 0.0 ? tangent : curves)++;
    if (state.lateral_force_left || state.lateral_force_right) ++flange;
  }
  EXPECT_GT(tangent, 100);
  EXPECT_GT(curves, 100);
  EXPECT_GT(flange, 10);  // tight curves put the outer flange against the rail
  EXPECT_EQ(s.wheel_profile, "S1002");
  EXPECT_EQ(s.rail_profile, "60E1");
}

// One bad scene, what it must say, and the line it must name.
struct BadScene {
  const char* name;
  std::string text;
  const char* message;
};

TEST_F(SceneTest, TangentialMethodIsFastsimUnlessAnotherIsAsked) {
  EXPECT_EQ(parse_scene(kState, dir_).tangential, TangentialMethod::fastsim);
  for (const auto& [name, method] :
       {std::pair{"best", TangentialMethod::best}, {"exact", TangentialMethod::exact}}) {
    const std::string text =
        "[contact]\nmodel = \"sdec\"\ntangential_method = \"" + std::string(name) + "\"\n" + kState;
    EXPECT_EQ(parse_scene(text, dir_).tangential, method) << name;
  }
}

// The command line's method names name the contact model with the method; each maps onto the
// same tangential method the kernel calls (scene_method).
TEST_F(SceneTest, TangentialMethodTakesTheCommandLineNames) {
  const std::vector<std::tuple<const char*, tangential::ContactModel, tangential::Method>> cases = {
      {"fastsim-sdec", tangential::ContactModel::sdec, tangential::Method::fastsim_sdec},
      {"fastsim-eql", tangential::ContactModel::eql, tangential::Method::fastsim_eql},
      {"fastsim-eqe", tangential::ContactModel::eqe, tangential::Method::fastsim_eqe},
      {"fastsim-eqe-shifted", tangential::ContactModel::eqe_shifted,
       tangential::Method::fastsim_eqe_shifted}};
  int compared = 0;
  for (const auto& [name, model, method] : cases) {
    const Scene s = parse_scene(
        "[contact]\ntangential_method = \"" + std::string(name) + "\"\n" + kState, dir_);
    EXPECT_EQ(s.tangential, TangentialMethod::fastsim) << name;
    EXPECT_EQ(s.model, model) << name;
    EXPECT_EQ(scene_method(s.model, s.tangential), method) << name;
    EXPECT_EQ(tangential::method_name(method), name);
    ++compared;
  }
  EXPECT_EQ(compared, 4);
  EXPECT_EQ(scene_method(tangential::ContactModel::hertz, TangentialMethod::fastsim),
            tangential::Method::fastsim_elliptic);
  EXPECT_EQ(scene_method(tangential::ContactModel::sdec, TangentialMethod::best),
            tangential::Method::best);
}

class BadSceneTest : public SceneTest, public ::testing::WithParamInterface<BadScene> {};

TEST_P(BadSceneTest, IsRejectedNamingTheKeyAndLine) {
  write("bad_cell.csv", "dy_m,axle_load_N,speed_m_s\n0.001,abc,30\n");
  write("bad_column.csv", "dy_m,axle_load_kN,speed_m_s\n0.001,110,30\n");
  try {
    parse_scene(GetParam().text, dir_);
    FAIL() << "accepted: " << GetParam().text;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(GetParam().message), std::string::npos)
        << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadSceneTest,
    ::testing::Values(
        BadScene{"UnknownKey", "colour = 1\n" + std::string(kState), "scene line 1: colour"},
        BadScene{"WrongUnit", "[wheel]\nradius_mm = 460\n" + std::string(kState),
                 "did you mean 'radius_m'"},
        BadScene{"WrongType", "[wheel]\nradius_m = \"big\"\n" + std::string(kState),
                 "scene line 2: wheel.radius_m: expected a number"},
        BadScene{"RadiusInMillimetres", "[wheel]\nradius_m = 460\n" + std::string(kState),
                 "wheel.radius_m = 460"},
        BadScene{"UnknownOrigin", "[wheel]\norigin = \"flange\"\n" + std::string(kState),
                 "wheel.origin = \"flange\": unknown origin; use auto, taping-line"},
        BadScene{"TapingLineInMillimetres",
                 "[wheel]\ntaping_line_distance_m = 70\n" + std::string(kState),
                 "wheel.taping_line_distance_m = 70"},
        BadScene{"UnknownGaugeSide", "[rail]\ngauge_side = \"inside\"\n" + std::string(kState),
                 "rail.gauge_side = \"inside\": use auto, left"},
        BadScene{"MaxDropAbove1", "[rail]\nmax_drop = 20\n" + std::string(kState),
                 "rail.max_drop = 20"},
        BadScene{"NegativeFriction", "[contact]\nfriction = -0.1\n" + std::string(kState),
                 "contact.friction = -0.1"},
        BadScene{"MissingProfile", "[wheel]\nprofile = \"nosuch.csv\"\n" + std::string(kState),
                 "no such file"},
        BadScene{"UnknownModel", "[contact]\nmodel = \"ellipse\"\n" + std::string(kState),
                 "unknown contact model"},
        BadScene{"UnknownTangentialMethod",
                 "[contact]\ntangential_method = \"kalker\"\n" + std::string(kState),
                 "contact.tangential_method = \"kalker\": unknown tangential method"},
        BadScene{"UnknownScheme", "[contact]\nscheme = \"rk4\"\n" + std::string(kState),
                 "contact.scheme = \"rk4\": unknown FASTSIM scheme; use kalker, second-order"},
        BadScene{"UnknownNormalMethod",
                 "[contact]\nnormal_method = \"analyn\"\n" + std::string(kState),
                 "contact.normal_method = \"analyn\": unknown normal method; use "
                 "kik-piotrowski, hertz-calibrated"},
        BadScene{"MethodDisagreesWithModel",
                 "[contact]\nmodel = \"eqe\"\ntangential_method = \"fastsim-sdec\"\n" +
                     std::string(kState),
                 "names the contact model sdec but contact.model = \"eqe\""},
        BadScene{"MethodWithoutCells",
                 "[contact]\ntangential_method = \"linear-sdec\"\n" + std::string(kState),
                 "contact.tangential_method = \"linear-sdec\": unknown tangential method"},
        BadScene{"ExactGridTooFine",
                 "[contact]\ngrid_nx = 500\ntangential_method = \"exact\"\n" + std::string(kState),
                 "500 x 30 is beyond 400 x 400"},
        BadScene{"BestNeedsSdec",
                 "[contact]\nmodel = \"eqe\"\ntangential_method = \"best\"\n" + std::string(kState),
                 "scene line 3: contact.tangential_method = \"best\" needs contact.model = "
                 "\"sdec\""},
        BadScene{"Syntax", "[run\n", "scene line 1"},
        BadScene{"NoStates", "[run]\ndistance_m = 10\n", "no [load_collective]"},
        BadScene{"StateWithoutLoad", "[[load_collective.state]]\ndy_m = 0.001\nspeed_m_s = 20\n",
                 "wheel loads are missing"},
        BadScene{"ShiftInMillimetres",
                 "[[load_collective.state]]\ndy_m = 5\naxle_load_N = 1e5\nspeed_m_s = 20\n",
                 "dy_m = 5"},
        BadScene{"NegativeLoad",
                 "[[load_collective.state]]\nload_left_N = -5\nload_right_N = 5e4\n"
                 "speed_m_s = 20\n",
                 "load_left_N = -5"},
        BadScene{"IncompleteCreepages",
                 "[[load_collective.state]]\naxle_load_N = 1e5\nspeed_m_s = 20\nvx_left = 0.001\n",
                 "creepages of the left wheel are incomplete"},
        BadScene{"MissingCollectiveFile", "[load_collective]\nfile = \"none.csv\"\n",
                 "no such file"},
        BadScene{"BadCell", "[load_collective]\nfile = \"bad_cell.csv\"\n",
                 "bad_cell.csv line 2: column axle_load_N: 'abc' is not a number"},
        BadScene{"UnknownColumn", "[load_collective]\nfile = \"bad_column.csv\"\n",
                 "unknown column 'axle_load_kN'"},
        BadScene{"UnknownWheelsMode", "[run]\nwheels = \"both\"\n" + std::string(kState),
                 "run.wheels = \"both\""}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

// Through the command line: a bad scene fails with exit code 2 before any file is written,
// and an existing results file stays as it was.
TEST_F(SceneTest, BadSceneLeavesNoFileAndKeepsAnExistingOne) {
  const fs::path scene = write("bad.toml", "[contact]\nfriction = -1\n" + std::string(kState));
  const fs::path out = dir_ / "out.h5";
  auto result = testing::run_wheelwear("run " + scene.string() + " -o " + out.string() + " -q");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("contact.friction"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir_ / "out.h5.partial"));

  write("out.h5", "earlier results");
  result =
      testing::run_wheelwear("run " + scene.string() + " -o " + out.string() + " -q --overwrite");
  EXPECT_EQ(result.exit_code, 2);
  std::ifstream in(out);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "earlier results");
}

// Step counts: distance over step distance beyond 1e5 steps is refused, beyond 1e4 warned about
// (the run passes the warning on), at 1e4 neither.
TEST_F(SceneTest, AbsurdStepCountsAreRefusedAndLargeOnesWarned) {
  const auto scene = [](const std::string& distance, const std::string& step) {
    return "[run]\ndistance_m = " + distance + "\nstep_distance_m = " + step + "\n" +
           std::string(kState);
  };
  try {
    parse_scene(scene("5e3", "1e-3"), {});
    ADD_FAILURE() << "five million steps accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 100000"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_scene(scene("100001", "1"), {}), InputError);
  EXPECT_EQ(parse_scene(scene("100000", "1"), {}).warnings.size(), 1u);
  EXPECT_EQ(parse_scene(scene("10001", "1"), {}).warnings.size(), 1u);
  EXPECT_TRUE(parse_scene(scene("10000", "1"), {}).warnings.empty());
  const fs::path file = write("many.toml", scene("20000", "1"));
  // The warning before the run; -q keeps the progress off, and the run is ended by its missing
  // output folder so that it does not take its 20000 steps.
  const auto result = testing::run_wheelwear("run " + file.string() + " -o " +
                                             (dir_ / "none" / "many.h5").string() + " -q");
  EXPECT_NE(result.err.find("warning: scene: [run] distance_m / step_distance_m makes 20000 steps"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("does not exist"), std::string::npos) << result.err;
  EXPECT_NE(result.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir_ / "none"));  // nothing created on the way
}

}  // namespace
}  // namespace wheelwear::pipeline
