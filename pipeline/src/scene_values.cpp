#include "scene_values.hpp"

#include <array>

#include "load_collective.hpp"
#include "scene_keys.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace wheelwear::pipeline::detail {

std::optional<SceneTangential> scene_tangential_method(const std::string& name) {
  using C = tangential::ContactModel;
  if (name == "fastsim") return SceneTangential{};
  const auto method = tangential::parse_method(name);
  if (!method) return std::nullopt;
  switch (*method) {
    case tangential::Method::best:
      return SceneTangential{TangentialMethod::best, false, C::sdec};
    case tangential::Method::exact:
      return SceneTangential{TangentialMethod::exact, false, C::sdec};
    case tangential::Method::fastsim_sdec:
      return SceneTangential{TangentialMethod::fastsim, true, C::sdec};
    case tangential::Method::fastsim_eql:
      return SceneTangential{TangentialMethod::fastsim, true, C::eql};
    case tangential::Method::fastsim_eqe:
      return SceneTangential{TangentialMethod::fastsim, true, C::eqe};
    case tangential::Method::fastsim_eqe_shifted:
      return SceneTangential{TangentialMethod::fastsim, true, C::eqe_shifted};
    default:  // no per-cell fields (linear, table) or no scene model (fastsim-elliptic)
      return std::nullopt;
  }
}

std::string profile_spec(const toml::node& node, const std::string& key, SceneFiles& files,
                         std::string_view standard, profiles::ProfileFileOptions& options) {
  const std::string spec = text(node, key);
  options.text.reset();
  if (core::to_lower(spec) == core::to_lower(standard)) return std::string(standard);
  const std::filesystem::path file = files.resolve(spec);
  options.text = files.read(key, file);
  if (!options.text) {
    throw InputError(where(node.source(), key) + " = \"" + spec + "\": no such file (looked for " +
                     file.string() + "); give \"" + std::string(standard) +
                     "\" or a profile file, relative to the scene file");
  }
  return file.string();
}

std::optional<BuiltinOrFile> builtin_or_file(const toml::node& node, const std::string& key,
                                             SceneFiles& files, std::string_view builtin,
                                             std::string_view file_kind) {
  const std::string name = text(node, key);
  if (name == "default") return std::nullopt;
  const std::filesystem::path file = files.resolve(name);
  auto content = files.read(key, file);
  if (!content) {
    throw InputError(where(node.source(), key) + " = \"" + name + "\": no such file (looked for " +
                     file.string() + "); give \"default\" (" + std::string(builtin) + ") or " +
                     std::string(file_kind));
  }
  return BuiltinOrFile{file, std::move(*content)};
}

void time_domain_irregularities(const toml::node& node, const std::string& key, SceneFiles& files,
                                TimeDomainKeys& keys) {
  const std::string name = text(node, key);
  if (name == "none" || name == "erri-low" || name == "erri-high") {
    keys.irregularities = name == "none"       ? IrregularitySource::none
                          : name == "erri-low" ? IrregularitySource::erri_low
                                               : IrregularitySource::erri_high;
    keys.measured = {};
    keys.irregularity_file.clear();
    return;
  }
  const std::filesystem::path file = files.resolve(name);
  const auto content = files.read(key, file);
  if (!content)
    throw InputError(where(node.source(), key) + " = \"" + name + "\": no such file (looked for " +
                     file.string() +
                     "); give erri-low or erri-high (ERRI B176 spectra, generated "
                     "per section from [time_domain] seed), none (ideal track) or a measured "
                     "irregularity file (docs/track_irregularities.md)");
  try {
    keys.measured = vehicle::parse_irregularities(*content, file.string());
  } catch (const InputError& e) {
    throw InputError(where(node.source(), key) + ": " + e.what());
  }
  keys.irregularities = IrregularitySource::file;
  keys.irregularity_file = file.string();
}

profiles::WheelOrigin wheel_origin(const toml::node& node, const std::string& key) {
  const std::string name = text(node, key);
  const auto origin = profiles::parse_wheel_origin(name);
  if (!origin)
    throw InputError(where(node.source(), key) + " = \"" + name +
                     "\": unknown origin; use auto, taping-line (the file's y = 0 is the taping "
                     "line) or internal-face (the flange back, as MiniProf writes wheels)");
  return *origin;
}

double max_drop(const toml::node& node, const std::string& key) {
  return number(node, key, 0.0, 1.0,
                "the share of points the cleaning may discard (merged duplicates do not count)");
}

double file_smoothing(const toml::node& node, const std::string& key) {
  return number(node, key, 0.0, profiles::kMaxSmoothingLength,
                "the profile file's smoothing length in m (wavelengths of 2 pi times it are "
                "halved; 0: the curve passes through the points)");
}

std::vector<std::string> hook_command(const toml::node& node, const std::string& key,
                                      const std::filesystem::path& base) {
  const toml::array* array = node.as_array();
  std::vector<std::string> command;
  if (array)
    for (const toml::node& element : *array) {
      const auto argument = element.value<std::string>();
      if (!argument) {
        command.clear();
        break;
      }
      command.push_back(*argument);
    }
  if (!array || command.size() != array->size() || command.empty() || command.front().empty())
    throw InputError(where(node.source(), key) +
                     ": expected the program and its arguments as a list of strings, run without "
                     "a shell, e.g. [\"python3\", \"mbs_batch.py\", \"{wheel}\", \"{rail}\", "
                     "\"{collective}\"]");
  try {
    validate_hook_command(command);
  } catch (const InputError& e) {
    throw InputError(where(node.source(), key) + ": " + e.what());
  }
  const std::filesystem::path program(command.front());
  if (program.is_relative() && command.front().find('/') != std::string::npos)
    command.front() = SceneFiles(base, {}).resolve(command.front()).string();
  return command;
}

HookProfileFormat hook_profile_format(const toml::node& node, const std::string& key) {
  constexpr std::array formats{HookProfileFormat::csv, HookProfileFormat::simpack,
                               HookProfileFormat::miniprof};
  return formats[one_of(node, key, {"csv", "simpack", "miniprof"},
                        "use csv (y, z in mm), simpack (.prw/.prr) or miniprof (.whl/.ban)")];
}

std::vector<WheelsetStateSpec> inline_states(const toml::node& node, const std::string& key) {
  const toml::array* array = node.as_array();
  if (!array || !array->is_array_of_tables()) {
    throw InputError(where(node.source(), key) +
                     ": expected [[load_collective.state]] tables, one per state");
  }
  std::vector<WheelsetStateSpec> states;
  for (const toml::node& element : *array) {
    const toml::table& table = *element.as_table();
    WheelsetStateSpec state;
    state.line = static_cast<int>(table.source().begin.line);
    for (auto&& [name, value] : table) {
      const std::string field(name.str());
      const std::string place = where(name.source(), key + "." + field);
      detail::StateField f{field, 0.0, {}};
      if (field == "label" || field == "section") {
        f.text = text(value, key + "." + field);
      } else {
        const auto v = value.value<double>();
        if (!v || value.is_boolean()) throw InputError(place + ": expected a number (SI units)");
        f.number = *v;
      }
      detail::set_state_field(state, f, where(name.source(), key));
    }
    detail::finish_state(state, "scene line " + std::to_string(state.line) + ": " + key);
    states.push_back(std::move(state));
  }
  return states;
}

}  // namespace wheelwear::pipeline::detail
