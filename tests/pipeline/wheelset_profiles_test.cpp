// Each wheelset's own profiles and the running direction of a vehicle run: against the shared
// profile (the eight wheels' mean wear is the shared wear: every wheel case counted once), the
// vehicle's symmetry (run backwards, the physical wheelsets wear in mirror order) and the
// weighting of both directions (half the distance each way: the mean of the two runs).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "short_route.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

// The short route solved quasi-statically (every section a running condition: a right-hand
// R 3000 m curve, a transition's midpoint, tangent track) in `direction`, each wheelset wearing
// its own profiles when `separate`.
Scene route_scene(RunningDirection direction, bool separate) {
  Scene scene = parse_scene(
      "[contact]\ngrid_nx = 12\ngrid_ny = 12\n[load_collective]\n[[load_collective.state]]\n"
      "axle_load_N = 1e5\nspeed_m_s = 40\n",
      {});
  VehicleRun run = short_route_run();
  run.direction = direction;
  scene.vehicle_run = run;
  scene.separate_wheels = separate;
  return scene;
}

// The rates of the vehicle's collective on new S1002 wheels, one per profile of the layout.
std::vector<wear::WearDistribution> route_rates(const Scene& scene) {
  const CollectiveEvaluator evaluator(scene);
  const profiles::Profile wheel = profiles::wheel_profile("S1002", 0.46, {});
  const std::vector<const profiles::Profile*> wheels(profile_count(profile_layout(scene)), &wheel);
  const VehicleCollective v =
      solve_vehicle_collective(*scene.vehicle_run, evaluator.kernel(), wheels);
  EXPECT_EQ(v.unconverged, 0);
  return evaluator.evaluate(wheels, v.states).rate;
}

double peak(const wear::WearDistribution& rate) {
  return *std::max_element(rate.depth.begin(), rate.depth.end());
}

// The largest difference between two rates over the peak of the first.
double largest_difference(const wear::WearDistribution& a, const wear::WearDistribution& b) {
  EXPECT_EQ(a.depth.size(), b.depth.size());
  double d = 0.0;
  for (std::size_t k = 0; k < a.depth.size(); ++k)
    d = std::max(d, std::abs(a.depth[k] - b.depth[k]));
  return d / peak(a);
}

TEST(WheelsetProfiles, TheEightWheelsMeanWearIsTheSharedWear) {
  const std::vector<wear::WearDistribution> shared =
      route_rates(route_scene(RunningDirection::forward, false));
  const std::vector<wear::WearDistribution> own =
      route_rates(route_scene(RunningDirection::forward, true));
  ASSERT_EQ(shared.size(), 1u);
  ASSERT_EQ(own.size(), 8u);
  // Each wheel case is counted once in either layout, with its state's share over the wheels a
  // profile carries: the eight profiles' mean is the shared rate, up to the rounding of sums of
  // a few hundred terms (1e-12 of the peak).
  wear::WearDistribution mean = shared.front();
  std::fill(mean.depth.begin(), mean.depth.end(), 0.0);
  for (const auto& r : own)
    for (std::size_t k = 0; k < r.depth.size(); ++k) mean.depth[k] += r.depth[k] / 8.0;
  EXPECT_LT(largest_difference(shared.front(), mean), 1e-12);
  // And the wheels differ: in the right-hand curve the leading wheelsets' outer (left) wheels
  // against the trailing ones', and left against right.
  const double leading_trailing = largest_difference(own[0], own[2]);
  const double left_right = largest_difference(own[0], own[1]);
  EXPECT_GT(leading_trailing, 0.01);
  EXPECT_GT(left_right, 0.01);
  std::printf("bins %zu; leading vs trailing outer wheel %.3f, left vs right %.3f of the peak\n",
              mean.depth.size(), leading_trailing, left_right);
}

// The built-in coach is symmetric front to back and the new wheels left to right: run backwards
// over the same track (its curve now left-hand in travel) the physical wheelset 4 - j wears as
// wheelset j + 1 forwards, each wheel on its own physical side (the outer rail is the same
// rail). The two runs' quasi-static solves converge independently, to balances within 1e-7 m g:
// the rates agree to far better than 1e-6 of the peak.
TEST(WheelsetProfiles, RunBackwardsThePhysicalWheelsetsWearInMirrorOrder) {
  const std::vector<wear::WearDistribution> forward =
      route_rates(route_scene(RunningDirection::forward, true));
  const std::vector<wear::WearDistribution> backward =
      route_rates(route_scene(RunningDirection::reverse, true));
  ASSERT_EQ(forward.size(), 8u);
  ASSERT_EQ(backward.size(), 8u);
  double largest = 0.0;
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t side = 0; side < 2; ++side)
      largest = std::max(largest,
                         largest_difference(forward[2 * j + side], backward[2 * (3 - j) + side]));
  EXPECT_LT(largest, 1e-6);
  // The direction matters: the physical wheelset 1 leads one way and trails the other.
  EXPECT_GT(largest_difference(forward[0], backward[0]), 0.01);
  std::printf("8 profiles compared, largest mirror difference %.2e of the peak\n", largest);
}

// Half the distance each way: each profile's rate is the mean of the two directions' (the same
// states, each with half its share), to rounding.
TEST(WheelsetProfiles, BothDirectionsWearTheMeanOfEach) {
  const auto forward = route_rates(route_scene(RunningDirection::forward, true));
  const auto backward = route_rates(route_scene(RunningDirection::reverse, true));
  const auto both = route_rates(route_scene(RunningDirection::both, true));
  ASSERT_EQ(both.size(), 8u);
  double largest = 0.0;
  for (std::size_t p = 0; p < 8; ++p) {
    wear::WearDistribution mean = forward[p];
    for (std::size_t k = 0; k < mean.depth.size(); ++k)
      mean.depth[k] = 0.5 * (forward[p].depth[k] + backward[p].depth[k]);
    largest = std::max(largest, largest_difference(mean, both[p]));
  }
  EXPECT_LT(largest, 1e-12);
  std::printf("8 profiles compared, largest difference %.2e of the peak\n", largest);
}

// Both ways with the time domain: each tangent and transition is simulated in either direction,
// the backward pieces along the reversed route (its transition leads into a left-hand curve),
// from backward start cases, with irregularities of their own; every state says which physical
// wheelset it is and which way it ran.
TEST(WheelsetProfiles, BackwardPiecesRunTheReversedRoute) {
  const Scene scene = route_scene(RunningDirection::both, true);
  VehicleRun run = *scene.vehicle_run;
  run.time_domain.enabled = true;
  run.time_domain.tangent_length = 20.0;
  run.time_domain.run_in = 10.0;
  run.time_domain.sample_distance = 2.0;
  const RoutePlan plan = route_plan(run);
  ASSERT_EQ(plan.pieces.size(), 4u);  // the transition and the tangent, each way
  double total = 0.0;
  for (const RouteCase& c : plan.cases) {
    total += c.share;
    // A curve's name is the forward way's: backwards its label says the hand it has now.
    if (c.reversed && c.curve.running.curve_radius < 0.0) {
      EXPECT_NE(c.label.find("(left-hand this way)"), std::string::npos) << c.label;
    }
  }
  for (const DynamicPiece& p : plan.pieces) {
    total += p.share;
    EXPECT_EQ(plan.cases[p.start_case].reversed, p.reversed);
    EXPECT_EQ(p.label.rfind("backwards, ", 0) == 0, p.reversed) << p.label;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_NE(plan.pieces[2].seed, plan.pieces[0].seed);
  EXPECT_NE(plan.pieces[3].seed, plan.pieces[1].seed);

  const StateKernel kernel(scene);
  const profiles::Profile wheel = profiles::wheel_profile("S1002", 0.46, {});
  const std::vector<const profiles::Profile*> wheels(8, &wheel);
  const VehicleCollective v = solve_vehicle_collective(run, kernel, wheels);
  EXPECT_EQ(v.incomplete(), 0);
  int forward = 0, backward = 0;
  std::array<int, 4> per_wheelset{};
  for (const WheelsetStateSpec& s : v.states) {
    ASSERT_GE(s.wheelset, 0);
    ++per_wheelset[static_cast<std::size_t>(s.wheelset)];
    // The right-hand R 3000 m curve, met backwards, is left-hand.
    if (s.reversed) {
      ++backward;
      EXPECT_LE(s.curve_radius, 0.0) << s.label;
    } else {
      ++forward;
      EXPECT_GE(s.curve_radius, 0.0) << s.label;
    }
  }
  EXPECT_GT(forward, 40);
  EXPECT_GT(backward, 40);
  for (int n : per_wheelset) EXPECT_GT(n, 20);
  std::printf("%d forward and %d backward states\n", forward, backward);
}

// A state without a wheelset cannot wear per-wheelset profiles; one with a wheelset out of range
// is refused when read.
TEST(WheelsetProfiles, StatesNameTheirWheelset) {
  WheelsetStateSpec s;
  s.label = "hand-written";
  EXPECT_THROW(worn_profiles(s, ProfileLayout::per_wheelset), InputError);
  s.wheelset = 2;
  s.reversed = true;
  EXPECT_EQ(worn_profiles(s, ProfileLayout::per_wheelset), (std::array<std::size_t, 2>{5, 4}));
  EXPECT_EQ(worn_profiles(s, ProfileLayout::left_right), (std::array<std::size_t, 2>{1, 0}));
  EXPECT_EQ(worn_profiles(s, ProfileLayout::shared), (std::array<std::size_t, 2>{0, 0}));
  EXPECT_THROW(parse_scene("[load_collective]\n[[load_collective.state]]\naxle_load_N = 1e5\n"
                           "speed_m_s = 40\nwheelset = 5\n",
                           {}),
               InputError);
  EXPECT_THROW(parse_scene("[load_collective]\n[[load_collective.state]]\naxle_load_N = 1e5\n"
                           "speed_m_s = 40\nwheelset = 1.5\n",
                           {}),
               InputError);
  const auto names = profile_names(ProfileLayout::per_wheelset);
  ASSERT_EQ(names.size(), 8u);
  EXPECT_EQ(names[5], "wheelsets/3/wheel_right");
}

class WheelsetProfilesRunTest : public WearRunTest {};

// A run that wears each wheelset's profiles in both directions records them under
// wheelsets/K/ with their parameters and conicity, and its collective keeps each state's
// wheelset and direction, so a killed run resumes to identical results.
TEST_F(WheelsetProfilesRunTest, RecordsEachWheelsetAndResumesToIdenticalResults) {
  write("route.toml", kShortRoute);
  const std::string text =
      "[contact]\ngrid_nx = 12\ngrid_ny = 12\n[run]\ndistance_m = 2000\nstep_distance_m = 1000\n"
      "max_depth_step_m = 1e-3\nwheels = \"separate\"\n[vehicle]\nfile = \"default\"\n"
      "resolve_depth_m = 0\ncritical_speed = false\n[route]\nfile = \"route.toml\"\n"
      "direction = \"both\"\n[time_domain]\nenabled = false\n";
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run(text, reference);
  const ResultsFile ref = ResultsFile::read(reference);
  ASSERT_EQ(ref.completed_steps(), 3);
  int compared = 0;
  for (int k = 1; k <= 4; ++k) {
    for (const char* side : {"wheel_left", "wheel_right"}) {
      const std::string wheel = "wheelsets/" + std::to_string(k) + "/" + side;
      // The new S1002's flange thickness (EN 15313: 32.5 mm) on every wheel at the start.
      EXPECT_NEAR(ref.read_step_array(0, wheel + "/Sd").at(0), 32.5e-3, 0.05e-3) << wheel;
      EXPECT_GT(ref.read_step_array(1, wheel + "/y").size(), 100u) << wheel;
      compared += 2;
    }
    EXPECT_EQ(
        ref.read_step_array(0, "wheelsets/" + std::to_string(k) + "/equivalent_conicity").size(),
        1u);
  }
  // Three conditions each way, four wheelsets: 24 states, each physical wheelset 6 times.
  const auto wheelset = ref.read_step_array(0, "collective/wheelset");
  const auto reversed = ref.read_step_array(0, "collective/reversed");
  ASSERT_EQ(wheelset.size(), 24u);
  for (int k = 1; k <= 4; ++k)
    EXPECT_EQ(std::count(wheelset.begin(), wheelset.end(), static_cast<double>(k)), 6) << k;
  EXPECT_EQ(std::count(reversed.begin(), reversed.end(), 1.0), 12);
  compared += 5;

  RunOptions stop;
  stop.progress = [](const RunProgress& p) {
    if (p.step == 1) throw std::runtime_error("interrupted");
  };
  EXPECT_THROW(run_scene(parse_scene(text, dir_), text, dir_, false, killed, stop),
               std::runtime_error);
  resume_run(killed, {});
  const ResultsFile res = ResultsFile::read(killed);
  ASSERT_EQ(res.completed_steps(), 3);
  for (int step = 0; step < 3; ++step) {
    expect_same_arrays(ref, res, step, "", compared);
    ASSERT_FALSE(HasFatalFailure());
  }
  EXPECT_GT(compared, 1000);
  std::printf("compared %d values\n", compared);
}

// The direction is a word; a route that ends with a transition cannot be run backwards.
TEST_F(WheelsetProfilesRunTest, DirectionKeyAndItsErrors) {
  write("route.toml", kShortRoute);
  const std::string base =
      "[vehicle]\nfile = \"default\"\n[route]\nfile = \"route.toml\"\ndirection = ";
  EXPECT_EQ(parse_scene(base + "\"both\"\n", dir_).vehicle_run->direction, RunningDirection::both);
  EXPECT_EQ(parse_scene(base + "\"reverse\"\n", dir_).vehicle_run->direction,
            RunningDirection::reverse);
  EXPECT_THROW(parse_scene(base + "\"backwards\"\n", dir_), InputError);
  std::string open_end = kShortRoute;
  open_end = open_end.substr(0, open_end.rfind("[[section]]"));
  write("open.toml", open_end);
  const std::string open_scene =
      "[vehicle]\nfile = \"default\"\n[route]\nfile = \"open.toml\"\ndirection = ";
  EXPECT_NO_THROW(parse_scene(open_scene + "\"forward\"\n", dir_));
  try {
    parse_scene(open_scene + "\"both\"\n", dir_);
    ADD_FAILURE() << "a route ending with a transition was run backwards";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ends with a transition"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wheelwear::pipeline
