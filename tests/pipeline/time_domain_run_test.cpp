// The time-domain pieces of a vehicle run: the plan of a route (pieces cover its tangents and
// transitions, the shares sum to one, every wheelset runs through its stretch after the run-in),
// the irregularities a piece runs over, and the states its simulation gives: their weights, the
// wear kernel meeting the dynamics' forces at every sample, ideal track giving the quasi-static
// state, independence of the number of threads, and the scene's keys.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "short_route.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

TimeDomainKeys short_keys() {
  TimeDomainKeys keys;
  keys.tangent_length = 20.0;
  keys.run_in = 10.0;
  keys.sample_distance = 2.0;
  return keys;
}

TEST(RoutePlan, DefaultRoutePiecesCoverTangentsAndTransitions) {
  const vehicle::Route route = vehicle::default_route();
  const vehicle::Vehicle car = vehicle::default_vehicle();
  const TimeDomainKeys keys;
  const RoutePlan plan = route_plan(route, keys, car);
  // data/routes/default.toml: 5 tangents and 14 transitions are simulated, 10 curves solved.
  ASSERT_EQ(plan.pieces.size(), 19u);
  double curves = 0.0, pieces = 0.0;
  for (const RouteCase& c : plan.cases) {
    if (c.share > 0.0) {
      EXPECT_NE(c.curve.running.curve_radius, 0.0) << c.label;
    }
    curves += c.share;
  }
  // The route file's table: 45 km of curves and 55 km of tangents and transitions in 100 km.
  EXPECT_NEAR(curves, 0.45, 1e-12);
  const std::vector<double> starts = route.section_starts();
  std::set<std::uint64_t> seeds;
  for (const DynamicPiece& p : plan.pieces) {
    pieces += p.share;
    const vehicle::RouteSection& section = route.sections[p.section];
    ASSERT_NE(section.kind, vehicle::SectionKind::curve);
    EXPECT_EQ(p.share, section.length_m / route.total_length());
    EXPECT_EQ(p.speed, section.speed_m_s);
    if (section.kind == vehicle::SectionKind::tangent) {
      // The middle 200 m of a tangent.
      EXPECT_EQ(p.length_m, 200.0);
      EXPECT_NEAR(p.start_m + 100.0, starts[p.section] + 0.5 * section.length_m, 1e-9);
    } else {
      EXPECT_EQ(p.length_m, section.length_m);
      EXPECT_EQ(p.start_m, starts[p.section]);
    }
    // Every wheelset runs at least the run-in before the stretch and through all of it.
    for (int k = 0; k < vehicle::kWheelsets; ++k) {
      const double x = car.wheelset_x(k);
      EXPECT_LE(p.sim_start_m + x, p.start_m + 1e-9) << p.label << ", wheelset " << k + 1;
      EXPECT_GE(p.sim_start_m + p.sim_length_m + x, p.start_m + p.length_m - 1e-9);
    }
    // It starts from the quasi-static state of the track where the car body starts.
    const vehicle::TrackPoint at = vehicle::track_at(route, p.sim_start_m - keys.run_in);
    const RouteCase& start = plan.cases.at(p.start_case);
    EXPECT_EQ(start.curve.running.curve_radius, at.radius_m) << p.label;
    EXPECT_EQ(start.curve.cant, at.cant_m) << p.label;
    EXPECT_EQ(start.curve.running.speed, p.speed) << p.label;
    seeds.insert(p.seed);
  }
  EXPECT_NEAR(pieces, 0.55, 1e-12);
  EXPECT_EQ(seeds.size(), plan.pieces.size());  // every section draws its own track

  // Without the time domain: every section's condition, as before.
  TimeDomainKeys off;
  off.enabled = false;
  const RoutePlan quasi_static = route_plan(route, off, car);
  EXPECT_TRUE(quasi_static.pieces.empty());
  ASSERT_EQ(quasi_static.cases.size(), route_cases(route).size());

  // Transitions quasi-statically: only the 5 tangents simulated; the 14 transitions join the
  // curves as conditions at their midpoints, so the shares still sum to the whole route.
  TimeDomainKeys tangents_only;
  tangents_only.simulate_transitions = false;
  const RoutePlan mixed = route_plan(route, tangents_only, car);
  ASSERT_EQ(mixed.pieces.size(), 5u);
  double total = 0.0;
  int transitions = 0;
  for (const DynamicPiece& p : mixed.pieces) {
    EXPECT_EQ(route.sections[p.section].kind, vehicle::SectionKind::tangent);
    total += p.share;
  }
  for (const RouteCase& c : mixed.cases) {
    total += c.share;
    transitions += c.label.find("transition") != std::string::npos && c.share > 0.0 ? 1 : 0;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_GT(transitions, 0);

  for (auto bad : {&TimeDomainKeys::tangent_length, &TimeDomainKeys::sample_distance}) {
    TimeDomainKeys k;
    k.*bad = 0.0;
    EXPECT_THROW(route_plan(route, k, car), InputError);
    k.*bad = NAN;
    EXPECT_THROW(route_plan(route, k, car), InputError);
  }
  TimeDomainKeys k;
  k.run_in = -1.0;
  EXPECT_THROW(route_plan(route, k, car), InputError);
}

TEST(PieceIrregularities, FadedInOverTheStretchAndSeededPerSection) {
  const vehicle::Route route = vehicle::default_route();
  const vehicle::Vehicle car = vehicle::default_vehicle();
  TimeDomainKeys keys;
  const RoutePlan plan = route_plan(route, keys, car);
  const DynamicPiece& piece = plan.pieces[0];
  const vehicle::TrackIrregularities low = piece_irregularities(piece, keys, car);
  // From where the leading wheelset starts, faded in from zero, to past where it ends.
  const double lead = car.wheelset_x(0);
  EXPECT_NEAR(low.distance.front(), piece.sim_start_m - keys.run_in + lead, 1e-9);
  EXPECT_GE(low.distance.back(), piece.sim_start_m + piece.sim_length_m + lead);
  EXPECT_EQ(low.alignment.front(), 0.0);
  EXPECT_EQ(low.cross_level.front(), 0.0);

  // The same seed draws the same frequencies and phases: the high level's alignment is the low
  // level's times sqrt(A_a high / A_a low) at every sample (the spectra differ only in A_a and
  // A_v), and its cross-level times sqrt(A_v high / A_v low).
  keys.irregularities = IrregularitySource::erri_high;
  const vehicle::TrackIrregularities high = piece_irregularities(piece, keys, car);
  ASSERT_EQ(high.distance.size(), low.distance.size());
  const double a = std::sqrt(6.125e-7 / 2.119e-7), v = std::sqrt(1.080e-6 / 4.032e-7);
  double largest = 0.0;
  for (std::size_t i = 0; i < low.distance.size(); ++i) {
    // 1e-12 m: the sums of 1000 cosines of amplitudes ~1e-5 m differ in their rounding only.
    EXPECT_NEAR(high.alignment[i], a * low.alignment[i], 1e-12) << i;
    EXPECT_NEAR(high.cross_level[i], v * low.cross_level[i], 1e-12) << i;
    largest = std::max(largest, std::abs(low.alignment[i]));
  }
  EXPECT_GT(largest, 1e-4);  // a real track: ERRI low alignment is ~1 mm

  // Another section draws another track.
  const vehicle::TrackIrregularities other = piece_irregularities(plan.pieces[1], keys, car);
  EXPECT_NE(other.alignment[100], high.alignment[100]);

  keys.irregularities = IrregularitySource::none;
  EXPECT_TRUE(piece_irregularities(piece, keys, car).distance.empty());
  keys.irregularities = IrregularitySource::file;
  keys.irregularity_file = "measured.csv";
  keys.measured.distance = {-100.0, 1.1e5};
  keys.measured.alignment = {1e-3, -1e-3};
  keys.measured.cross_level = {0.0, 0.0};
  EXPECT_EQ(piece_irregularities(piece, keys, car).alignment, keys.measured.alignment);
  // A record that stops short of where a piece's wheelsets run is refused, naming the file.
  keys.measured.distance = {0.0, 1000.0};
  try {
    piece_irregularities(piece, keys, car);
    ADD_FAILURE() << "a record short of the piece was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("measured.csv"), std::string::npos) << e.what();
  }
}

// The short route's collective with its pieces simulated in time, each state's kernel forces
// against the dynamics' own at the sample it came from.
class TimeDomainCollective : public ::testing::Test {
 protected:
  TimeDomainCollective()
      : scene_(parse_scene(
            // The dynamics' FASTSIM grid (VehicleMotionOptions::fastsim_grid), for the kernel.
            "[contact]\ngrid_nx = 20\ngrid_ny = 20\n[load_collective]\n"
            "[[load_collective.state]]\naxle_load_N = 1e5\nspeed_m_s = 40\n",
            {})),
        kernel_(scene_),
        wheel_(profiles::wheel_profile("S1002", 0.46, {})) {
    run_.vehicle = vehicle::default_vehicle();
    run_.route = vehicle::parse_route(kShortRoute, "test route");
    run_.time_domain = short_keys();
    run_.critical_speed = false;
  }

  // The simulation of piece `p` exactly as the collective runs it.
  vehicle::VehicleMotion simulate(const VehicleCollective& v, std::size_t p) const {
    vehicle::WheelsetModel model = wheelset_model(kernel_, wheel_, wheel_);
    model.table = contact_table(model, run_.vehicle);
    const DynamicPiece& piece = v.pieces[p];
    vehicle::VehicleMotionOptions options;
    options.run_in = run_.time_domain.run_in;
    options.sample_distance = run_.time_domain.sample_distance;
    options.speed = piece.speed;
    return vehicle::simulate_vehicle(run_.vehicle, {model, model, model, model}, run_.route,
                                     piece.sim_start_m, piece.sim_length_m,
                                     piece_irregularities(piece, run_.time_domain, run_.vehicle),
                                     vehicle::placement_of(v.curving[piece.start_case]), options);
  }

  Scene scene_;
  StateKernel kernel_;
  profiles::Profile wheel_;
  VehicleRun run_;
};

TEST_F(TimeDomainCollective, KernelMeetsTheDynamicsForcesAtEverySample) {
  const VehicleCollective v = solve_vehicle_collective(run_, kernel_, {&wheel_});
  ASSERT_EQ(v.pieces.size(), 2u);  // the transition and the tangent
  EXPECT_EQ(v.incomplete(), 0);
  double total = 0.0;
  for (const WheelsetStateSpec& s : v.states) total += s.weight;
  EXPECT_NEAR(total, 1.0, 1e-12);

  const contactgeom::WheelsetOnTrack track{kernel_.pair(wheel_), kernel_.pair(wheel_)};
  const std::vector<int> worn = run_.worn_wheelsets();
  std::size_t next = 4;  // the curve's states come first
  vehicle::WheelsetModel model = wheelset_model(kernel_, wheel_, wheel_);
  model.solve.fastsim.nx = model.solve.fastsim.ny = 20;  // the dynamics' grid
  int compared = 0;
  double fastest_yaw_creep = 0.0, fastest_lateral_creep = 0.0;
  for (std::size_t p = 0; p < v.pieces.size(); ++p) {
    const vehicle::VehicleMotion motion = simulate(v, p);
    PieceRun summary;
    const std::vector<WheelsetStateSpec> states =
        piece_states(v.pieces[p], motion, v.cases[v.pieces[p].start_case],
                     v.curving[v.pieces[p].start_case], worn, summary);
    // The collective holds this simulation's states, bit for bit.
    for (const WheelsetStateSpec& s : states) {
      ASSERT_LT(next, v.states.size());
      const WheelsetStateSpec& c = v.states[next++];
      ASSERT_EQ(s.label, c.label);
      EXPECT_EQ(s.dy, c.dy);
      EXPECT_EQ(s.yaw_rate, c.yaw_rate);
      EXPECT_EQ(s.weight, c.weight);
    }
    // Each sample's kernel forces: the same contact (solved for the vertical forces the
    // dynamics' contact carried) and the same creepages from the same motion.
    for (const vehicle::VehicleSample& sample : motion.samples)
      for (std::size_t k = 0; k < vehicle::kWheelsets; ++k) {
        const vehicle::WheelsetMotionSample& w = sample.wheelsets[k];
        const WheelsetStateSpec s = motion_state(w.state, w.forces, w.running, "sample", 1.0);
        fastest_yaw_creep = std::max(fastest_yaw_creep, std::abs(s.yaw_rate) * 0.75 / s.speed);
        fastest_lateral_creep =
            std::max(fastest_lateral_creep, std::abs(s.lateral_velocity) / s.speed);
        const contactgeom::WheelsetContact contact = kernel_.contact(track, s);
        // The dynamics' forces solved directly (its table's miss, up to ~500 N of Fx on the
        // tread, is the table's own accuracy, wheelset_table_test.cpp), with its loads Q.
        const vehicle::WheelsetForces direct =
            vehicle::wheelset_forces(model, w.state, w.load_left, w.load_right, w.running);
        for (int side = 0; side < 2; ++side) {
          const WheelOutcome out = kernel_.wheel(contact, side, s, wheel_);
          ASSERT_TRUE(out.usable());
          const contactgeom::WheelRailContact& c = side == 0 ? contact.left : contact.right;
          double Fx = 0.0, Fy = 0.0;
          for (std::size_t i = 0; i < out.patches.size(); ++i) {
            Fx += out.patches[i].solution.forces.Fx;
            Fy += out.patches[i].solution.forces.Fy * std::cos(c.patches[i].contact_angle);
          }
          const vehicle::WheelForces& f = direct.wheels[static_cast<std::size_t>(side)];
          // The kernel's contact carries the vertical forces of the dynamics' tabulated one, the
          // direct solve meets the loads Q itself: both to the dynamics' load tolerance, 1e-4 of
          // 55 kN, 5.5 N of normal force, which moves creep forces of a few kN by less (1.1 N
          // measured). 5 N.
          EXPECT_NEAR(Fx, f.Fx, 5.0) << "piece " << p << ", t = " << sample.time;
          EXPECT_NEAR(Fy, f.Fy, 5.0) << "piece " << p << ", t = " << sample.time;
          compared += 2;
        }
      }
  }
  EXPECT_EQ(next, v.states.size());
  EXPECT_GT(compared, 400);
  // The motion's rates matter to the forces compared: their creepages reach 4.9e-4 (yaw rate
  // times the lateral arm over V) and 1.6e-3 (lateral velocity over V), measured; a creepage of
  // 1e-4 is ~1 kN of creep force (f11 ~ 1e7 N), so a wrong sign of either would show.
  EXPECT_GT(fastest_yaw_creep, 1e-4);
  EXPECT_GT(fastest_lateral_creep, 1e-4);
}

TEST_F(TimeDomainCollective, IdealTrackGivesTheQuasiStaticStateAndThreadsDoNotMatter) {
  run_.time_domain.irregularities = IrregularitySource::none;
  const VehicleCollective v = solve_vehicle_collective(run_, kernel_, {&wheel_});
  // On ideal tangent track the vehicle stays where its quasi-static state put it: centred
  // (the mirror-symmetric wheelset's round-off, 1 nm, as the dynamics' own test).
  const DynamicPiece& tangent = v.pieces.at(1);
  ASSERT_EQ(run_.route.sections[tangent.section].kind, vehicle::SectionKind::tangent);
  int compared = 0;
  for (const WheelsetStateSpec& s : v.states) {
    if (s.label.rfind("section 3", 0) != 0) continue;
    EXPECT_NEAR(s.dy, 0.0, 1e-9) << s.label;
    EXPECT_NEAR(s.yaw, 0.0, 1e-9) << s.label;
    ++compared;
  }
  EXPECT_GE(compared, 4 * 10);

  // One thread gives the same collective as many, to the last bit, the critical speed's search
  // running beside the pieces.
  run_.critical_speed = true;
  const VehicleCollective many = solve_vehicle_collective(run_, kernel_, {&wheel_});
  VehicleCollective one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = solve_vehicle_collective(run_, kernel_, {&wheel_});
  }
  ASSERT_EQ(one.states.size(), many.states.size());
  for (std::size_t i = 0; i < many.states.size(); ++i) {
    EXPECT_EQ(one.states[i].dy, many.states[i].dy) << i;
    EXPECT_EQ(one.states[i].yaw, many.states[i].yaw) << i;
    EXPECT_EQ(one.states[i].load_left, many.states[i].load_left) << i;
    EXPECT_EQ(one.states[i].weight, many.states[i].weight) << i;
  }
  EXPECT_TRUE(std::isfinite(many.critical_speed)) << many.critical_speed_note;
  EXPECT_EQ(one.critical_speed, many.critical_speed);
}

TEST_F(TimeDomainCollective, APieceAtTheRoutesStartSamplesEveryWheelset) {
  // A 10 m tangent first, shorter than the vehicle's half length (10.75 m to the leading
  // wheelset): the car body starts before the route (on its first section's track), so every
  // wheelset still runs the whole stretch after the run-in.
  run_.route = vehicle::parse_route(R"(
[route]
speed_m_s = 30
[[section]]
kind = "tangent"
length_m = 10
[[section]]
kind = "transition"
length_m = 60
radius_m = 3000
cant_m = 0.03
[[section]]
kind = "curve"
length_m = 500
radius_m = 3000
cant_m = 0.03
)",
                                    "test route");
  const VehicleCollective v = solve_vehicle_collective(run_, kernel_, {&wheel_});
  ASSERT_EQ(v.pieces.size(), 2u);
  EXPECT_LT(v.pieces[0].sim_start_m, 0.0);
  int compared = 0;
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_TRUE(v.piece_runs[p].completed) << v.piece_runs[p].message;
    for (int samples : v.piece_runs[p].samples) {
      // 10 m at most 2 m apart: 5 or 6 samples; 60 m: 30 or 31.
      EXPECT_GE(samples, p == 0 ? 5 : 30) << p;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 8);
  double total = 0.0;
  for (const WheelsetStateSpec& s : v.states) total += s.weight;
  EXPECT_NEAR(total, 1.0, 1e-12);
}

// A simulation that stops early: each sample it reached keeps the weight it has in the
// completed run, and the start state carries the rest of each wheelset's part, so the piece's
// states still weigh its share and the states before the stop are not inflated.
TEST_F(TimeDomainCollective, AStoppedPieceWeightsItsSamplesAsTheCompletedRunDoes) {
  const VehicleCollective v = solve_vehicle_collective(run_, kernel_, {&wheel_});
  const std::vector<int> worn = run_.worn_wheelsets();
  const std::size_t p = 0;
  const DynamicPiece& piece = v.pieces[p];
  const vehicle::VehicleMotion full = simulate(v, p);
  ASSERT_TRUE(full.completed);
  PieceRun full_summary;
  const std::vector<WheelsetStateSpec> complete = piece_states(
      piece, full, v.cases[piece.start_case], v.curving[piece.start_case], worn, full_summary);

  vehicle::VehicleMotion stopped = full;
  stopped.completed = false;
  stopped.message = "stopped for the test";
  stopped.samples.resize(full.samples.size() / 2);
  PieceRun summary;
  const std::vector<WheelsetStateSpec> states = piece_states(
      piece, stopped, v.cases[piece.start_case], v.curving[piece.start_case], worn, summary);

  const double per_wheelset = piece.share / static_cast<double>(worn.size());
  double total = 0.0;
  int compared = 0;
  for (const WheelsetStateSpec& s : states) total += s.weight;
  EXPECT_NEAR(total, piece.share, 1e-15);
  for (int k : worn) {
    const auto K = static_cast<std::size_t>(k);
    const int planned = full_summary.samples[K], reached = summary.samples[K];
    ASSERT_GT(planned, reached) << k;
    const std::string prefix = piece.label + ", wheelset " + std::to_string(k + 1);
    double sampled = 0.0, rest = 0.0;
    for (const WheelsetStateSpec& s : states) {
      if (s.label.rfind(prefix + ",", 0) == 0) {
        // The completed run's weight for the same sample.
        const auto same =
            std::find_if(complete.begin(), complete.end(),
                         [&](const WheelsetStateSpec& c) { return c.label == s.label; });
        ASSERT_NE(same, complete.end()) << s.label;
        EXPECT_EQ(s.weight, same->weight) << s.label;
        sampled += s.weight;
        ++compared;
      } else if (s.label.rfind(prefix + " (start state", 0) == 0) {
        rest += s.weight;
      }
    }
    EXPECT_NEAR(sampled, per_wheelset * reached / planned, 1e-15) << k;
    EXPECT_NEAR(rest, per_wheelset * (planned - reached) / planned, 1e-15) << k;
  }
  EXPECT_GT(compared, 10);
}

// A piece's summary counts the samples in its stretch whose contact kept a side of a jump of Q.
TEST_F(TimeDomainCollective, APieceCountsItsSamplesAtAJumpOfQ) {
  const VehicleCollective v = solve_vehicle_collective(run_, kernel_, {&wheel_});
  const DynamicPiece& piece = v.pieces[0];
  vehicle::VehicleMotion motion = simulate(v, 0);
  const std::vector<int> worn = run_.worn_wheelsets();
  PieceRun none;
  piece_states(piece, motion, v.cases[piece.start_case], v.curving[piece.start_case], worn, none);
  // Wheelset 2 at a jump in every sample, the others in none.
  for (vehicle::VehicleSample& sample : motion.samples) sample.wheelsets[1].forces.load_jump = true;
  PieceRun marked;
  piece_states(piece, motion, v.cases[piece.start_case], v.curving[piece.start_case], worn, marked);
  for (std::size_t k = 0; k < vehicle::kWheelsets; ++k) {
    EXPECT_EQ(none.load_jumps[k], 0) << k;  // S1002 on 60E1: no jump on this tangent
    EXPECT_EQ(marked.load_jumps[k], k == 1 ? marked.samples[k] : 0) << k;
  }
  EXPECT_GT(marked.samples[1], 10);
}

TEST(TimeDomainScene, KeysAndTheirErrors) {
  const std::string head = "[vehicle]\nfile = \"default\"\n[route]\nfile = \"default\"\n";
  const Scene s = parse_scene(head +
                                  "[time_domain]\nirregularities = \"erri-high\"\nseed = 7\n"
                                  "tangent_length_m = 300\nrun_in_m = 80\nsample_distance_m = 1\n",
                              {});
  const TimeDomainKeys& k = s.vehicle_run->time_domain;
  EXPECT_TRUE(k.enabled);
  EXPECT_EQ(k.irregularities, IrregularitySource::erri_high);
  EXPECT_EQ(k.seed, 7u);
  EXPECT_EQ(k.tangent_length, 300.0);
  EXPECT_EQ(k.run_in, 80.0);
  EXPECT_EQ(k.sample_distance, 1.0);
  // Defaults: on, ERRI B176 low level, seed 1, 200 m of each tangent, 50 m run-in, 0.5 m.
  const TimeDomainKeys d = parse_scene(head, {}).vehicle_run->time_domain;
  EXPECT_TRUE(d.enabled);
  EXPECT_EQ(d.irregularities, IrregularitySource::erri_low);
  EXPECT_EQ(d.sample_distance, 0.5);
  EXPECT_FALSE(
      parse_scene(head + "[time_domain]\nenabled = false\n", {}).vehicle_run->time_domain.enabled);
  const auto message = [&](const std::string& keys) {
    try {
      parse_scene(head + "[time_domain]\n" + keys, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("irregularities = \"fra-6\"\n").find("erri-low"), std::string::npos);
  EXPECT_NE(message("seed = -1\n").find("seed"), std::string::npos);
  EXPECT_NE(message("tangent_length_m = 0\n").find("tangent_length_m"), std::string::npos);
  EXPECT_NE(message("sample_distance_m = 0\n").find("sample_distance_m"), std::string::npos);
  EXPECT_NE(message("run_in = 5\n").find("run_in"), std::string::npos);  // the unit missing
  EXPECT_NE(message("transitions = \"whole\"\n").find("quasi-static"), std::string::npos);
  EXPECT_TRUE(d.simulate_transitions);
  EXPECT_FALSE(parse_scene(head + "[time_domain]\ntransitions = \"quasi-static\"\n", {})
                   .vehicle_run->time_domain.simulate_transitions);
}

}  // namespace
}  // namespace wheelwear::pipeline
