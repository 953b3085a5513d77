#include "wheelwear/core/toml_keys.hpp"

#include <cmath>
#include <sstream>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::core {

namespace {

// A hint for a key that is unknown only by its unit suffix (radius_mm for radius_m).
std::string unit_hint(std::string_view key, const std::map<std::string, TomlKeyHandler>& known) {
  const std::size_t cut = key.rfind('_');
  if (cut == std::string_view::npos) return {};
  const std::string_view stem = key.substr(0, cut);
  for (const auto& [name, handler] : known) {
    if (name.size() > stem.size() && name.compare(0, stem.size(), stem) == 0 &&
        name[stem.size()] == '_') {
      return "; did you mean '" + name + "'? Keys carry SI units (m, N, Pa, m/s as _m_s)";
    }
  }
  return {};
}

}  // namespace

std::string TomlKeys::format(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string TomlKeys::where(const toml::source_region& source, std::string_view key) const {
  std::ostringstream out;
  out << document_ << " line " << source.begin.line << ": " << key;
  return out.str();
}

double TomlKeys::number(const toml::node& node, const std::string& key, double lo, double hi,
                        std::string_view meaning) const {
  const auto value = node.value<double>();  // integers convert too
  if (!value || node.is_boolean()) {
    throw InputError(where(node.source(), key) + ": expected a number (" + std::string(meaning) +
                     ")");
  }
  if (!std::isfinite(*value) || *value < lo || *value > hi) {
    throw InputError(where(node.source(), key) + " = " + format(*value) + ": " +
                     std::string(meaning) + " must lie in [" + format(lo) + ", " +
                     format(hi) + "]");
  }
  return *value;
}

int TomlKeys::integer(const toml::node& node, const std::string& key, int lo, int hi,
                      std::string_view meaning) const {
  const auto value = node.value_exact<int64_t>();
  if (!value || *value < lo || *value > hi) {
    throw InputError(where(node.source(), key) + ": expected a whole number in [" +
                     std::to_string(lo) + ", " + std::to_string(hi) + "] (" + std::string(meaning) +
                     ")");
  }
  return static_cast<int>(*value);
}

std::string TomlKeys::text(const toml::node& node, const std::string& key) const {
  const auto value = node.value_exact<std::string>();
  if (!value) throw InputError(where(node.source(), key) + ": expected a quoted string");
  return *value;
}

bool TomlKeys::boolean(const toml::node& node, const std::string& key) const {
  const auto value = node.value_exact<bool>();
  if (!value) throw InputError(where(node.source(), key) + ": expected true or false");
  return *value;
}

void TomlKeys::read_table(const toml::table& table, const std::string& section,
                          const std::map<std::string, TomlKeyHandler>& handlers) const {
  for (auto&& [key, node] : table) {
    const std::string name(key.str());
    const auto handler = handlers.find(name);
    if (handler == handlers.end()) {
      std::string allowed;
      for (const auto& [known, unused] : handlers) allowed += (allowed.empty() ? "" : ", ") + known;
      throw InputError(where(key.source(), section.empty() ? name : section + "." + name) +
                       ": unknown key" + unit_hint(name, handlers) + " (allowed here: " + allowed +
                       ")");
    }
    handler->second(node, section.empty() ? name : section + "." + name);
  }
}

}  // namespace wheelwear::core
