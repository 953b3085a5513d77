// A run spread over the processes of a job: the results file is bit-identical to the
// single-process run's for any number of processes, also resumed with another number. The
// processes are threads here (thread_group.hpp); tests/mpi runs the same under mpirun.

#include "wheelwear/pipeline/distributed_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "short_route.hpp"
#include "thread_group.hpp"
#include "wear_run_support.hpp"
#include "wire.hpp"

namespace wheelwear::pipeline {
namespace {

class DistributedRunTest : public WearRunTest {
 protected:
  // Runs `text` into `out` over `processes` threads acting as processes; returns the exit
  // status process 0 gave the others, as they received it.
  RunSummary distributed(const std::string& text, const fs::path& out, int processes,
                         bool resume = false) {
    RunSummary summary;
    std::vector<int> codes(static_cast<std::size_t>(processes), -1);
    run_thread_group(
        processes,
        [&](ProcessGroup& group) {
          StepDistributor distributor(group);
          RunOptions options;
          options.distributor = &distributor;
          try {
            summary = resume ? resume_run(out, options)
                             : run_scene(parse_scene(text, dir_), text, dir_, false, out, options);
          } catch (const std::exception& e) {
            ADD_FAILURE() << e.what();
          }
          distributor.finish(0);
        },
        [&](ProcessGroup& group) {
          codes[static_cast<std::size_t>(group.rank())] = serve_steps(group);
        });
    for (int r = 1; r < processes; ++r) EXPECT_EQ(codes[static_cast<std::size_t>(r)], 0) << r;
    return summary;
  }
};

// Shared and separate wheels, state summaries and T gamma maps: every dataset of every step
// equal, bit for bit, over 2 and 3 processes; every state evaluated once and gathered.
TEST_F(DistributedRunTest, FilesAreBitIdenticalToOneProcessForAnyNumber) {
  for (const char* wheels : {"shared", "separate"}) {
    std::string scene =
        small_scene(3000, 1000, 1e-3) + "[output]\nstate_summaries = true\ntgamma_maps = true\n";
    scene.replace(scene.find("[run]\n"), 6, std::string("[run]\nwheels = \"") + wheels + "\"\n");
    const fs::path one = dir_ / "one.h5";
    fs::remove(one);
    const RunSummary alone = run(scene, one);
    for (int processes : {2, 3}) {
      const fs::path many = dir_ / ("many" + std::to_string(processes) + ".h5");
      fs::remove(many);
      const RunSummary spread = distributed(scene, many, processes);
      expect_identical_runs(one, many);
      EXPECT_EQ(spread.processes, processes);
      EXPECT_EQ(spread.evaluations, alone.evaluations);
      // Each geometry solved by one process only: the reuse is kept whole.
      EXPECT_EQ(spread.geometry_solves, alone.geometry_solves);
      EXPECT_GT(spread.gathered_bytes, 0u);
    }
  }
}

// A vehicle run (its conditions and pieces spread at each solve, its critical speed searched by
// process 0 meanwhile, its states sent along) over 3 processes, stopped after its first step
// and resumed over 2: the file of the uninterrupted single run.
TEST_F(DistributedRunTest, VehicleRunStoppedAndResumedWithAnotherNumberOfProcesses) {
  write("route.toml", kShortRoute);
  const std::string text =
      "[contact]\ngrid_nx = 12\ngrid_ny = 12\n[run]\ndistance_m = 2000\nstep_distance_m = 1000\n"
      "max_depth_step_m = 1e-3\n[vehicle]\nfile = \"default\"\nresolve_depth_m = 0\n"
      "[route]\nfile = \"route.toml\"\n[time_domain]\n"
      "tangent_length_m = 40\nrun_in_m = 10\nsample_distance_m = 2\n";
  const fs::path one = dir_ / "one.h5", stopped = dir_ / "stopped.h5";
  run(text, one);
  ASSERT_EQ(ResultsFile::read(one).completed_steps(), 3);
  run_thread_group(
      3,
      [&](ProcessGroup& group) {
        StepDistributor distributor(group);
        RunOptions options;
        options.distributor = &distributor;
        options.progress = [](const RunProgress& p) {
          if (p.step == 1) throw std::runtime_error("stopped");
        };
        try {
          run_scene(parse_scene(text, dir_), text, dir_, false, stopped, options);
          ADD_FAILURE() << "not stopped";
        } catch (const std::exception& e) {
          EXPECT_STREQ(e.what(), "stopped");
        }
        EXPECT_FALSE(distributor.busy());  // stopped between steps: the others can be released
        distributor.finish(5);
      },
      [&](ProcessGroup& group) { EXPECT_EQ(serve_steps(group), 5); });
  ASSERT_EQ(ResultsFile::read(stopped).completed_steps(), 2);
  distributed("", stopped, 2, true);
  expect_identical_runs(one, stopped);
}

// The bytes between processes: what is read back is what was written, bit for bit (NaN,
// signed zero, optionals, cell fields), and a truncated message is refused, not misread.
TEST(Wire, OutcomesAndStatesRoundTripBitForBit) {
  StateOutcome state;
  state.roll = -0.0;
  WheelOutcome& wheel = state.wheels[1];
  wheel.status = contactgeom::WheelRailStatus::load_jump;
  wheel.lateral_fit = contactgeom::LateralFit::kept_position;
  wheel.dy = std::numeric_limits<double>::quiet_NaN();
  wheel.nadal.exceeded = true;
  wheel.contact_patches = 3;
  wheel.hertz_dropped = 1;
  PatchOutcome patch;
  patch.sdec = {4e-3, 3e-3, -0.25};
  patch.creepages = {1e-3, -2e-4, 0.3};
  patch.solution.forces.Mz = 12.5;
  patch.solution.table_outside = "a/b 30";
  patch.solution.from_table = true;
  tangential::CellFields fields;
  fields.nx = 2;
  fields.work = {1.0, std::nextafter(1.0, 2.0)};
  fields.slip = {0, 1};
  patch.solution.fields = fields;
  patch.wear.first = 17;
  patch.wear.depth = {1e-12, 3e-12};
  wheel.patches = {patch, PatchOutcome{}};
  WheelsetStateSpec spec;
  spec.label = "R500, wheelset 2";
  spec.lateral_force_right = 25e3;
  spec.creepages_left = tangential::Creepages{1e-3, 2e-3, 0.1};
  spec.wheelset = 2;
  spec.reversed = true;

  detail::WireWriter w;
  detail::write(w, std::vector<StateOutcome>{state, StateOutcome{}});
  detail::write(w, std::vector<WheelsetStateSpec>{spec});
  const std::string bytes = w.take();
  detail::WireReader r(bytes);
  const std::vector<StateOutcome> states = detail::read_outcomes(r);
  const std::vector<WheelsetStateSpec> specs = detail::read_specs(r);
  EXPECT_TRUE(r.done());
  ASSERT_EQ(states.size(), 2u);
  const WheelOutcome& back = states[0].wheels[1];
  EXPECT_TRUE(std::signbit(states[0].roll));
  EXPECT_TRUE(std::isnan(back.dy));
  EXPECT_EQ(back.status, wheel.status);
  EXPECT_EQ(back.lateral_fit, wheel.lateral_fit);
  EXPECT_EQ(back.drop_reason(), DropReason::load_jump);
  EXPECT_EQ(back.contact_patches, 3u);
  EXPECT_EQ(back.hertz_dropped, 1);
  ASSERT_EQ(back.patches.size(), 2u);
  const PatchOutcome& p = back.patches[0];
  EXPECT_EQ(p.sdec.psi, -0.25);
  EXPECT_EQ(p.creepages.phi, 0.3);
  EXPECT_EQ(p.solution.forces.Mz, 12.5);
  EXPECT_EQ(p.solution.table_outside, "a/b 30");
  EXPECT_TRUE(p.solution.from_table);
  ASSERT_TRUE(p.solution.fields);
  EXPECT_EQ(p.solution.fields->work, fields.work);
  EXPECT_EQ(p.solution.fields->slip, fields.slip);
  EXPECT_EQ(p.wear.first, 17u);
  EXPECT_EQ(p.wear.depth, patch.wear.depth);
  EXPECT_FALSE(back.patches[1].solution.fields);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].label, spec.label);
  EXPECT_EQ(specs[0].lateral_force_right, 25e3);
  EXPECT_FALSE(specs[0].lateral_force_left);
  EXPECT_EQ(specs[0].creepages_left->vy, 2e-3);
  EXPECT_EQ(specs[0].wheelset, 2);
  EXPECT_TRUE(specs[0].reversed);

  const std::string cut = bytes.substr(0, bytes.size() / 2);
  detail::WireReader truncated(cut);
  EXPECT_THROW(
      {
        detail::read_outcomes(truncated);
        detail::read_specs(truncated);
      },
      std::runtime_error);
}

// The shares of the processes partition the states, keep states of one geometry together and
// spread the geometries evenly.
TEST(StateOwners, PartitionByGeometry) {
  const std::string text = small_scene(1000, 1000, 1e-3);
  Scene scene = parse_scene(text, {});
  // Two more states in the geometry of the first (they differ in yaw only).
  for (double yaw : {5e-4, -5e-4}) {
    scene.states.push_back(scene.states[0]);
    scene.states.back().yaw = yaw;
  }
  const CollectiveEvaluator evaluator(scene);
  const std::vector<int> owner = evaluator.owners(scene.states, 3);
  ASSERT_EQ(owner.size(), scene.states.size());
  EXPECT_EQ(owner[4], owner[0]);
  EXPECT_EQ(owner[5], owner[0]);
  std::vector<int> count(3, 0);
  for (std::size_t i = 0; i < 4; ++i) ++count[static_cast<std::size_t>(owner[i])];
  EXPECT_EQ(count, (std::vector<int>{2, 1, 1}));  // four geometries dealt out in turn
}

}  // namespace
}  // namespace wheelwear::pipeline
