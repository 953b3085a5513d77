// A run stores every file its scene names (/inputs) and a resumed run uses only those copies:
// a file changed since is refused by name unless --resume-stored, a file moved away is no
// obstacle, and another program version is refused.

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::pipeline {
namespace {

// The collective of small_scene as a CSV file.
constexpr const char* kStates =
    "label,dy_m,yaw_rad,load_left_N,load_right_N,lateral_force_right_N,speed_m_s,"
    "curve_radius_m,lateral_velocity_m_s,weight\n"
    "tangent,0.001,2e-4,55e3,55e3,,40,0,0.01,3\n"
    "tangent,-0.002,-3e-4,55e3,55e3,,40,0,,3\n"
    "R1000,0.004,1e-3,60e3,50e3,,30,1000,,1\n"
    "R500,-0.0065,-2e-3,50e3,60e3,25e3,22,-500,,1\n";

// kStates with every load x 1.2.
constexpr const char* kStatesHeavier =
    "label,dy_m,yaw_rad,load_left_N,load_right_N,lateral_force_right_N,speed_m_s,"
    "curve_radius_m,lateral_velocity_m_s,weight\n"
    "tangent,0.001,2e-4,66e3,66e3,,40,0,0.01,3\n"
    "tangent,-0.002,-3e-4,66e3,66e3,,40,0,,3\n"
    "R1000,0.004,1e-3,72e3,60e3,,30,1000,,1\n"
    "R500,-0.0065,-2e-3,60e3,72e3,25e3,22,-500,,1\n";

// A scene naming the collective and a wheel profile by file; four steps of 10 km.
std::string file_scene() {
  return "[wheel]\nprofile = \"wheel.csv\"\n"
         "[contact]\ngrid_nx = 12\ngrid_ny = 12\n"
         "[run]\ndistance_m = 40e3\nstep_distance_m = 10e3\nmax_depth_step_m = 1e-3\n"
         "[load_collective]\nfile = \"states.csv\"\n";
}

// Stops a run by throwing from its progress report once `steps` steps are written.
struct StopAfter {};
RunOptions stopping_after(int steps) {
  RunOptions options;
  options.progress = [steps](const RunProgress& p) {
    if (p.step + 1 >= steps) throw StopAfter{};
  };
  return options;
}

// The message of the InputError a resume of `file` throws; a test failure if it resumes.
std::string resume_refusal(const fs::path& file, const RunOptions& options = {}) {
  try {
    resume_run(file, options);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "resume of " << file << " went ahead";
  return {};
}

class StoredInputsTest : public WearRunTest {
 protected:
  void SetUp() override {
    WearRunTest::SetUp();
    std::ifstream wheel(fs::path(WHEELWEAR_TEST_DATA) / "profiles" / "s1002_worn_33200km.csv");
    std::stringstream text;
    text << wheel.rdbuf();
    wheel_text_ = text.str();
    write("wheel.csv", wheel_text_);
    write("states.csv", kStates);
    scene_ = write("scene.toml", file_scene());
  }
  // The scene run whole into `out`, or stopped after `steps` steps.
  void run_scene_file(const fs::path& out, int steps = 0) const {
    const Scene scene = load_scene(scene_);
    const std::string text = core::read_text_file(scene_);
    if (steps == 0) {
      run_scene(scene, text, dir_, false, out, {});
      return;
    }
    EXPECT_THROW(run_scene(scene, text, dir_, false, out, stopping_after(steps)), StopAfter);
  }
  // Every array of every step equal in both files; returns how many values were compared.
  static int compare_steps(const fs::path& a, const fs::path& b) {
    const ResultsFile fa = ResultsFile::read(a), fb = ResultsFile::read(b);
    EXPECT_EQ(fa.completed_steps(), fb.completed_steps());
    int compared = 0;
    for (int step = 0; step < std::min(fa.completed_steps(), fb.completed_steps()); ++step)
      expect_same_arrays(fa, fb, step, "", compared);
    return compared;
  }
  std::string wheel_text_;
  fs::path scene_;
};

TEST_F(StoredInputsTest, TheFileHoldsEveryInputWithItsHash) {
  const fs::path out = dir_ / "run.h5";
  run_scene_file(out, 1);
  const auto inputs = ResultsFile::read(out).read_bytes("/inputs");
  ASSERT_EQ(inputs.size(), 2u);
  int matched = 0;
  for (const BytesRecord& in : inputs) {
    const std::string& path = in.attributes.at("path");
    const std::string expected = path == (dir_ / "wheel.csv").string() ? wheel_text_ : kStates;
    EXPECT_EQ(in.bytes, expected) << path;
    EXPECT_EQ(in.attributes.at("sha256"), tangential::sha256_hex(expected)) << path;
    matched += in.attributes.at("key") == "wheel.profile" ||
               in.attributes.at("key") == "load_collective.file";
  }
  EXPECT_EQ(matched, 2);
}

TEST_F(StoredInputsTest, AChangedFileIsRefusedByNameUnlessResumeStored) {
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run_scene_file(reference);
  run_scene_file(killed, 2);
  // The loads x 1.2: what made a resumed run contradict its own stored collective.
  write("states.csv", kStatesHeavier);
  std::ofstream(dir_ / "wheel.csv", std::ios::app) << "\n";
  const std::string what = resume_refusal(killed);
  EXPECT_NE(what.find((dir_ / "states.csv").string()), std::string::npos) << what;
  EXPECT_NE(what.find((dir_ / "wheel.csv").string()), std::string::npos) << what;
  EXPECT_NE(what.find("--resume-stored"), std::string::npos) << what;
  EXPECT_EQ(ResultsFile::read(killed).completed_steps(), 2);  // the refusal wrote nothing

  // With --resume-stored it completes, equal to the run that never saw the change.
  RunOptions stored;
  stored.resume_stored = true;
  resume_run(killed, stored);
  EXPECT_GT(compare_steps(reference, killed), 1000);
}

TEST_F(StoredInputsTest, TheCommandLineRefusesAChangedFileWithExitTwo) {
  // Enough steps that the run is still going when it is killed after its second step.
  std::string text = file_scene();
  text.replace(text.find("40e3"), 4, "400e3");
  const fs::path scene = write("long.toml", text), killed = dir_ / "killed.h5";
  const int status =
      kill_run_after_steps({"run", scene.string(), "-q", "-o", killed.string()}, killed, 2);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  write("states.csv", kStatesHeavier);
  const auto refused = testing::run_wheelwear("run -q --resume " + killed.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("states.csv (load_collective.file)"), std::string::npos)
      << refused.err;
  const int kept = ResultsFile::read(killed).completed_steps();
  const auto resumed = testing::run_wheelwear("run -q --resume-stored --resume " + killed.string());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_GT(ResultsFile::read(killed).completed_steps(), kept);
}

TEST_F(StoredInputsTest, AFileMovedAwayIsNoObstacle) {
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run_scene_file(reference);
  run_scene_file(killed, 2);
  fs::remove(dir_ / "states.csv");
  fs::remove(dir_ / "wheel.csv");
  resume_run(killed, {});
  EXPECT_GT(compare_steps(reference, killed), 1000);
}

TEST_F(StoredInputsTest, AnHdf5CollectiveMovedAwayResumesFromItsStoredBytes) {
  {
    H5::H5File h5((dir_ / "states.h5").string(), H5F_ACC_TRUNC);
    const auto column = [&](const char* name, std::vector<double> values) {
      const hsize_t n = values.size();
      h5.createDataSet(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(1, &n))
          .write(values.data(), H5::PredType::NATIVE_DOUBLE);
    };
    column("dy_m", {0.001, -0.0065});
    column("yaw_rad", {2e-4, -2e-3});
    column("axle_load_N", {110e3, 110e3});
    column("speed_m_s", {40, 22});
    column("curve_radius_m", {0, -500});
    column("weight", {3, 1});
  }
  std::string text = file_scene();
  text.replace(text.find("states.csv"), 10, "states.h5");
  scene_ = write("scene.toml", text);
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run_scene_file(reference);
  run_scene_file(killed, 2);
  fs::remove(dir_ / "states.h5");
  resume_run(killed, {});
  EXPECT_GT(compare_steps(reference, killed), 1000);
}

TEST_F(StoredInputsTest, AChangedWearTableIsRefusedByItsKey) {
  write("usfd.csv", core::read_text_file(fs::path(WHEELWEAR_TEST_DATA) / ".." / ".." / "data" /
                                         "wear" / "usfd.csv"));
  scene_ = write("scene.toml", file_scene() + "[wear]\nlaw_table = \"usfd.csv\"\n");
  const fs::path killed = dir_ / "killed.h5";
  run_scene_file(killed, 2);
  std::ofstream(dir_ / "usfd.csv", std::ios::app) << "# edited\n";
  const std::string what = resume_refusal(killed);
  EXPECT_NE(what.find("usfd.csv (wear.law_table)"), std::string::npos) << what;
}

// A complete run is not resumed, whatever changed since, and its file is left as it was.
TEST_F(StoredInputsTest, ACompleteRunIsLeftAsItIs) {
  const fs::path out = dir_ / "complete.h5";
  run_scene_file(out);
  write("states.csv", kStatesHeavier);
  const auto before = fs::last_write_time(out);
  const auto size = fs::file_size(out);
  const std::string what = resume_refusal(out);
  EXPECT_NE(what.find("the run is complete"), std::string::npos) << what;
  EXPECT_EQ(fs::last_write_time(out), before);
  EXPECT_EQ(fs::file_size(out), size);
}

TEST_F(StoredInputsTest, AnotherProgramVersionIsRefused) {
  const fs::path killed = dir_ / "killed.h5";
  run_scene_file(killed, 2);
  RunOptions other;
  other.program = "wheelwear 0.0.0 (commit elsewhere)";
  const std::string what = resume_refusal(killed, other);
  EXPECT_NE(what.find("written by " + RunOptions{}.program), std::string::npos) << what;
  EXPECT_NE(what.find("commit elsewhere"), std::string::npos) << what;
}

TEST_F(StoredInputsTest, ResumeStoredGoesOnlyWithResume) {
  const auto result = testing::run_wheelwear("run " + scene_.string() + " -q --resume-stored -o " +
                                             (dir_ / "x.h5").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--resume-stored"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.h5"));
}

}  // namespace
}  // namespace wheelwear::pipeline
