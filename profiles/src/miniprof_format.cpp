#include "wheelwear/profiles/miniprof_format.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::profiles {

using core::check_text;
using core::format_number;
using core::parse_number;
using core::split_lines;
using core::to_lower;
using core::trim;
using core::write_file_atomically;

namespace {

std::vector<std::string> split_values(std::string_view line) {
  std::vector<std::string> out;
  std::string token;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!token.empty()) out.push_back(token);
      token.clear();
    } else {
      token.push_back(c);
    }
  }
  if (!token.empty()) out.push_back(token);
  return out;
}

}  // namespace

RawProfile parse_miniprof(std::string_view text, std::string_view source,
                          std::string_view extension, const ReadOptions& options) {
  (void)options;
  check_text(text, source);
  RawProfile raw;
  raw.source = std::string(source);
  raw.format = "miniprof";
  const std::string src(source);
  const auto lines = split_lines(text);
  bool old_layout = false;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, lines.size()); ++i)
    if (lines[i].find("MINIPROF") != std::string_view::npos) old_layout = true;
  const std::string ext = to_lower(extension);
  if (ext == ".whl" || (!lines.empty() && lines.front().rfind("#MINIWHEELPROF", 0) == 0))
    raw.body = Body::wheel;
  else if (ext == ".ban")
    raw.body = Body::rail;

  bool in_data = false;
  std::vector<std::vector<double>> rows;
  std::vector<int> row_lines;
  std::string column_def = "X,Y";
  std::optional<double> declared_points;
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const int number = static_cast<int>(index + 1);
    const std::string_view line = trim(lines[index]);
    const auto where = [&] { return src + ":" + std::to_string(number); };
    if (line.empty()) {
      in_data = true;  // the points follow the first empty line
      continue;
    }
    if (line.front() == '"') {
      // Older layout: '"' introduces the instrument's Sd, Sh, qR when "(Sd/Sh/qR)" follows;
      // newer layout: a quoted key=value line.
      std::string_view inner = line.substr(1);
      if (!inner.empty() && inner.back() == '"') inner.remove_suffix(1);
      const auto eq = inner.find('=');
      if (eq != std::string_view::npos) {
        const std::string key(trim(inner.substr(0, eq)));
        const std::string value(trim(inner.substr(eq + 1)));
        raw.header.emplace_back(key, value);
        if (key == "ColumnDef") column_def = value;
        continue;
      }
      const bool labelled = index + 1 < lines.size() &&
                            trim(lines[index + 1]).find("Sd/Sh/qR") != std::string_view::npos;
      const auto values = split_values(inner);
      if (labelled && values.size() == 3) {
        const char* names[] = {"Sd", "Sh", "qR"};
        for (std::size_t k = 0; k < 3; ++k) raw.header.emplace_back(names[k], values[k]);
      }
      continue;
    }
    const auto eq = line.find('=');
    if (eq != std::string_view::npos) {
      const std::string key(trim(line.substr(0, eq)));
      const std::string value(trim(line.substr(eq + 1)));
      raw.header.emplace_back(key, value);
      if (key == "ColumnDef") column_def = value;
      if (key == "XYPoints" && !value.empty()) {
        declared_points = parse_number(value);
        if (!declared_points || *declared_points < 0.0)
          throw InputError(where() + ": XYPoints=" + value + " is not a point count");
      }
      continue;
    }
    if (!in_data) {
      if (old_layout) continue;  // free header text of the older layout
      throw InputError(where() + ": \"" + std::string(line.substr(0, 60)) +
                       "\" is neither a key=value header line nor a point row");
    }
    std::vector<double> values;
    for (const std::string& token : split_values(line)) {
      const auto value = parse_number(token);
      if (!value)
        throw InputError(where() + ": \"" + std::string(line.substr(0, 60)) +
                         "\" is not a row of numbers");
      values.push_back(*value);
    }
    if (!rows.empty() && values.size() != rows.front().size())
      throw InputError(where() + ": " + std::to_string(values.size()) + " values, but line " +
                       std::to_string(row_lines.front()) + " has " +
                       std::to_string(rows.front().size()) + " (truncated line?)");
    rows.push_back(std::move(values));
    row_lines.push_back(number);
  }

  // ColumnDef names the columns one letter each: X lateral, Y vertical.
  std::vector<std::string> columns;
  for (const std::string& c : split_values(column_def)) columns.push_back(c);
  const auto x = std::find(columns.begin(), columns.end(), "X");
  const auto y = std::find(columns.begin(), columns.end(), "Y");
  if (x == columns.end() || y == columns.end())
    throw InputError(src + ": ColumnDef=" + column_def + " names no X and Y columns");
  const auto xi = static_cast<std::size_t>(x - columns.begin());
  const auto yi = static_cast<std::size_t>(y - columns.begin());
  if (!rows.empty() && std::max(xi, yi) >= rows.front().size())
    throw InputError(src + ":" + std::to_string(row_lines.front()) + ": " +
                     std::to_string(rows.front().size()) + " values per row, but ColumnDef=" +
                     column_def + " needs column " + std::to_string(std::max(xi, yi) + 1));
  if (declared_points && static_cast<double>(rows.size()) != *declared_points)
    throw InputError(src + ": the header declares XYPoints=" + format_number(*declared_points) +
                     " but " + std::to_string(rows.size()) +
                     " points were read (truncated or damaged file?)");
  for (const auto& row : rows) raw.points.emplace_back(row[xi] * 1e-3, row[yi] * 1e-3);
  raw.lines = std::move(row_lines);
  raw.notes.push_back(std::string("MiniProf ") + (old_layout ? "older" : "key=value") +
                      " layout, ColumnDef=" + column_def + ", mm");
  return raw;
}

std::string format_miniprof(const PointList& points, Body body) {
  std::string out;
  if (body == Body::wheel) {
    out = "#MINIWHEELPROF\nwheelwear\nMINIPROF text export\n\n";
  } else {
    out = "Filename=wheelwear\nProgramName=wheelwear\nXYPoints=" + std::to_string(points.size()) +
          "\nColumnDef=X,Y\n\n";
  }
  const double sign = body == Body::wheel ? 1.0 : -1.0;
  for (const Point& p : points) {
    require_finite("written profile y [m]", p[0]);
    require_finite("written profile z [m]", p[1]);
    out += format_number(sign * p[0] * 1e3) + " " + format_number(sign * p[1] * 1e3) + "\n";
  }
  return out;
}

void write_miniprof(const std::filesystem::path& path, const PointList& points, Body body) {
  write_file_atomically(path, format_miniprof(points, body));
}

}  // namespace wheelwear::profiles
