#pragma once
/// One table per enumeration maps each value to the name the command line, scenes and result
/// files use; the functions below read it both ways, so no module writes its own lookup.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wheelwear::core {

/// The names of an enumeration's N values, in the order they are listed to users.
template <class Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

/// The name of `value` in `table`; "unknown" when the table does not list it.
template <class Enum, std::size_t N>
constexpr std::string_view name_of(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return "unknown";
}

/// The value named `name` (exact, case-sensitive match); std::nullopt when none is.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> value_named(const NameTable<Enum, N>& table, std::string_view name) {
  for (const auto& [v, text] : table)
    if (text == name) return v;
  return std::nullopt;
}

/// Every name, in the table's order (for a command line's list of choices).
template <class Enum, std::size_t N>
std::vector<std::string> all_names(const NameTable<Enum, N>& table) {
  std::vector<std::string> out;
  for (const auto& [v, name] : table) out.emplace_back(name);
  return out;
}

/// "a, b, c": the names for a message that lists the choices.
template <class Enum, std::size_t N>
std::string list_names(const NameTable<Enum, N>& table) {
  std::string out;
  for (const auto& [v, name] : table) out.append(out.empty() ? "" : ", ").append(name);
  return out;
}

}  // namespace wheelwear::core
