// `wheelwear route`: the vehicle on its route alone, without wear: every constant curve solved
// quasi-statically and every tangent and transition simulated in time on the scene's profiles,
// and the load collective its states make.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

#include "commands.hpp"
#include "json_writer.hpp"
#include "thread_limit.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::cli {

namespace {

struct RouteArgs {
  std::string scene;
  std::string vehicle;
  std::string route;
  std::string output;
  bool overwrite = false;
  bool quasi_static = false;
  bool json = false;
  int threads = 0;
};

// The vehicle run of the scene, or the built-in vehicle on the built-in route; the files given
// on the command line replace the scene's.
pipeline::VehicleRun vehicle_run(const pipeline::Scene& scene, const RouteArgs& args) {
  pipeline::VehicleRun run;
  if (scene.vehicle_run) {
    run = *scene.vehicle_run;
  } else {
    run.vehicle = vehicle::default_vehicle();
    run.route = vehicle::default_route();
  }
  if (!args.vehicle.empty()) run.vehicle = vehicle::read_vehicle(args.vehicle);
  if (!args.route.empty()) run.route = vehicle::read_route(args.route);
  if (args.quasi_static) run.time_domain.enabled = false;
  // The scene's route was checked with the scene (its warnings are the scene's); a route given
  // here is checked here.
  if (!args.route.empty())
    for (const std::string& w : run.route.validate())
      std::cerr << "wheelwear: warning: " << w << "\n";
  return run;
}

// The largest Y/Q of a case's wheels, and the largest contact angle [rad].
struct CaseExtremes {
  double y_over_q = 0.0;
  double contact_angle = 0.0;
};

CaseExtremes extremes(const vehicle::VehicleCurving& c) {
  CaseExtremes e;
  for (const vehicle::CurvingWheelset& w : c.wheelsets)
    for (const vehicle::WheelForces& wheel : w.forces.wheels) {
      if (wheel.Q > 0.0) e.y_over_q = std::max(e.y_over_q, std::abs(wheel.Y) / wheel.Q);
      e.contact_angle = std::max(e.contact_angle, std::abs(wheel.contact_angle));
    }
  return e;
}

// The width of a column that shows every label of `rows` whole (a label names a section's
// radius at its end: "section 2, transition, R 6000 m"), at least `heading`'s.
template <typename Rows>
int label_width(const Rows& rows, const char* heading) {
  std::size_t width = std::strlen(heading);
  for (const auto& row : rows) width = std::max(width, row.label.size());
  return static_cast<int>(width);
}

// The time-domain pieces: per piece the leading wheelset's motion and the largest Y/Q.
void print_pieces(const pipeline::VehicleCollective& v) {
  constexpr const char* kHeading = "time-domain piece";
  const int width = label_width(v.pieces, kHeading);
  std::printf("\n%-*s %7s %6s %7s %5s | %-27s | %6s\n", width, kHeading, "length", "V", "samples",
              "done", "leading wheelset dy rms/max", "Y/Q");
  std::printf("%-*s %7s %6s %7s %5s | %-27s | %6s\n", width, "", "[m]", "[m/s]", "", "",
              "[mm] / [mm], aoa rms [mrad]", "max");
  for (std::size_t i = 0; i < v.pieces.size(); ++i) {
    const pipeline::DynamicPiece& d = v.pieces[i];
    const pipeline::PieceRun& r = v.piece_runs[i];
    double y_over_q = 0.0;
    for (double q : r.y_over_q) y_over_q = std::max(y_over_q, q);
    std::printf("%-*s %7.0f %6.1f %7d %5s | %6.3f / %6.3f, %6.3f  | %6.3f\n", width,
                d.label.c_str(), d.length_m, d.speed, r.samples[0], r.completed ? "yes" : "NO",
                r.dy_rms[0] * 1e3, r.dy_max[0] * 1e3, r.yaw_rms[0] * 1e3, y_over_q);
  }
}

void print_text(const pipeline::VehicleCollective& v, double seconds) {
  constexpr const char* kHeading = "condition";
  const int width = label_width(v.cases, kHeading);
  std::printf("%-*s %7s %6s %6s %6s %5s | %-23s | %6s %6s\n", width, kHeading, "R [m]", "cant", "V",
              "share", "conv", "leading wheelset dy/aoa", "Y/Q", "angle");
  std::printf("%-*s %7s %6s %6s %6s %5s | %-23s | %6s %6s\n", width, "", "", "[mm]", "[m/s]", "[%]",
              "", "[mm] / [mrad]", "max", "[deg]");
  for (std::size_t i = 0; i < v.cases.size(); ++i) {
    const pipeline::RouteCase& rc = v.cases[i];
    const vehicle::VehicleCurving& c = v.curving[i];
    const CaseExtremes e = extremes(c);
    std::printf("%-*s %7.0f %6.0f %6.1f %6.2f %5s | %9.3f / %9.3f   | %6.3f %6.1f\n", width,
                rc.label.c_str(), rc.curve.running.curve_radius, rc.curve.cant * 1e3,
                rc.curve.running.speed, rc.share * 100.0, c.converged ? "yes" : "NO",
                c.wheelsets[0].state.dy * 1e3, c.wheelsets[0].state.yaw * 1e3, e.y_over_q,
                e.contact_angle * 180.0 / std::numbers::pi);
  }
  if (!v.pieces.empty()) print_pieces(v);
  if (std::isfinite(v.critical_speed))
    std::printf("\nlinear critical speed on tangent track: %.1f m/s (%.0f km/h), %s\n",
                v.critical_speed, v.critical_speed * 3.6, v.critical_speed_note.c_str());
  else
    std::printf("\nlinear critical speed on tangent track: %s\n", v.critical_speed_note.c_str());
  std::printf(
      "%zu conditions and %zu time-domain pieces in %.1f s; %d conditions did not "
      "converge (their last iterate is shown), %d pieces stopped early\n",
      v.cases.size(), v.pieces.size(), seconds, v.unconverged, v.incomplete());
}

void print_json(const pipeline::VehicleCollective& v, double seconds) {
  std::vector<std::string> cases;
  for (std::size_t i = 0; i < v.cases.size(); ++i) {
    const pipeline::RouteCase& rc = v.cases[i];
    const vehicle::VehicleCurving& c = v.curving[i];
    std::vector<std::string> wheelsets;
    for (const vehicle::CurvingWheelset& w : c.wheelsets) {
      std::vector<std::string> wheels;
      for (std::size_t side = 0; side < 2; ++side) {
        const vehicle::WheelForces& f = w.forces.wheels[side];
        wheels.push_back(JsonObject()
                             .add("side", side == 0 ? "left" : "right")
                             .add("Q", f.Q)
                             .add("Y", f.Y)
                             .add("contact_angle", f.contact_angle)
                             .add("Fx", f.Fx)
                             .add("Fy", f.Fy)
                             .add("N", f.N)
                             .str());
      }
      wheelsets.push_back(JsonObject()
                              .add("dy", w.state.dy)
                              .add("angle_of_attack", w.state.yaw)
                              .add("spin", w.state.spin)
                              .add("roll", w.forces.contact.roll)
                              .add("axle_torque", w.forces.axle_torque)
                              .add_raw("wheels", json_array(wheels))
                              .str());
    }
    cases.push_back(JsonObject()
                        .add("label", rc.label)
                        .add("radius", rc.curve.running.curve_radius)
                        .add("cant", rc.curve.cant)
                        .add("speed", rc.curve.running.speed)
                        .add("friction", rc.curve.running.friction)
                        .add("friction_flange", rc.curve.running.rail_friction().flange)
                        .add("share", rc.share)
                        .add("converged", c.converged)
                        .add("cant_deficiency", c.cant_deficiency)
                        .add_raw("wheelsets", json_array(wheelsets))
                        .str());
  }
  std::vector<std::string> pieces;
  for (std::size_t i = 0; i < v.pieces.size(); ++i) {
    const pipeline::DynamicPiece& d = v.pieces[i];
    const pipeline::PieceRun& r = v.piece_runs[i];
    std::vector<std::string> wheelsets;
    for (std::size_t k = 0; k < vehicle::kWheelsets; ++k)
      wheelsets.push_back(JsonObject()
                              .add("samples", r.samples[k])
                              .add("dy_rms", r.dy_rms[k])
                              .add("dy_max", r.dy_max[k])
                              .add("angle_of_attack_rms", r.yaw_rms[k])
                              .add("Y_over_Q_max", r.y_over_q[k])
                              .str());
    pieces.push_back(JsonObject()
                         .add("label", d.label)
                         .add("section", static_cast<int>(d.section + 1))
                         .add("start", d.start_m)
                         .add("length", d.length_m)
                         .add("speed", d.speed)
                         .add("share", d.share)
                         .add("completed", r.completed)
                         .add("message", r.message)
                         .add("time_step", r.time_step)
                         .add_raw("wheelsets", json_array(wheelsets))
                         .str());
  }
  std::cout << JsonObject()
                   .add("elapsed", seconds)
                   .add("unconverged", v.unconverged)
                   .add("incomplete_pieces", v.incomplete())
                   .add("critical_speed", v.critical_speed)
                   .add("critical_speed_note", v.critical_speed_note)
                   .add("states", static_cast<int>(v.states.size()))
                   .add_raw("cases", json_array(cases))
                   .add_raw("pieces", json_array(pieces))
                   .str()
            << '\n';
}

// Computed but not every condition balanced or every piece run through: what was computed is
// printed and written, and the command fails with exit status 3 (docs/cli.md).
bool complete(const pipeline::VehicleCollective& v) {
  return v.unconverged == 0 && v.incomplete() == 0;
}

void require_complete(const pipeline::VehicleCollective& v) {
  if (complete(v)) return;
  std::string what;
  if (v.unconverged > 0)
    what = std::to_string(v.unconverged) + " of " + std::to_string(v.cases.size()) +
           " quasi-static conditions did not converge (their last iterates are in the states, "
           "shown as NO)";
  if (v.incomplete() > 0)
    what += std::string(what.empty() ? "" : "; ") + std::to_string(v.incomplete()) + " of " +
            std::to_string(v.pieces.size()) +
            " simulated pieces stopped early (their samples up to there are in the states)";
  throw std::runtime_error(what);
}

void route(const RouteArgs& args) {
  if (!args.output.empty() && std::filesystem::exists(args.output) && !args.overwrite) {
    throw InputError("-o " + args.output + ": the file exists; pass --overwrite to replace it");
  }
  const auto threads = thread_limit(args.threads);
  const pipeline::Scene scene =
      args.scene.empty() ? pipeline::default_scene()
                         : pipeline::load_scene(args.scene, pipeline::SceneUse::vehicle_solve);
  // A route given here replaces the scene's, and with it the scene's warnings about its route.
  std::vector<std::string> replaced;
  if (!args.route.empty() && scene.vehicle_run) replaced = scene.vehicle_run->route.validate();
  for (const std::string& w : scene.warnings)
    if (std::find(replaced.begin(), replaced.end(), w) == replaced.end())
      std::cerr << "wheelwear: warning: " << w << "\n";
  const pipeline::VehicleRun run = vehicle_run(scene, args);
  const pipeline::StateKernel kernel(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  const std::string vehicle_name = !args.vehicle.empty()       ? "--vehicle " + args.vehicle
                                   : !run.vehicle_file.empty() ? "vehicle file " + run.vehicle_file
                                                               : std::string();
  if (!vehicle_name.empty())
    for (const std::string& w : pipeline::vehicle_scene_differences(
             run.vehicle, vehicle_name, scene, wheel.info().nominal_radius, std::nullopt))
      std::cerr << "wheelwear: warning: " << w << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  const pipeline::VehicleCollective v = pipeline::solve_vehicle_collective(run, kernel, {&wheel});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!args.output.empty())
    core::write_file_atomically(args.output, pipeline::collective_csv(v.states));
  if (args.json) {
    print_json(v, seconds);
  } else {
    print_text(v, seconds);
    if (!args.output.empty() && complete(v)) {
      std::printf(
          "wrote %s: %zu states, the load collective of this vehicle on this route; wear "
          "with it by naming it in a scene's [load_collective] file\n",
          args.output.c_str(), v.states.size());
    } else if (!args.output.empty()) {
      std::printf(
          "wrote %s: %zu states, among them the last iterates of the conditions that did not "
          "converge and the samples of the pieces that stopped early (below)\n",
          args.output.c_str(), v.states.size());
    }
  }
  require_complete(v);
}

}  // namespace

void add_route_command(CLI::App& app) {
  auto args = std::make_shared<RouteArgs>();
  CLI::App* cmd = app.add_subcommand(
      "route",
      "The vehicle on its route without wear, on the scene's wheel and rail profiles, as a wear\n"
      "run solves it at its steps (docs/vehicle.md): the quasi-static state of the whole vehicle\n"
      "in every constant curve (alike curves once), and a time-domain simulation with the\n"
      "track's irregularities through a stretch of every tangent and, as the scene's\n"
      "[time_domain] says, through every transition or at its midpoint (--quasi-static: every\n"
      "section quasi-statically, each transition at its midpoint). Prints per curve the\n"
      "leading wheelset's shift and angle of attack, the largest Y/Q and contact angle, per\n"
      "piece its motion's rms and extremes, and the vehicle's linear critical speed on tangent\n"
      "track ([vehicle] critical_speed);\n"
      "-o writes the load collective the states make (CSV, the columns of docs/scenes.md) for a\n"
      "scene or a study.\n"
      "Where SCENE names none, the built-in coach and the built-in route (a scene of profiles\n"
      "alone will do); without SCENE, the built-in scene's, with its [time_domain] (100 m of\n"
      "each tangent, transitions at their midpoints, a state every 2 m).\n"
      "Example: wheelwear route -o route_states.csv");
  cmd->add_option("scene", args->scene,
                  "scene file (TOML): profiles, contact model, [vehicle], "
                  "[route]")
      ->check(CLI::ExistingFile);
  cmd->add_option("--vehicle", args->vehicle, "vehicle file (TOML), instead of the scene's")
      ->check(CLI::ExistingFile);
  cmd->add_option("--route", args->route, "route file (TOML), instead of the scene's")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "write the states as a load-collective CSV file");
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing output file");
  cmd->add_flag("--quasi-static", args->quasi_static,
                "every section quasi-statically, without the time domain");
  cmd->add_flag("--json", args->json, "print every condition's and piece's solution as JSON");
  cmd->add_option("--threads", args->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->callback([args] { route(*args); });
}

}  // namespace wheelwear::cli
