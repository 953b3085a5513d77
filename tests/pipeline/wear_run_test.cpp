// The wear-evolution run end to end: determinism across threads, the worn area against the
// accumulated wear, monotone growth, the tangential methods, stability under large steps (kill
// and resume: wear_run_resume_test.cpp; golden results and the default scene:
// wear_run_golden_test.cpp; the file's layout: results_layout_test.cpp).

#include "wheelwear/pipeline/wear_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "support/csv_table.hpp"
#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

TEST_F(WearRunTest, OneAndTwoThreadsGiveIdenticalFiles) {
  const fs::path scene = write("s.toml", small_scene(20e3, 10e3, 1e-3));
  const std::string base = "run " + scene.string() + " -q -o ";
  ASSERT_EQ(testing::run_wheelwear(base + (dir_ / "t1.h5").string() + " --threads 1").exit_code, 0);
  ASSERT_EQ(testing::run_wheelwear(base + (dir_ / "t2.h5").string() + " --threads 2").exit_code, 0);
  expect_identical_runs(dir_ / "t1.h5", dir_ / "t2.h5");
  // HDF5's own comparison finds no difference outside /run_info (timings, host) either.
  const std::string h5diff = "h5diff --exclude-path /run_info " + (dir_ / "t1.h5").string() + " " +
                             (dir_ / "t2.h5").string() + " > /dev/null";
  EXPECT_EQ(std::system(h5diff.c_str()), 0);
}

TEST_F(WearRunTest, WornAreaEqualsAccumulatedWearAndGrowsMonotonically) {
  const fs::path out = dir_ / "run.h5";
  run(small_scene(2e6, 250e3, 1e-3), out);
  const ResultsFile file = ResultsFile::read(out);
  const int last = file.completed_steps() - 1;
  ASSERT_GE(last, 8);
  const auto y0 = file.read_step_array(0, "wheel/y"), z0 = file.read_step_array(0, "wheel/z");
  double accumulated = 0.0, previous_area = 0.0;
  for (int step = 0; step < last; ++step) {
    // The step's worn cross-section: the applied depth integrated along the profile.
    const auto y = file.read_step_array(step, "wheel/wear_step/y");
    const auto depth = file.read_step_array(step, "wheel/wear_step/depth");
    const auto yk = file.read_step_array(step, "wheel/y"),
               zk = file.read_step_array(step, "wheel/z");
    const profiles::Profile before(points(yk, zk), {"step", profiles::Body::wheel});
    for (std::size_t i = 0; i + 1 < y.size(); ++i) {
      // Arc length between the two lateral positions on the profile the depth was applied to.
      const double ds = arc_between(before, y[i], y[i + 1]);
      accumulated += 0.5 * (depth[i] + depth[i + 1]) * ds;
    }
    const int next = step + 1;
    const auto y1 = file.read_step_array(next, "wheel/y"),
               z1 = file.read_step_array(next, "wheel/z");
    const double area = area_between(file.read_step_array(0, "wheel/y"),
                                     file.read_step_array(0, "wheel/z"), y1, z1);
    EXPECT_GT(area, previous_area) << "step " << next;
    previous_area = area;
    // Wear removes material: the new tread lies on or above (z down) the old one everywhere;
    // 0.1 um allows for re-interpolating the curve through its moved knots.
    const profiles::Profile after(points(y1, z1), {"step", profiles::Body::wheel});
    for (double yq = -0.030; yq <= 0.050; yq += 0.5e-3)
      EXPECT_LE(*after.z_at(yq), *before.z_at(yq) + 1e-7) << "y " << yq << " step " << next;
    // The normal offset of a curved surface changes the area by depth^2 curvature / 2 (below
    // 0.5 % for 0.1 mm on the 15 mm flange root), the wear on the flange back's side is
    // dropped, and the polygon closes over re-interpolated ends: 1 % covers these.
    EXPECT_NEAR(area, accumulated, 0.01 * accumulated) << "step " << next;

    // The recorded cumulative wear, integrated along the step-0 profile, is that area too
    // (same 1 %: it is the normal depth of the same curved surface).
    const auto s = file.read_step_array(next, "wheel/cumulative_wear/s");
    const auto normal = file.read_step_array(next, "wheel/cumulative_wear/depth");
    double integral = 0.0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
      if (std::isfinite(normal[i]) && std::isfinite(normal[i + 1]))
        integral += 0.5 * (normal[i] + normal[i + 1]) * (s[i + 1] - s[i]);
    EXPECT_NEAR(integral, area, 0.01 * area) << "step " << next;
    // On the tread (within +-25 mm) the radius falls by the normal depth over the cosine of the
    // surface's slope; 1 % allows for the depth's own gradient over the normal's lateral offset.
    const auto ry = file.read_step_array(next, "wheel/radius_change/y");
    const auto dr = file.read_step_array(next, "wheel/radius_change/value");
    const profiles::Profile original(points(y0, z0), {"step0", profiles::Body::wheel});
    const double peak = *std::max_element(normal.begin(), normal.end(), [](double p, double q) {
      return !(p >= q) && std::isfinite(q);
    });
    int compared = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double y_O = original.position(s[i]).x();
      if (std::abs(y_O) > 0.025 || !(normal[i] > 0.1 * peak)) continue;
      // Delta r at y_O, linear between the 0.1 mm grid's points.
      const auto k = static_cast<std::size_t>(std::floor((y_O - ry.front()) / (ry[1] - ry[0])));
      if (k + 1 >= ry.size()) continue;
      const double u = (y_O - ry[k]) / (ry[k + 1] - ry[k]);
      const double at_y = (1.0 - u) * dr[k] + u * dr[k + 1];
      const double cos_slope = std::abs(original.normal(s[i]).y());
      EXPECT_NEAR(-at_y * cos_slope, normal[i], 0.01 * normal[i])
          << "y " << y_O << " step " << next;
      ++compared;
    }
    if (next == last) {
      EXPECT_GT(compared, 50);
    }
  }
  // The final profile at its fixed name is the last step's.
  const auto final_y = file.read_array("/final/wheel/y");
  EXPECT_EQ(final_y, file.read_step_array(last, "wheel/y"));
  EXPECT_EQ(file.read_array("/final/wheel/z"), file.read_step_array(last, "wheel/z"));
}

// tangential_method = "best": where the book of tables covers a patch its recorded totals are
// the table's for the recorded patch and creepages (recomputed here from the file), and its
// frictional work is their rigid-slip work; FASTSIM's stand only where the table does not reach.
TEST_F(WearRunTest, BestTakesTotalsFromTheTableWhereItReaches) {
  std::string text = small_scene(10e3, 10e3, 1e-3);
  text.insert(text.find("[contact]\n") + 10, "tangential_method = \"best\"\n");
  const fs::path out = dir_ / "best.h5";
  const RunSummary summary = run(text, out);
  const ResultsFile file = ResultsFile::read(out);
  auto column = [&](const std::string& name) { return file.read_step_array(0, "states/" + name); };
  const auto from_table = column("from_table"), a = column("a"), b = column("b"),
             psi = column("psi"), n = column("normal_force"), vx = column("vx"), vy = column("vy"),
             phi = column("phi"), fx = column("Fx"), fy = column("Fy"),
             work = column("frictional_work");
  const Scene scene = parse_scene(text, dir_);
  const tangential::Material material{scene.youngs_modulus / (2.0 * (1.0 + scene.poisson)),
                                      scene.poisson};
  std::size_t tabled = 0, patches = 0;
  // The step's share of the frictional work from the table: each patch's work weighted by its
  // state's share of the distance (patch arrays are [state][wheel][slot]).
  const std::vector<double> shares = state_shares(scene.states);
  const std::size_t slots = from_table.size() / (2 * shares.size());
  double all_work = 0.0, table_work = 0.0;
  for (std::size_t i = 0; i < from_table.size(); ++i) {
    if (from_table[i] < 0.0) continue;  // -1: a slot without a patch
    ++patches;
    const double weighted_work = shares[i / (2 * slots)] * work[i];
    all_work += weighted_work;
    if (from_table[i] == 1.0) table_work += weighted_work;
    const contactgeom::Sdec sdec{a[i], b[i], psi[i]};
    const tangential::Creepages v{vx[i], vy[i], phi[i]};
    const tangential::ContactLoad load{n[i], scene.friction};
    const bool covered = tangential::creep_table_covers(sdec, v, load, material);
    EXPECT_EQ(from_table[i] == 1.0, covered) << "patch " << i;
    if (!covered) continue;
    ++tabled;
    const tangential::CreepForces t = tangential::creep_table_forces(sdec, v, load, material);
    // The same computation on the same inputs; 1e-9 allows only for the recorded inputs' and
    // outputs' round trip through the file (exact in double) and for contraction differences.
    const double scale = 1e-9 * load.mu * load.N;
    EXPECT_NEAR(fx[i], t.Fx, scale) << "patch " << i;
    EXPECT_NEAR(fy[i], t.Fy, scale) << "patch " << i;
    EXPECT_NEAR(work[i], std::max(0.0, tangential::rigid_slip_work(t, v)), 1e-9 * (work[i] + 1e-9));
  }
  EXPECT_GT(tabled, patches / 2) << "the scene's patches should mostly lie in the table";
  EXPECT_EQ(file.read_step_array(0, "table_patches")[0], static_cast<double>(tabled));
  ASSERT_GT(all_work, 0.0);
  // The same sums in another order: 1e-12 of the share.
  EXPECT_NEAR(file.read_step_array(0, "table_work_share")[0], table_work / all_work, 1e-12);
  double over_steps = 0.0;  // the summary counts every evaluation, one per step
  for (int step = 0; step < file.completed_steps(); ++step)
    over_steps += file.read_step_array(step, "table_patches")[0];
  EXPECT_EQ(static_cast<double>(summary.table_patches), over_steps);
}

// tangential_method = "exact": every patch's recorded totals are those of a fresh exact solve
// of the recorded patch and creepages on the scene's grid, and its frictional work their
// rigid-slip work (exact_fields.hpp).
TEST_F(WearRunTest, ExactSolvesEveryPatchWithTheExactTheory) {
  std::string text = small_scene(10e3, 10e3, 1e-3);
  text.insert(text.find("[contact]\n") + 10, "tangential_method = \"exact\"\n");
  const fs::path out = dir_ / "exact.h5";
  run(text, out);
  const ResultsFile file = ResultsFile::read(out);
  auto column = [&](const std::string& name) { return file.read_step_array(0, "states/" + name); };
  const auto a = column("a"), b = column("b"), psi = column("psi"), n = column("normal_force"),
             vx = column("vx"), vy = column("vy"), phi = column("phi"), fx = column("Fx"),
             fy = column("Fy"), work = column("frictional_work"), area = column("worn_area");
  const Scene scene = parse_scene(text, dir_);
  const tangential::Material material{scene.youngs_modulus / (2.0 * (1.0 + scene.poisson)),
                                      scene.poisson};
  tangential::SdecGridOptions options;
  options.nx = scene.grid_nx;
  options.ny = scene.grid_ny;
  int patches = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i])) continue;
    ++patches;
    const tangential::Creepages v{vx[i], vy[i], phi[i]};
    const tangential::ContactLoad load{n[i], scene.friction};
    const tangential::ExactSolution e =
        tangential::exact_sdec({a[i], b[i], psi[i]}, v, load, material, options);
    // The run's solve repeated on the recorded inputs: equal but for rounding (1e-9 of mu N).
    const double scale = 1e-9 * load.mu * load.N;
    EXPECT_NEAR(fx[i], e.forces.Fx, scale) << "patch " << i;
    EXPECT_NEAR(fy[i], e.forces.Fy, scale) << "patch " << i;
    EXPECT_NEAR(work[i], std::max(0.0, tangential::rigid_slip_work(e.forces, v)),
                1e-9 * (work[i] + 1e-9));
    EXPECT_GT(area[i], 0.0) << "patch " << i;
  }
  EXPECT_GE(patches, 8);
}

// [contact] max_contact_angle_rad: a position-prescribed contact on S1002's 70 degree flank is
// dropped for Nadal's limit by default (1.35 rad), and as climbing once the limit is below it.
TEST_F(WearRunTest, TheSteepestContactAngleSortsFlankContactsAsClimbing) {
  const std::string states =
      "[[load_collective.state]]\ndy_m = -0.0064\nyaw_rad = -2e-3\nload_left_N = 50e3\n"
      "load_right_N = 60e3\nspeed_m_s = 22\ncurve_radius_m = -500\n";
  std::vector<double> reasons;
  for (const char* limit : {"", "max_contact_angle_rad = 1.0\n"}) {
    const std::string text = "[contact]\ngrid_nx = 12\ngrid_ny = 12\n" + std::string(limit) +
                             "[run]\ndistance_m = 1000\n" + states;
    const fs::path out = dir_ / (std::string(limit).empty() ? "default.h5" : "limit.h5");
    run(text, out);
    const ResultsFile file = ResultsFile::read(out);
    const auto reason = file.read_step_array(0, "states/drop_reason");
    ASSERT_EQ(reason.size(), 2u);
    EXPECT_EQ(reason[0], 0.0);  // the left wheel on its tread
    reasons.push_back(reason[1]);
  }
  EXPECT_EQ(reasons, (std::vector<double>{4.0, 2.0}));  // Nadal, then climbing
  EXPECT_EQ(parse_scene(
                "[contact]\nmax_contact_angle_rad = 1.5\n[run]\ndistance_m = 1000\n" + states, dir_)
                .max_contact_angle,
            1.5);
  for (const char* bad : {"0.5", "1.6", "nan"}) {
    try {
      parse_scene("[contact]\nmax_contact_angle_rad = " + std::string(bad) + "\n" + states, dir_);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("max_contact_angle_rad"), std::string::npos);
    }
  }
}

TEST_F(WearRunTest, SeparateWheelsOfAMirroredCollectiveWearAlike) {
  // A state and its mirror image: the left wheel of one is the right wheel of the other, so
  // separately evolved left and right profiles stay identical, and equal the shared profile.
  const std::string states =
      "[[load_collective.state]]\ndy_m = 0.003\nyaw_rad = 1e-3\nload_left_N = 60e3\n"
      "load_right_N = 50e3\nspeed_m_s = 30\ncurve_radius_m = 1000\n"
      "[[load_collective.state]]\ndy_m = -0.003\nyaw_rad = -1e-3\nload_left_N = 50e3\n"
      "load_right_N = 60e3\nspeed_m_s = 30\ncurve_radius_m = -1000\n";
  const std::string common =
      "[contact]\ngrid_nx = 10\ngrid_ny = 10\nstrip_width_m = 0.2e-3\n"
      "[run]\ndistance_m = 20e3\nstep_distance_m = 10e3\n";
  const fs::path separate = dir_ / "separate.h5", shared = dir_ / "shared.h5";
  run(common + "wheels = \"separate\"\n" + states, separate);
  run(common + states, shared);
  const ResultsFile fs_ = ResultsFile::read(separate), fh = ResultsFile::read(shared);
  ASSERT_EQ(fs_.completed_steps(), 3);
  for (int step = 0; step < 3; ++step) {
    EXPECT_EQ(fs_.read_step_array(step, "wheel_left/z"),
              fs_.read_step_array(step, "wheel_right/z"));
    const auto left = fs_.read_step_array(step, "wheel_left/wear_rate/depth");
    const auto one = fh.read_step_array(step, "wheel/wear_rate/depth");
    ASSERT_EQ(left.size(), one.size());
    // The shared profile weighs each wheel by one half: the same sum up to rounding.
    for (std::size_t i = 0; i < left.size(); ++i) EXPECT_NEAR(left[i], one[i], 1e-12 * one[i]);
  }
}

// Largest second difference of a step's wear depth, relative to its peak: how ragged it is.
double raggedness(const std::vector<double>& depth) {
  double peak = 0.0, worst = 0.0;
  for (double d : depth) peak = std::max(peak, d);
  for (std::size_t i = 1; i + 1 < depth.size(); ++i)
    worst = std::max(worst, std::abs(depth[i - 1] - 2 * depth[i] + depth[i + 1]));
  return peak > 0.0 ? worst / peak : 0.0;
}

// Integral of |z_a - z_b| over the worn width (y from -40 to 50 mm) [m^2]: how far apart two
// profiles are, without the cancellation a signed area would allow.
double distance_between(const ResultsFile& a, const ResultsFile& b, int step_a, int step_b) {
  const profiles::Profile pa(
      points(a.read_step_array(step_a, "wheel/y"), a.read_step_array(step_a, "wheel/z")),
      {"a", profiles::Body::wheel});
  const profiles::Profile pb(
      points(b.read_step_array(step_b, "wheel/y"), b.read_step_array(step_b, "wheel/z")),
      {"b", profiles::Body::wheel});
  double sum = 0.0;
  const double dy = 0.05e-3;
  for (double y = -0.040; y <= 0.050; y += dy) sum += std::abs(*pa.z_at(y) - *pb.z_at(y)) * dy;
  return sum;
}

TEST_F(WearRunTest, LargeStepsConvergeToSmallSteps) {
  // Tread contact (tangent track, a wide curve): 8000 km with the deepest increment of a step
  // limited to 0.25, 0.1 and 0.02 mm.
  auto scene = [](double max_depth) {
    return "[contact]\ngrid_nx = 12\ngrid_ny = 12\nstrip_width_m = 0.2e-3\n"
           "[run]\ndistance_m = 8e6\nstep_distance_m = 1e9\nmax_depth_step_m = " +
           std::to_string(max_depth) +
           "\n[[load_collective.state]]\ndy_m = 0.001\nyaw_rad = 2e-4\naxle_load_N = 110e3\n"
           "speed_m_s = 40\nlateral_velocity_m_s = 0.01\nweight = 3\n"
           "[[load_collective.state]]\ndy_m = -0.002\nyaw_rad = -3e-4\naxle_load_N = 110e3\n"
           "speed_m_s = 40\nweight = 3\n"
           "[[load_collective.state]]\ndy_m = 0.004\nyaw_rad = 1e-3\nload_left_N = 60e3\n"
           "load_right_N = 50e3\nspeed_m_s = 30\ncurve_radius_m = 1000\n";
  };
  const fs::path coarse = dir_ / "coarse.h5", medium = dir_ / "medium.h5", fine = dir_ / "fine.h5";
  run(scene(0.25e-3), coarse);
  run(scene(0.1e-3), medium);
  run(scene(0.02e-3), fine);
  const ResultsFile c = ResultsFile::read(coarse), m = ResultsFile::read(medium),
                    f = ResultsFile::read(fine);
  EXPECT_LT(3 * c.completed_steps(), f.completed_steps());
  const int lc = c.completed_steps() - 1, lm = m.completed_steps() - 1,
            lf = f.completed_steps() - 1;
  const double worn = distance_between(f, f, lf, 0);
  const double error_coarse = distance_between(c, f, lc, lf);
  const double error_medium = distance_between(m, f, lm, lf);
  // The update is an explicit (first-order) integration of the evolution: its error shrinks in
  // proportion to the step, (0.1 - 0.02)/(0.25 - 0.02) = 0.35 here; 0.6 leaves room for the
  // steps' uneven lengths. An oscillating update would not converge at all.
  EXPECT_LT(error_medium, 0.6 * error_coarse);
  // Even the coarse steps stay within half of the wear itself.
  EXPECT_LT(error_coarse, 0.5 * worn);
}

TEST_F(WearRunTest, LargeStepsWithFlangeContactStaySmooth) {
  // Flange contact moves the wear abruptly as the profile changes: 0.25 mm steps still give a
  // smooth increment every step.
  const fs::path out = dir_ / "large.h5";
  run(small_scene(4e6, 1e9, 0.25e-3), out);
  const ResultsFile c = ResultsFile::read(out);
  ASSERT_GE(c.completed_steps(), 4);
  for (int step = 0; step + 1 < c.completed_steps(); ++step) {
    const auto depth = c.read_step_array(step, "wheel/wear_step/depth");
    // A smooth depth on 0.1 mm bins changes its slope by far less than its peak per bin; a
    // ragged one (alternating bins) by about twice its peak.
    EXPECT_LT(raggedness(depth), 0.5) << "step " << step;
    // No step exceeds its depth limit (the smoothed increment is what the limit applies to).
    EXPECT_LE(*std::max_element(depth.begin(), depth.end()), 0.25e-3 * (1 + 1e-12));
  }
}

}  // namespace
}  // namespace wheelwear::pipeline
