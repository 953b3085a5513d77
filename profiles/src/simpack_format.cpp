#include "wheelwear/profiles/simpack_format.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::profiles {

using core::check_text;
using core::format_number;
using core::parse_number;
using core::split_lines;
using core::trim;
using core::write_file_atomically;

namespace {

// Text before a '!' that is not inside a quoted string.
std::string_view strip_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'' || line[i] == '"') quoted = !quoted;
    if (line[i] == '!' && !quoted) return line.substr(0, i);
  }
  return line;
}

std::string unquote(std::string_view value) {
  value = trim(value);
  if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"') &&
      value.back() == value.front())
    value = value.substr(1, value.size() - 2);
  return std::string(trim(value));
}

}  // namespace

RawProfile parse_simpack(std::string_view text, std::string_view source,
                         const ReadOptions& options) {
  (void)options;
  check_text(text, source);
  RawProfile raw;
  raw.source = std::string(source);
  raw.format = "simpack";
  const std::string src(source);
  const auto lines = split_lines(text);
  std::string section;  // "", "header", "spline", "point"
  bool saw_points = false, points_ended = false;
  std::map<std::string, double> numbers;
  std::vector<double> weights;
  int last_line = 0, type_line = 0;
  std::vector<int> comment_lines;
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const int number = static_cast<int>(index + 1);
    last_line = number;
    const std::string_view line = trim(strip_comment(lines[index]));
    if (line.empty()) continue;
    const auto where = [&] { return src + ":" + std::to_string(number); };
    if (line.size() > 6 && line.substr(line.size() - 6) == ".begin") {
      const std::string name(trim(line.substr(0, line.size() - 6)));
      if (name == "point") {
        if (section != "spline")
          throw InputError(where() + ": point.begin outside the spline section");
        saw_points = true;
      } else if (name != "header" && name != "spline") {
        throw InputError(where() + ": unknown section \"" + name + "\"");
      }
      section = name;
      continue;
    }
    if (line.size() > 4 && line.substr(line.size() - 4) == ".end") {
      const std::string name(trim(line.substr(0, line.size() - 4)));
      if (name != section)
        throw InputError(where() + ": \"" + std::string(line) + "\" does not close section \"" +
                         section + "\"");
      if (name == "point") points_ended = true;
      section = name == "point" ? "spline" : "";
      continue;
    }
    if (section == "point") {
      // '!' comments are the format's; text after '"', '%' or '#' is a comment as well (CONTACT's
      // readers treat it so), recorded as a repair.
      bool commented = false;
      const std::string_view row = strip_row_comment(line, commented);
      if (row.empty()) continue;
      if (commented) comment_lines.push_back(number);
      std::vector<double> values;
      std::vector<std::string> tokens;
      std::string token;
      bool numeric = true;
      auto flush = [&] {
        if (token.empty()) return;
        const auto value = parse_number(token);
        if (!value)
          numeric = false;
        else
          values.push_back(*value);
        tokens.push_back(token);
        token.clear();
      };
      for (char c : row) {
        if (c == ' ' || c == '\t' || c == ',')
          flush();
        else
          token.push_back(c);
      }
      flush();
      if (!numeric)
        throw InputError(where() + ": \"" + quote_line(lines[index]) +
                         "\" is not a row of numbers in the point block");
      if (values.size() < 2 || values.size() > 3)
        throw InputError(where() + ": " + std::to_string(values.size()) +
                         " values where \"y z [weight]\" is expected (truncated line?)");
      raw.points.emplace_back(values[0], values[1]);
      raw.lines.push_back(number);
      raw.written.push_back({number, tokens[0], tokens[1]});
      weights.push_back(values.size() == 3 ? values[2] : 1.0);
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string_view::npos || section.empty())
      throw InputError(where() + ": \"" + quote_line(lines[index]) +
                       "\" is neither a key = value line nor a section marker");
    const std::string key = section + "." + std::string(trim(line.substr(0, eq)));
    const std::string value = unquote(line.substr(eq + 1));
    raw.header.emplace_back(key, value);
    if (key == "header.type") type_line = number;
    if (const auto v = parse_number(value)) numbers[key] = *v;
  }
  if (!saw_points) throw InputError(src + ": no point block (point.begin ... point.end)");
  if (!points_ended)
    throw InputError(src + ":" + std::to_string(last_line) +
                     ": the file ends inside the point block (point.end missing): truncated?");

  if (numbers.count("header.type")) {
    const double type = numbers["header.type"];
    require(type == 0.0 || type == 1.0, src + ": header type", type,
            "must be 0 (rail) or 1 (wheel)");
    raw.body = type == 1.0 ? Body::wheel : Body::rail;
    raw.body_line = type_line;
    raw.body_evidence = type == 1.0 ? "type = 1" : "type = 0";
  }
  if (!comment_lines.empty())
    raw.add_repair("trailing_comments", comment_lines,
                   trailing_comment_text(comment_lines.size(), "\", % or #"));
  auto get = [&](const std::string& key, double fallback) {
    const auto it = numbers.find("spline." + key);
    return it == numbers.end() ? fallback : it->second;
  };
  for (const char* key :
       {"point.dist.min", "shift.y", "shift.z", "rotate", "bound.y.min", "bound.y.max",
        "bound.z.min", "bound.z.max", "units.len.f", "units.ang.f"})
    require_finite(src + ": spline " + key, get(key, 0.0));

  // The processing steps, in SIMPACK's order.
  auto& pts = raw.points;
  const double dist_min = get("point.dist.min", 0.0);
  if (dist_min >= 1e-12 && !pts.empty()) {
    std::vector<bool> drop(pts.size(), false);
    double last_y = pts.front()[0];
    for (std::size_t i = 1; i < pts.size(); ++i) {
      if (std::abs(pts[i][0] - last_y) > dist_min)
        last_y = pts[i][0];
      else
        drop[i] = true;
    }
    raw.erase_if(drop);
    raw.notes.push_back("point.dist.min applied");
  }
  const Point shift(get("shift.y", 0.0), get("shift.z", 0.0));
  if (shift.squaredNorm() > 0.0) {
    for (Point& p : pts) p += shift;
    raw.notes.push_back("shift.y/shift.z applied");
  }
  const double angle_factor = get("units.ang.f", 1.0);
  require(angle_factor > 0.0, src + ": spline units.ang.f", angle_factor, "must be > 0");
  const double angle = get("rotate", 0.0) / angle_factor;
  if (angle != 0.0) {
    const double c = std::cos(angle), s = std::sin(angle);
    for (Point& p : pts) p = Point(c * p[0] - s * p[1], s * p[0] + c * p[1]);
    raw.notes.push_back("rotate applied");
  }
  const double y_lo = get("bound.y.min", 1.0), y_hi = get("bound.y.max", 0.0);
  if (y_lo < y_hi) {
    std::vector<bool> drop(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) drop[i] = pts[i][0] < y_lo || pts[i][0] > y_hi;
    raw.erase_if(drop);
    raw.notes.push_back("bound.y applied");
  }
  const double z_lo = get("bound.z.min", 1.0), z_hi = get("bound.z.max", 0.0);
  if (z_lo < z_hi) {
    for (Point& p : pts) p[1] = std::clamp(p[1], z_lo, z_hi);
    raw.notes.push_back("bound.z applied (clipping)");
  }
  if (get("mirror.y", 0.0) == 1.0) {
    for (Point& p : pts) p[0] = -p[0];
    raw.notes.push_back("mirror.y applied (y -> -y)");
  }
  if (get("mirror.z", 0.0) == 1.0) {
    for (Point& p : pts) p[1] = -p[1];
    raw.notes.push_back("mirror.z applied (z -> -z)");
  }
  if (get("inversion", 0.0) == 1.0) {
    std::reverse(pts.begin(), pts.end());
    std::reverse(raw.lines.begin(), raw.lines.end());
    raw.notes.push_back("inversion applied (order reversed)");
  }
  const double length_factor = get("units.len.f", 1000.0);
  require(length_factor > 0.0, src + ": spline units.len.f", length_factor, "must be > 0");
  if (!numbers.count("spline.units.len.f"))
    raw.notes.push_back("no units.len.f: lengths taken as mm");
  for (Point& p : pts) p /= length_factor;
  raw.written_unit = length_factor == 1000.0 ? "mm"
                     : length_factor == 1.0
                         ? "m"
                         : "file units, units.len.f = " + format_number(length_factor);
  return raw;
}

std::string format_simpack(const PointList& points, Body body, std::string_view comment) {
  // Quotes and '!' would end the quoted value or start a comment.
  std::string safe_comment(comment);
  for (char& c : safe_comment)
    if (c == '\'' || c == '"' || c == '!' || c == '\n' || c == '\r') c = ' ';
  std::string out =
      "! SIMPACK rail-wheel profile written by wheelwear\n"
      "  header.begin\n"
      "    version = 1\n"
      "    type = " +
      std::string(body == Body::wheel ? "1" : "0") +
      "   ! 0 = rail profile, 1 = wheel profile\n"
      "  header.end\n"
      "  spline.begin\n"
      "    approx.smooth = 0\n"
      "    comment = '" +
      safe_comment +
      "'\n"
      "    mirror.y = 0\n"
      "    mirror.z = 0\n"
      "    inversion = 0\n"
      "    units.len.f = 1000   ! lengths in mm\n"
      "    units.ang.f = 1\n"
      "    point.begin\n";
  for (const Point& p : points) {
    require_finite("written profile y [m]", p[0]);
    require_finite("written profile z [m]", p[1]);
    out += "      " + format_number(p[0] * 1e3) + "  " + format_number(p[1] * 1e3) + "\n";
  }
  out += "    point.end\n  spline.end\n";
  return out;
}

void write_simpack(const std::filesystem::path& path, const PointList& points, Body body,
                   std::string_view comment) {
  write_file_atomically(path, format_simpack(points, body, comment));
}

}  // namespace wheelwear::profiles
