#include "scene_states_source.hpp"

#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline::detail {

void settle_states_source(Scene& s, const StatesSourceLines& lines, SceneUse use) {
  if (s.hook) {
    if (s.hook->command.empty())
      throw InputError(
          "scene: [hook] has no command; give command = [\"program\", \"args\", "
          "..., \"{collective}\"]");
    if (s.vehicle_run || lines.collective)
      throw InputError("scene line " + std::to_string(s.hook->line) + ": [hook] and " +
                       (s.vehicle_run ? "[vehicle]" : "[load_collective]") +
                       " both give the run's states; give one: the hook's program makes the "
                       "collective of every step");
    return;
  }
  // A vehicle solve alone takes the built-in coach or route for the one a scene leaves out.
  if (s.vehicle_run && use == SceneUse::vehicle_solve) {
    if (!lines.vehicle) s.vehicle_run->vehicle = vehicle::default_vehicle();
    if (!lines.route) s.vehicle_run->route = vehicle::default_route();
  }
  if (s.vehicle_run) {
    if (use == SceneUse::wear_run && (!lines.vehicle || !lines.route)) {
      throw InputError(std::string("scene: a vehicle run needs both [vehicle] file and [route] "
                                   "file (\"default\" for the built-in ones); ") +
                       (lines.vehicle ? "[route] file" : "[vehicle] file") + " is missing");
    }
    if (lines.collective) {
      throw InputError("scene line " + std::to_string(*lines.collective) +
                       ": [load_collective] and [vehicle] both give the run's states; give one: "
                       "the vehicle on its route makes the collective of every step itself");
    }
    // A route that cannot be run backwards is refused now, not at the first solve.
    if (s.vehicle_run->direction != RunningDirection::forward)
      (void)vehicle::reversed(s.vehicle_run->route);
    // A cant deficiency above what EN 13803 admits is a warning (Route::validate).
    for (const std::string& w : s.vehicle_run->route.validate()) s.warnings.push_back(w);
    return;
  }
  if (s.states.empty() && !lines.collective && use == SceneUse::vehicle_solve) return;
  if (s.states.empty()) {
    throw InputError(lines.collective ? "scene line " + std::to_string(*lines.collective) +
                                            ": load_collective: no states"
                                      : "scene: no [load_collective], no [vehicle] and no [hook]; "
                                        "give [load_collective] file = \"states.csv\" (or "
                                        "[[load_collective.state]] tables), or [vehicle] file and "
                                        "[route] file (\"default\" for the built-in ones), or a "
                                        "co-simulation [hook] command");
  }
  double total = 0.0;
  for (const auto& state : s.states) total += state.weight;
  if (!(total > 0.0))
    throw InputError("scene: load_collective: the weights sum to 0; give some state a weight > 0");
}

}  // namespace wheelwear::pipeline::detail
