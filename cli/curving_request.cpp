#include "curving_request.hpp"

#include <chrono>
#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::cli {

CurvingAnswer solve_curving(const CurvingRequest& request) {
  const pipeline::Scene scene =
      request.scene.empty()
          ? pipeline::default_scene()
          : pipeline::load_scene(request.scene, pipeline::SceneUse::vehicle_solve);
  // --vehicle, else the scene's [vehicle], else the built-in coach.
  vehicle::Vehicle v = vehicle::default_vehicle();
  std::string vehicle_name;
  if (!request.vehicle.empty()) {
    v = vehicle::read_vehicle(request.vehicle);
    vehicle_name = "--vehicle " + request.vehicle;
  } else if (scene.vehicle_run) {
    v = scene.vehicle_run->vehicle;
    if (!scene.vehicle_run->vehicle_file.empty())
      vehicle_name = "vehicle file " + scene.vehicle_run->vehicle_file;
  }
  vehicle::SteadyCurve curve;
  curve.running = {request.speed, request.radius, request.friction.value_or(scene.friction)};
  if (!request.friction) curve.running.friction_flange = scene.friction_flange;
  curve.cant = request.cant;
  curve.traction = request.traction;
  require(std::isfinite(request.speed) && request.speed > 0.0, "--speed", request.speed,
          "the speed must be positive (m/s)");
  require(
      std::isfinite(request.radius) && (request.radius == 0.0 || std::abs(request.radius) >= 50.0),
      "--radius", request.radius, "give 0 for tangent track or |R| >= 50 m (+ right-hand)");
  require(request.radius != 0.0 || request.cant == 0.0, "--cant", request.cant,
          "tangent track (--radius 0) has no cant");
  curve.validate();
  const pipeline::StateKernel kernel(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  vehicle::WheelsetModel model = pipeline::wheelset_model(kernel, wheel, wheel);
  CurvingAnswer answer;
  answer.warnings = scene.warnings;
  if (!vehicle_name.empty())
    for (std::string& w : pipeline::vehicle_scene_differences(
             v, vehicle_name, scene, wheel.info().nominal_radius, curve.running.friction))
      answer.warnings.push_back(std::move(w));
  std::optional<TableReport>& table = answer.table;
  if (request.contact_table) {
    const auto start = std::chrono::steady_clock::now();
    model.table = pipeline::contact_table(model, v);
    table = TableReport{
        model.table->shifts().size(), model.table->loads().size(), model.table->contact_solves(),
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  }
  answer.curving = vehicle::solve_vehicle_curving(v, {model, model, model, model}, curve);
  answer.curve = curve;
  return answer;
}

}  // namespace wheelwear::cli
