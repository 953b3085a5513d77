#pragma once
// The scene's key readers: core::TomlKeys with "scene" in every message.

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/toml_keys.hpp"

namespace wheelwear::pipeline::detail {

using KeyHandler = core::TomlKeyHandler;

inline const core::TomlKeys& scene_keys() {
  static const core::TomlKeys keys("scene");
  return keys;
}

inline std::string where(const toml::source_region& source, std::string_view key) {
  return scene_keys().where(source, key);
}
inline std::string format(double v) {
  return core::TomlKeys::format(v);
}
inline double number(const toml::node& node, const std::string& key, double lo, double hi,
                     std::string_view meaning) {
  return scene_keys().number(node, key, lo, hi, meaning);
}
inline int integer(const toml::node& node, const std::string& key, int lo, int hi,
                   std::string_view meaning) {
  return scene_keys().integer(node, key, lo, hi, meaning);
}
inline std::string text(const toml::node& node, const std::string& key) {
  return scene_keys().text(node, key);
}
inline bool boolean(const toml::node& node, const std::string& key) {
  return scene_keys().boolean(node, key);
}
// The index in `names` of the text at `key`; any other text is refused, `hint` saying what to
// give instead.
inline std::size_t one_of(const toml::node& node, const std::string& key,
                          std::initializer_list<std::string_view> names, std::string_view hint) {
  const std::string name = text(node, key);
  std::size_t index = 0;
  for (std::string_view candidate : names) {
    if (candidate == name) return index;
    ++index;
  }
  throw InputError(where(node.source(), key) + " = \"" + name + "\": " + std::string(hint));
}
// The value `table` names by the text at `key`; any other text is refused naming the choices,
// `what` saying what the key chooses ("FASTSIM scheme").
template <class Enum, std::size_t N>
Enum named(const toml::node& node, const std::string& key, const core::NameTable<Enum, N>& table,
           std::string_view what) {
  const std::string name = text(node, key);
  if (const auto value = core::value_named(table, name)) return *value;
  throw InputError(where(node.source(), key) + " = \"" + name + "\": unknown " + std::string(what) +
                   "; use " + core::list_names(table));
}
inline void read_table(const toml::table& table, const std::string& section,
                       const std::map<std::string, KeyHandler>& handlers) {
  scene_keys().read_table(table, section, handlers);
}

}  // namespace wheelwear::pipeline::detail
