#include "scene_tables.hpp"

#include <cstdint>
#include <limits>

#include "scene_values.hpp"

namespace wheelwear::pipeline::detail {

std::map<std::string, KeyHandler> time_domain_keys(const std::function<TimeDomainKeys&()>& keys,
                                                   SceneFiles& files) {
  return {
      {"enabled", [=](const auto& n, const auto& k) { keys().enabled = boolean(n, k); }},
      {"irregularities",
       [=, &files](const auto& n, const auto& k) {
         time_domain_irregularities(n, k, files, keys());
       }},
      {"seed",
       [=](const auto& n, const auto& k) {
         keys().seed =
             static_cast<std::uint64_t>(integer(n, k, 0, std::numeric_limits<int>::max(),
                                                "the base seed of the generated irregularities"));
       }},
      {"redraw", [=](const auto& n, const auto& k) { keys().redraw = boolean(n, k); }},
      {"tangent_length_m",
       [=](const auto& n, const auto& k) {
         keys().tangent_length =
             number(n, k, 10.0, 1e5, "the simulated stretch of each tangent in m");
       }},
      {"transitions",
       [=](const auto& n, const auto& k) {
         keys().simulate_transitions =
             one_of(n, k, {"time", "quasi-static"},
                    "use time (simulated whole, with the tangents) or quasi-static (each at its "
                    "midpoint, as the curves)") == 0;
       }},
      {"run_in_m",
       [=](const auto& n, const auto& k) {
         keys().run_in = number(n, k, 0.0, 1e4, "the run before each stretch's first sample in m");
       }},
      {"sample_distance_m",
       [=](const auto& n, const auto& k) {
         keys().sample_distance =
             number(n, k, 0.01, 100.0, "the distance between two samples in m");
       }},
  };
}

std::map<std::string, KeyHandler> hook_keys(const std::function<CosimulationHook&()>& hook) {
  return {
      {"command",
       [=](const auto& n, const auto& k) {
         CosimulationHook& h = hook();
         h.command = hook_command(n, k, h.working_directory);
         h.line = static_cast<int>(n.source().begin.line);
       }},
      {"resolve_depth_m",
       [=](const auto& n, const auto& k) {
         hook().resolve_depth = number(n, k, 0.0, 0.01, "the wear depth between two calls in m");
       }},
      {"timeout_s",
       [=](const auto& n, const auto& k) {
         hook().timeout = number(n, k, 0.1, 1e6, "the longest run of one call in s");
       }},
      {"profile_format",
       [=](const auto& n, const auto& k) { hook().profile_format = hook_profile_format(n, k); }},
  };
}

}  // namespace wheelwear::pipeline::detail
