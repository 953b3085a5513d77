// `wheelwear route`: the vehicle on its route alone, without wear: every running condition
// solved quasi-statically on the scene's profiles, and the load collective its states make.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
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

void print_text(const pipeline::VehicleCollective& v, double seconds) {
  std::printf("%-28s %7s %6s %6s %6s %5s | %-23s | %6s %6s\n", "condition", "R [m]", "cant", "V",
              "share", "conv", "leading wheelset dy/aoa", "Y/Q", "angle");
  std::printf("%-28s %7s %6s %6s %6s %5s | %-23s | %6s %6s\n", "", "", "[mm]", "[m/s]", "[%]", "",
              "[mm] / [mrad]", "max", "[deg]");
  for (std::size_t i = 0; i < v.cases.size(); ++i) {
    const pipeline::RouteCase& rc = v.cases[i];
    const vehicle::VehicleCurving& c = v.curving[i];
    const CaseExtremes e = extremes(c);
    std::printf("%-28.28s %7.0f %6.0f %6.1f %6.2f %5s | %9.3f / %9.3f   | %6.3f %6.1f\n",
                rc.label.c_str(), rc.curve.running.curve_radius, rc.curve.cant * 1e3,
                rc.curve.running.speed, rc.share * 100.0, c.converged ? "yes" : "NO",
                c.wheelsets[0].state.dy * 1e3, c.wheelsets[0].state.yaw * 1e3, e.y_over_q,
                e.contact_angle * 180.0 / std::numbers::pi);
  }
  std::printf("%zu conditions in %.1f s; %d did not converge (their last iterate is shown)\n",
              v.cases.size(), seconds, v.unconverged);
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
  std::cout << JsonObject()
                   .add("elapsed", seconds)
                   .add("unconverged", v.unconverged)
                   .add("states", static_cast<int>(v.states.size()))
                   .add_raw("cases", json_array(cases))
                   .str()
            << '\n';
}

void route(const RouteArgs& args) {
  if (!args.output.empty() && std::filesystem::exists(args.output) && !args.overwrite) {
    throw InputError("-o " + args.output + ": the file exists; pass --overwrite to replace it");
  }
  const auto threads = thread_limit(args.threads);
  const pipeline::Scene scene =
      args.scene.empty() ? pipeline::default_scene() : pipeline::load_scene(args.scene);
  const pipeline::VehicleRun run = vehicle_run(scene, args);
  const pipeline::StateKernel kernel(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  const auto t0 = std::chrono::steady_clock::now();
  const pipeline::VehicleCollective v = pipeline::solve_vehicle_collective(run, kernel, {&wheel});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!args.output.empty())
    core::write_file_atomically(args.output, pipeline::collective_csv(v.states));
  if (args.json) {
    print_json(v, seconds);
    return;
  }
  print_text(v, seconds);
  if (!args.output.empty()) {
    std::printf(
        "wrote %s: %zu states, the load collective of this vehicle on this route; wear "
        "with it by naming it in a scene's [load_collective] file\n",
        args.output.c_str(), v.states.size());
  }
}

}  // namespace

void add_route_command(CLI::App& app) {
  auto args = std::make_shared<RouteArgs>();
  CLI::App* cmd = app.add_subcommand(
      "route",
      "The vehicle on its route without wear: the quasi-static state of the whole vehicle in\n"
      "every running condition of the route (each curve and tangent, each transition at its\n"
      "midpoint; alike conditions once) on the scene's wheel and rail profiles, as a wear run\n"
      "solves it at its steps (docs/vehicle.md). Prints per condition the leading wheelset's\n"
      "shift and angle of attack, the largest Y/Q and contact angle; -o writes the load\n"
      "collective the states make (CSV, the columns of docs/scenes.md) for a scene or a study.\n"
      "Without SCENE, or when it has no [vehicle]: the built-in coach on the built-in route.\n"
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
  cmd->add_flag("--json", args->json, "print every condition's solution as JSON");
  cmd->add_option("--threads", args->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->callback([args] { route(*args); });
}

}  // namespace wheelwear::cli
