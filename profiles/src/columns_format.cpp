#include "wheelwear/profiles/columns_format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
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

std::vector<std::string> tokens_of(std::string_view line) {
  // Semicolon-separated files are the European spreadsheet export, where the comma is the
  // decimal separator.
  const bool semicolons = line.find(';') != std::string_view::npos;
  std::vector<std::string> tokens;
  std::string current;
  auto flush = [&] {
    if (!current.empty()) tokens.push_back(current);
    current.clear();
  };
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ';' || (!semicolons && c == ',')) {
      flush();
    } else {
      current.push_back(semicolons && c == ',' ? '.' : c);
    }
  }
  flush();
  return tokens;
}

// Column names: split at commas, semicolons or tabs when the line has any (names may contain
// blanks, "y [mm]"), otherwise at blanks, re-attaching a bracketed unit to its name ("y [mm]").
std::vector<std::string> header_tokens(std::string_view line) {
  const bool delimited = line.find_first_of(",;\t") != std::string_view::npos;
  std::vector<std::string> tokens;
  std::string current;
  for (char c : line) {
    if (delimited ? (c == ',' || c == ';' || c == '\t') : (c == ' ')) {
      tokens.emplace_back(trim(current));
      current.clear();
    } else {
      current.push_back(c);
    }
  }
  tokens.emplace_back(trim(current));
  std::vector<std::string> out;
  for (const std::string& token : tokens) {
    if (token.empty()) continue;
    if (!out.empty() && (token.front() == '[' || token.front() == '('))
      out.back() += " " + token;
    else
      out.push_back(token);
  }
  return out;
}

struct ColumnName {
  std::string base;                // lower-case name without its unit
  std::optional<LengthUnit> unit;  // unit written on the name, if any
};

ColumnName parse_column_name(std::string_view token) {
  std::string name = to_lower(trim(token));
  ColumnName out;
  // A unit in brackets or parentheses, or as a suffix "_mm", "_m", "/mm".
  for (const char* open : {"[", "("}) {
    const auto at = name.find(open);
    if (at == std::string::npos) continue;
    const auto close = name.find_first_of("])", at);
    const std::string unit(
        trim(name.substr(at + 1, close == std::string::npos ? std::string::npos : close - at - 1)));
    name = std::string(trim(name.substr(0, at)));
    if (unit == "mm") out.unit = LengthUnit::millimetre;
    if (unit == "m") out.unit = LengthUnit::metre;
  }
  for (const char* sep : {"_", "/", " "}) {
    const auto at = name.rfind(sep);
    if (at == std::string::npos) continue;
    const std::string unit = name.substr(at + 1);
    if (unit == "mm" || unit == "m") {
      out.unit = unit == "mm" ? LengthUnit::millimetre : LengthUnit::metre;
      name = name.substr(0, at);
    }
  }
  out.base = name;
  return out;
}

bool is_lateral(const std::string& name) {
  return name == "y" || name == "lateral" || name == "lat" || name.rfind("y", 0) == 0;
}
bool is_vertical(const std::string& name) {
  return name == "z" || name == "vertical" || name == "height" || name.rfind("z", 0) == 0;
}

bool all_numbers(const std::vector<std::string>& tokens) {
  return !tokens.empty() && std::all_of(tokens.begin(), tokens.end(), [](const std::string& t) {
    return parse_number(t).has_value();
  });
}

double span(const std::vector<std::vector<double>>& rows, std::size_t column) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& row : rows)
    if (std::isfinite(row[column])) {
      lo = std::min(lo, row[column]);
      hi = std::max(hi, row[column]);
    }
  return hi >= lo ? hi - lo : 0.0;
}

}  // namespace

RawProfile parse_columns(std::string_view text, std::string_view source,
                         const ReadOptions& options) {
  check_text(text, source);
  RawProfile raw;
  raw.source = std::string(source);
  raw.format = "columns";
  std::vector<ColumnName> header;
  std::vector<std::string> header_names;  // as written, for messages
  int header_line = 0;
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<std::string>> row_tokens;
  std::vector<int> row_lines, comment_lines;
  const auto lines = split_lines(text);
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const int number = static_cast<int>(index + 1);
    std::string_view line = trim(lines[index]);
    if (line.empty()) continue;
    if (line.front() == '#' || line.front() == '%' || line.front() == '!' ||
        line.substr(0, 2) == "//") {
      // wheelwear's own metadata comments: "# body: wheel", "# side: right".
      const std::string comment = to_lower(trim(line.substr(line.front() == '/' ? 2 : 1)));
      if (comment == "body: wheel" || comment == "body: rail") {
        raw.body = comment == "body: wheel" ? Body::wheel : Body::rail;
        raw.body_line = number;
      }
      if (comment == "side: left") raw.side = Side::left;
      if (comment == "side: right") raw.side = Side::right;
      continue;
    }
    // A row of numbers followed by a comment ('"', '%', '!' or '#', as CONTACT reads profiles) is
    // a point row; in other lines only '#' starts a comment (a header may quote its names).
    bool commented = false;
    const std::string_view before = strip_row_comment(line, commented);
    if (commented && !before.empty() && all_numbers(tokens_of(before))) {
      line = before;
      comment_lines.push_back(number);
    } else if (const auto hash = line.find('#'); hash != std::string_view::npos) {
      line = trim(line.substr(0, hash));
    }
    std::vector<std::string> tokens = tokens_of(line);
    if (tokens.empty()) continue;
    std::vector<double> values;
    for (const std::string& token : tokens) {
      const auto value = parse_number(token);
      if (!value) break;
      values.push_back(*value);
    }
    if (values.size() != tokens.size()) {
      if (rows.empty() && header.empty()) {
        for (const std::string& token : header_tokens(line)) {
          header.push_back(parse_column_name(token));
          header_names.push_back(token);
        }
        header_line = number;
        continue;
      }
      throw InputError(raw.source + ":" + std::to_string(number) + ": \"" +
                       quote_line(lines[index]) + "\" is not a row of numbers");
    }
    if (values.size() < 2)
      throw InputError(raw.source + ":" + std::to_string(number) + ": " +
                       std::to_string(values.size()) +
                       " value where at least 2 columns (y, z) are expected (truncated line?)");
    if (!rows.empty() && values.size() != rows.front().size())
      throw InputError(raw.source + ":" + std::to_string(number) + ": " +
                       std::to_string(values.size()) + " values, but line " +
                       std::to_string(row_lines.front()) + " has " +
                       std::to_string(rows.front().size()));
    rows.push_back(std::move(values));
    row_tokens.push_back(std::move(tokens));
    row_lines.push_back(number);
  }
  if (!comment_lines.empty())
    raw.add_repair("trailing_comments", comment_lines,
                   trailing_comment_text(comment_lines.size(), "\", %, ! or #"));
  if (rows.empty()) {
    raw.notes.push_back("no numeric rows");
    return raw;
  }

  // Column order.
  std::size_t y_column = 0, z_column = 1;
  if (options.columns == ColumnOrder::z_y) {
    std::swap(y_column, z_column);
  } else if (options.columns == ColumnOrder::automatic) {
    std::optional<std::size_t> lateral, vertical;
    for (std::size_t c = 0; c < header.size() && c < rows.front().size(); ++c) {
      if (!vertical && is_vertical(header[c].base))
        vertical = c;
      else if (!lateral && is_lateral(header[c].base))
        lateral = c;
    }
    if (!vertical) {
      // MiniProf-style names: x lateral, y vertical.
      std::optional<std::size_t> x, y;
      for (std::size_t c = 0; c < header.size() && c < rows.front().size(); ++c) {
        if (!x && header[c].base.rfind("x", 0) == 0) x = c;
        if (!y && header[c].base.rfind("y", 0) == 0) y = c;
      }
      if (x && y) {
        lateral = x;
        vertical = y;
      }
    }
    if (lateral && vertical) {
      y_column = *lateral;
      z_column = *vertical;
      raw.notes.push_back("columns from the header (line " + std::to_string(header_line) + ")");
    } else if (span(rows, 1) > 1.2 * span(rows, 0)) {
      std::swap(y_column, z_column);
      raw.notes.push_back("no usable header: the second column spans more, so it is taken as y");
    } else {
      raw.notes.push_back("no usable header: first column y, second z");
    }
  }

  // Unit.
  LengthUnit unit = options.unit;
  if (unit == LengthUnit::automatic) {
    std::optional<LengthUnit> from_header;
    for (std::size_t c : {y_column, z_column})
      if (c < header.size() && header[c].unit) {
        if (from_header && *from_header != *header[c].unit)
          throw InputError(raw.source + ":" + std::to_string(header_line) +
                           ": the header gives different units for y and z");
        from_header = header[c].unit;
      }
    if (from_header) {
      unit = *from_header;
      raw.notes.push_back(std::string("unit from the header: ") +
                          (unit == LengthUnit::millimetre ? "mm" : "m"));
    } else {
      unit = std::max(span(rows, y_column), span(rows, z_column)) > 1.0 ? LengthUnit::millimetre
                                                                        : LengthUnit::metre;
      raw.notes.push_back(std::string("unit from the magnitudes: ") +
                          (unit == LengthUnit::millimetre ? "mm" : "m"));
    }
  }
  const double scale = unit == LengthUnit::millimetre ? 1e-3 : 1.0;
  raw.points.reserve(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    raw.points.emplace_back(rows[r][y_column] * scale, rows[r][z_column] * scale);
    raw.written.push_back({row_lines[r], row_tokens[r][y_column], row_tokens[r][z_column]});
  }
  raw.lines = std::move(row_lines);
  raw.written_unit = unit == LengthUnit::millimetre ? "mm" : "m";
  if (y_column < header_names.size() && z_column < header_names.size()) {
    raw.lateral_name = header_names[y_column];
    raw.vertical_name = header_names[z_column];
  }
  return raw;
}

std::string format_csv(const PointList& points, const CsvWriteOptions& options) {
  require(options.unit != LengthUnit::automatic, "CSV unit", 0.0, "must be mm or m");
  const bool mm = options.unit == LengthUnit::millimetre;
  const double scale = mm ? 1e3 : 1.0;
  std::string out = "# wheelwear profile\n";
  if (!options.name.empty()) out += "# name: " + options.name + "\n";
  if (options.body) out += "# body: " + std::string(to_string(*options.body)) + "\n";
  if (options.side) out += "# side: " + std::string(to_string(*options.side)) + "\n";
  out += "# frame: y lateral (+ towards the field side), z vertical (+ downwards)\n";
  out += mm ? "y_mm,z_mm\n" : "y_m,z_m\n";
  for (const Point& p : points) {
    require_finite("written profile y [m]", p[0]);
    require_finite("written profile z [m]", p[1]);
    out += format_number(p[0] * scale) + "," + format_number(p[1] * scale) + "\n";
  }
  return out;
}

void write_csv(const std::filesystem::path& path, const PointList& points,
               const CsvWriteOptions& options) {
  write_file_atomically(path, format_csv(points, options));
}

}  // namespace wheelwear::profiles
