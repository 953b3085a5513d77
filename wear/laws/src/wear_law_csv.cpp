#include "wear_law_csv.hpp"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::wear::detail {

using core::trim;

namespace {

std::vector<std::string> split(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.emplace_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string_view column_name(std::string_view header, std::size_t column) {
  std::size_t start = 0;
  for (std::size_t i = 0; i < column; ++i) start = header.find(',', start) + 1;
  return header.substr(start, header.find(',', start) - start);
}

}  // namespace

std::string RowNaming::at(std::size_t row) const {
  if (lines.empty()) return source + ": regime " + std::to_string(row + 1);
  return source + ":" + std::to_string(lines[row]);
}

std::string RowNaming::other(std::size_t row) const {
  if (lines.empty()) return "regime " + std::to_string(row + 1);
  return "line " + std::to_string(lines[row]);
}

void table_error(std::string_view source, int line, std::string_view problem) {
  std::string message(source);
  if (line > 0) message += ":" + std::to_string(line);
  message += ": ";
  message += problem;
  throw InputError(message);
}

std::vector<TableLine> read_table(std::istream& in, std::string_view source,
                                  std::string_view header) {
  const std::size_t columns = split(header).size();
  std::vector<TableLine> rows;
  bool header_seen = false;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (!text.empty() && text.back() == '\r') text.pop_back();  // files written on Windows
    const std::string_view line = trim(text);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string> fields = split(line);
    if (!header_seen) {
      std::string joined;
      for (std::size_t i = 0; i < fields.size(); ++i) joined += (i ? "," : "") + fields[i];
      if (joined != header) {
        table_error(
            source, number,
            "bad header: expected '" + std::string(header) + "', got '" + std::string(line) + "'");
      }
      header_seen = true;
      continue;
    }
    if (fields.size() != columns) {
      table_error(source, number,
                  "expected " + std::to_string(columns) + " comma-separated fields, got " +
                      std::to_string(fields.size()));
    }
    rows.push_back({number, std::move(fields)});
  }
  if (!header_seen) {
    table_error(source, 0, "empty file: expected the header '" + std::string(header) + "'");
  }
  if (rows.empty()) table_error(source, 0, "no rows after the header");
  return rows;
}

double table_number(const TableLine& line, std::size_t column, std::string_view header,
                    std::string_view source, bool allow_infinity) {
  const std::string& field = line.fields[column];
  const std::string where = "column '" + std::string(column_name(header, column)) + "': ";
  // std::from_chars, strict: no '+', and a literal out of range (1e999, 1e-400) is refused
  // rather than taken as infinity or zero.
  double value = 0.0;
  const char* const end = field.data() + field.size();
  const auto [stop, error] = std::from_chars(field.data(), end, value);
  if (field.empty() || error != std::errc() || stop != end)
    table_error(source, line.number, where + "'" + field + "' is not a number");
  if (std::isnan(value)) table_error(source, line.number, where + "NaN is not a valid value");
  if (std::isinf(value) && !allow_infinity) {
    table_error(source, line.number, where + "'" + field + "' must be finite");
  }
  return value;
}

void check_row_name(const std::string& name, const RowNaming& naming, std::size_t row) {
  const bool valid = !name.empty() && name.find_first_of(",\r\n") == std::string::npos &&
                     trim(name).size() == name.size() && name.front() != '#';
  if (!valid) {
    throw InputError(naming.at(row) + ": regime name '" + name +
                     "' must be non-empty, without commas, line breaks or surrounding spaces, "
                     "and not start with '#'");
  }
}

void write_table_line(std::ostream& out, const std::string& name,
                      std::initializer_list<double> numbers) {
  out << name;
  for (const double number : numbers) out << ',' << core::format_number(number);
  out << '\n';
}

}  // namespace wheelwear::wear::detail
