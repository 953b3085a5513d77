#pragma once
// Where a parsed scene's run takes its states from: a collective, the vehicle on its route, or
// a co-simulation hook (scene.cpp parses the keys, this checks that they say one thing).

#include <optional>

#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

/// The scene lines of the tables that give states, where the scene has them.
struct StatesSourceLines {
  std::optional<int> collective;  ///< [load_collective]
  std::optional<int> vehicle;     ///< [vehicle] file
  std::optional<int> route;       ///< [route] file
};

/// Throws InputError naming the lines where the scene gives its states more than one way, none
/// (for a wear run), a vehicle without its route or a route without its vehicle (for a wear run;
/// a vehicle solve takes the built-in one), or a collective whose weights sum to 0. Completes a
/// vehicle solve's missing vehicle or route with the built-in one and adds the route's warnings.
void settle_states_source(Scene& s, const StatesSourceLines& lines, SceneUse use);

}  // namespace wheelwear::pipeline::detail
