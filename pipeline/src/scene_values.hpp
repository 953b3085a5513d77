#pragma once
// The scene's readers of single values beyond numbers and text: the tangential method's name,
// file names relative to the scene, profile names, the wheel's origin, inline states. Each
// names the key and its line when it refuses a value.

#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene_files.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline::detail {

// contact.tangential_method: fastsim, best or exact, or a FASTSIM method of the command line's
// names that also names the contact model (fastsim-sdec is fastsim with model sdec).
struct SceneTangential {
  TangentialMethod method = TangentialMethod::fastsim;
  bool names_model = false;  // the name also gives the contact model
  tangential::ContactModel model = tangential::ContactModel::sdec;
};

// The method a name gives; none for names that are no scene method.
std::optional<SceneTangential> scene_tangential_method(const std::string& name);

// A profile is a standard name (`standard`, any case) or a file, which must exist; a file's
// bytes go to options.text.
std::string profile_spec(const toml::node& node, const std::string& key, SceneFiles& files,
                         std::string_view standard, profiles::ProfileFileOptions& options);

// A file a key names, as read.
struct BuiltinOrFile {
  std::filesystem::path path;
  std::string content;
};

// A file named by `key`, or none for "default" (the built-in one, `builtin`); a file that does
// not exist is refused, naming both choices (`file_kind`: what kind of file to give).
std::optional<BuiltinOrFile> builtin_or_file(const toml::node& node, const std::string& key,
                                             SceneFiles& files, std::string_view builtin,
                                             std::string_view file_kind);

// [time_domain] irregularities: "erri-low", "erri-high", "none" or a measured file (read here,
// refused naming the key if it cannot be).
void time_domain_irregularities(const toml::node& node, const std::string& key, SceneFiles& files,
                                TimeDomainKeys& keys);

// [wheel] origin: "auto", "taping-line" or "internal-face" (profiles::WheelOrigin).
profiles::WheelOrigin wheel_origin(const toml::node& node, const std::string& key);

// The share of a file's points the cleaning may discard.
double max_drop(const toml::node& node, const std::string& key);

// The smoothing length of a profile file's fit [m].
double file_smoothing(const toml::node& node, const std::string& key);

// [hook] command: a list of strings, the program first; a relative program name with a '/' is
// taken from `base` (a bare name is looked up on PATH).
std::vector<std::string> hook_command(const toml::node& node, const std::string& key,
                                      const std::filesystem::path& base);

// [hook] profile_format: "csv", "simpack" or "miniprof".
HookProfileFormat hook_profile_format(const toml::node& node, const std::string& key);

// [[load_collective.state]] tables.
std::vector<WheelsetStateSpec> inline_states(const toml::node& node, const std::string& key);

}  // namespace wheelwear::pipeline::detail
