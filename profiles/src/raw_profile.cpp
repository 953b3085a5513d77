#include "wheelwear/profiles/raw_profile.hpp"

#include "wheelwear/core/enum_names.hpp"

namespace wheelwear::profiles {

namespace {
constexpr core::NameTable<LengthUnit, 3> kUnitNames = {{
    {LengthUnit::automatic, "auto"},
    {LengthUnit::millimetre, "mm"},
    {LengthUnit::metre, "m"},
}};
}  // namespace

std::optional<LengthUnit> parse_length_unit(std::string_view text) {
  return core::value_named(kUnitNames, text);
}

std::string RawProfile::where(std::size_t i) const {
  if (i < lines.size() && lines[i] > 0) return source + ":" + std::to_string(lines[i]);
  return source;
}

std::optional<std::string> RawProfile::header_value(std::string_view key) const {
  for (auto it = header.rbegin(); it != header.rend(); ++it)
    if (it->first == key) return it->second;
  return std::nullopt;
}

void RawProfile::erase_if(const std::vector<bool>& remove) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (remove[i]) continue;
    points[kept] = points[i];
    if (i < lines.size()) lines[kept] = lines[i];
    ++kept;
  }
  points.resize(kept);
  lines.resize(std::min(lines.size(), kept));
}

}  // namespace wheelwear::profiles
