// `wheelwear curving`: the quasi-static curving of the scene's vehicle in a constant curve.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "commands.hpp"
#include "curving_request.hpp"
#include "json_writer.hpp"
#include "output_path.hpp"
#include "thread_limit.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::cli {

namespace {

struct CurvingArgs {
  std::string scene;
  std::string vehicle;
  double radius = 0.0;
  double cant = 0.0;
  double speed = 0.0;
  std::optional<double> friction;
  double traction = 0.0;
  bool json = false;
  bool contact_table = false;
  int threads = 0;
  std::string export_vehicle;
  bool overwrite = false;
};

std::string wheel_json(const vehicle::WheelForces& w, const char* side) {
  JsonObject o;
  o.add("side", side)
      .add("Q", w.Q)
      .add("Y", w.Y)
      .add("contact_angle", w.contact_angle)
      .add("Fx", w.Fx)
      .add("Fy", w.Fy)
      .add("N", w.N)
      .add("status", contactgeom::status_name(w.status))
      .add("patches", static_cast<int>(w.patches.size()));
  return o.str();
}

// A wheelset's status: ok when both wheels are, else the first wheel's that is not.
const char* wheelset_status(const vehicle::WheelsetForces& f) {
  for (const vehicle::WheelForces& w : f.wheels)
    if (w.status != contactgeom::WheelRailStatus::ok) return contactgeom::status_name(w.status);
  return "ok";
}

void print_json(const vehicle::VehicleCurving& c, const std::optional<TableReport>& table) {
  std::vector<std::string> wheelsets;
  for (const vehicle::CurvingWheelset& w : c.wheelsets) {
    JsonObject o;
    o.add("x", w.x)
        .add("dy", w.state.dy)
        .add("angle_of_attack", w.state.yaw)
        .add("spin", w.state.spin)
        .add("roll", w.forces.contact.roll)
        .add("Fx_axle", w.forces.Fx_axle)
        .add("axle_torque", w.forces.axle_torque)
        .add("sum_Y", w.forces.lateral)  // Y_right - Y_left: the rails' lateral force, + left
        .add("status", wheelset_status(w.forces))
        .add_raw("wheels", json_array({wheel_json(w.forces.wheels[0], "left"),
                                       wheel_json(w.forces.wheels[1], "right")}));
    wheelsets.push_back(o.str());
  }
  JsonObject body;
  body.add("y", c.car_body.y).add("yaw", c.car_body.yaw);
  std::vector<std::string> bogies;
  for (const vehicle::BodyPlacement& b : c.bogies)
    bogies.push_back(JsonObject().add("y", b.y).add("yaw", b.yaw).str());
  JsonObject out;
  out.add("converged", c.converged)
      .add("message", c.message)
      .add("cant_deficiency", c.cant_deficiency)
      .add("iterations", c.iterations)
      .add("wheelset_evaluations", c.wheelset_evaluations)
      .add("finished_directly", c.finished_directly)
      .add_raw("car_body", body.str())
      .add_raw("bogies", json_array(bogies))
      .add_raw("wheelsets", json_array(wheelsets));
  if (table)
    out.add_raw("contact_table", JsonObject()
                                     .add("shifts", static_cast<int>(table->shifts))
                                     .add("load_levels", static_cast<int>(table->load_levels))
                                     .add("contact_solves", table->contact_solves)
                                     .add("build_seconds", table->seconds)
                                     .str());
  std::cout << out.str() << "\n";
}

void print_text(const vehicle::VehicleCurving& c, const vehicle::SteadyCurve& curve) {
  std::printf(
      "quasi-static curving: R %.0f m, cant %.0f mm, %.1f m/s, friction %.2f (flange %.2f): %s\n",
      curve.running.curve_radius, curve.cant * 1e3, curve.running.speed, curve.running.friction,
      curve.running.rail_friction().flange,
      c.converged ? "converged" : ("NOT converged: " + c.message).c_str());
  std::printf("cant deficiency %.0f mm; car body %+.1f mm, bogies %+.2f / %+.2f mm\n",
              c.cant_deficiency * 1e3, c.car_body.y * 1e3, c.bogies[0].y * 1e3,
              c.bogies[1].y * 1e3);
  std::printf("%7s %9s %9s %9s | %-27s | %-27s\n", "x [m]", "dy [mm]", "aoa[mrad]", "Fx [N]",
              "left  Q / Y [kN], angle[deg]", "right Q / Y [kN], angle[deg]");
  for (const vehicle::CurvingWheelset& w : c.wheelsets) {
    const vehicle::WheelForces& l = w.forces.wheels[0];
    const vehicle::WheelForces& r = w.forces.wheels[1];
    std::printf("%7.2f %9.3f %9.3f %9.1f | %7.2f %7.2f %6.1f %-5s| %7.2f %7.2f %6.1f %-5s\n", w.x,
                w.state.dy * 1e3, w.state.yaw * 1e3, w.forces.Fx_axle, l.Q * 1e-3, l.Y * 1e-3,
                l.contact_angle * 180.0 / M_PI, contactgeom::status_name(l.status), r.Q * 1e-3,
                r.Y * 1e-3, r.contact_angle * 180.0 / M_PI, contactgeom::status_name(r.status));
  }
}

void export_vehicle(const CurvingArgs& args) {
  const std::filesystem::path dir(args.export_vehicle);
  make_output_folder(dir, "--export-default-vehicle");
  const std::filesystem::path file = dir / "vehicle.toml";
  if (std::filesystem::exists(file) && !args.overwrite)
    throw InputError("--export-default-vehicle: " + file.string() +
                     " exists; pass --overwrite to replace it");
  core::write_file_atomically(file, std::string(vehicle::default_vehicle_text()));
  std::cout << "wrote " << file.string() << "; use it with: wheelwear curving --vehicle "
            << file.string() << " --radius 500 --cant 0.1 --speed 20\n";
}

void curving(const CurvingArgs& args) {
  if (!args.export_vehicle.empty()) {
    export_vehicle(args);
    return;
  }
  const auto threads = thread_limit(args.threads);
  CurvingRequest request;
  request.scene = args.scene;
  request.vehicle = args.vehicle;
  request.radius = args.radius;
  request.cant = args.cant;
  request.speed = args.speed;
  request.friction = args.friction;
  request.traction = args.traction;
  request.contact_table = args.contact_table;
  const CurvingAnswer answer = solve_curving(request);
  for (const std::string& w : answer.warnings) std::cerr << "wheelwear: warning: " << w << "\n";
  const vehicle::VehicleCurving& c = answer.curving;
  const vehicle::SteadyCurve& curve = answer.curve;
  const std::optional<TableReport>& table = answer.table;
  if (args.json) {
    print_json(c, table);
  } else {
    print_text(c, curve);
    if (table)
      std::printf("contact table: %zu shifts x %zu loads, %d contact solves, built in %.2f s\n",
                  table->shifts, table->load_levels, table->contact_solves, table->seconds);
    if (c.finished_directly)
      std::printf(
          "the attempts on the contact table did not converge; the balance above is "
          "with direct contacts\n");
  }
  // Computed but no balance: the last iterate is printed, and the command fails with exit
  // status 3 (docs/cli.md).
  if (!c.converged) throw std::runtime_error("curving did not converge: " + c.message);
}

}  // namespace

void add_curving_command(CLI::App& app) {
  auto args = std::make_shared<CurvingArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curving",
      "Quasi-static curving of a vehicle (car body, two bogies, four wheelsets) in a constant\n"
      "curve: the steady state where every body is in balance and every axle rolls freely,\n"
      "with the rails' forces from the scene's contact chain. Frames: docs/architecture.md;\n"
      "the model: docs/vehicle.md. Without SCENE the built-in scene's profiles (S1002 on 60E1\n"
      "1:40); without --vehicle the scene's [vehicle], else the built-in Manchester benchmark\n"
      "coach. The scene's profiles, track and friction are used; where a vehicle file's wheel\n"
      "radius or proposed [contact] differ from them, a warning names each.\n"
      "Example: wheelwear curving --radius 500 --cant 0.1 --speed 20 --json");
  cmd->add_option("scene", args->scene, "scene file (TOML) for profiles, track and contact model")
      ->check(CLI::ExistingFile);
  cmd->add_option("--vehicle", args->vehicle,
                  "vehicle file (TOML); default the scene's, else the built-in")
      ->check(CLI::ExistingFile);
  cmd->add_option("--radius", args->radius,
                  "curve radius [m]: > 0 right-hand (left rail outer), < 0 left-hand, 0 tangent");
  cmd->add_option("--cant", args->cant, "cant: height of the outer rail above the inner [m], >= 0");
  cmd->add_option("--speed", args->speed, "vehicle speed [m/s], > 0");
  cmd->add_option("--friction", args->friction,
                  "friction coefficient, top of rail and flange alike (default: the scene's)")
      ->check(CLI::Range(0.01, 1.0));
  cmd->add_option("--traction", args->traction,
                  "longitudinal force per powered axle [N]: > 0 traction, < 0 braking (default 0, "
                  "coasting); the vehicle file's powered_wheelsets carry it, the others roll "
                  "freely")
      ->check(CLI::Range(-5e5, 5e5));
  cmd->add_flag("--json", args->json, "print the result as JSON");
  cmd->add_flag("--contact-table", args->contact_table,
                "interpolate the contacts from a look-up table built first (as a run does; "
                "docs/vehicle.md) instead of solving each directly");
  cmd->add_option("--threads", args->threads,
                  "worker threads for the contact table's build (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--export-default-vehicle", args->export_vehicle,
                  "write the built-in vehicle (vehicle.toml) into this directory and exit");
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing exported file");
  cmd->callback([args] {
    if (args->export_vehicle.empty() && args->speed == 0.0)
      throw InputError("--speed: give the vehicle's speed in m/s (e.g. --speed 20)");
    curving(*args);
  });
}

}  // namespace wheelwear::cli
