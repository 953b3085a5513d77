#include "wheelwear/profiles/raw_profile.hpp"

#include <algorithm>
#include <sstream>

#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::profiles {

namespace {
constexpr core::NameTable<LengthUnit, 3> kUnitNames = {{
    {LengthUnit::automatic, "auto"},
    {LengthUnit::millimetre, "mm"},
    {LengthUnit::metre, "m"},
}};

constexpr std::size_t kQuoteLimit = 200;
constexpr std::size_t kListedLines = 20;

const WrittenPoint* find_written(const std::vector<WrittenPoint>& written, int line) {
  if (line <= 0) return nullptr;
  const auto it = std::lower_bound(written.begin(), written.end(), line,
                                   [](const WrittenPoint& w, int l) { return w.line < l; });
  return it != written.end() && it->line == line ? &*it : nullptr;
}

}  // namespace

std::optional<LengthUnit> parse_length_unit(std::string_view text) {
  return core::value_named(kUnitNames, text);
}

std::string quote_line(std::string_view line) {
  line = core::trim(line);
  if (line.size() <= kQuoteLimit) return std::string(line);
  return std::string(line.substr(0, kQuoteLimit)) + "...";
}

std::string trailing_comment_text(std::size_t rows, std::string_view characters) {
  return std::to_string(rows) +
         (rows == 1 ? " point row carries text after its numbers"
                    : " point rows carry text after their numbers") +
         ", read as a comment (after " + std::string(characters) + ")";
}

std::string_view strip_row_comment(std::string_view line, bool& comment) {
  const auto at = line.find_first_of("\"%!#");
  comment = at != std::string_view::npos;
  return core::trim(comment ? line.substr(0, at) : line);
}

std::string RawProfile::where(std::size_t i) const {
  if (i < lines.size() && lines[i] > 0) return source + ":" + std::to_string(lines[i]);
  return source;
}

std::string RawProfile::as_written(std::size_t i) const {
  const int line = i < lines.size() ? lines[i] : 0;
  if (const WrittenPoint* w = find_written(written, line))
    return lateral_name + " = " + w->lateral + ", " + vertical_name + " = " + w->vertical;
  std::ostringstream out;
  out.precision(6);
  out << "y = " << (i < points.size() ? points[i][0] * 1e3 : 0.0) << " mm";
  return out.str();
}

std::string RawProfile::written_note() const {
  if (written.empty()) return "";
  return " (values as written in the file" + (written_unit.empty() ? "" : ", " + written_unit) +
         ")";
}

std::optional<std::string> RawProfile::header_value(std::string_view key) const {
  for (auto it = header.rbegin(); it != header.rend(); ++it)
    if (it->first == key) return it->second;
  return std::nullopt;
}

void RawProfile::add_repair(std::string name, std::vector<int> lines_concerned,
                            std::string_view text, bool warning) {
  ReadRepair repair;
  repair.name = std::move(name);
  std::sort(lines_concerned.begin(), lines_concerned.end());
  repair.count = lines_concerned.size();
  repair.message = source;
  if (!lines_concerned.empty()) {
    repair.message += ':';  // appended piece by piece: GCC 12 warns falsely on ":" + std::string
    repair.message += std::to_string(lines_concerned.front());
  }
  repair.message += ": ";
  repair.message += text;
  if (lines_concerned.size() > kListedLines) lines_concerned.resize(kListedLines);
  repair.lines = std::move(lines_concerned);
  repair.warning = warning;
  repairs.push_back(std::move(repair));
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
