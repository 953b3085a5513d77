#pragma once
// The keys of the scene's self-contained optional tables, [time_domain] and [hook]: each handler
// fills the table's value, made on first use by the getter given.

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "scene_files.hpp"
#include "scene_keys.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

// [time_domain]: the vehicle run's time-domain keys; a measured irregularity file is read
// through `files`, which must outlive the handlers.
std::map<std::string, KeyHandler> time_domain_keys(const std::function<TimeDomainKeys&()>& keys,
                                                   SceneFiles& files);

// [hook]: the co-simulation hook (its working directory set by the getter).
std::map<std::string, KeyHandler> hook_keys(const std::function<CosimulationHook&()>& hook);

}  // namespace wheelwear::pipeline::detail
