#include "wheelwear/profiles/miniprof_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
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

// The values of a row of numbers; nullopt if a token is not a number.
std::optional<std::vector<double>> numbers_of(const std::vector<std::string>& tokens) {
  std::vector<double> values;
  for (const std::string& token : tokens) {
    const auto value = parse_number(token);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

// Line (1-based) of a "[FileInfo]" section among the first three lines, 0 if none.
int mpt_marker_line(const std::vector<std::string_view>& lines) {
  for (std::size_t i = 0; i < std::min<std::size_t>(3, lines.size()); ++i)
    if (lines[i].find("[FileInfo]") != std::string_view::npos) return static_cast<int>(i + 1);
  return 0;
}

constexpr const char* kMptRefusal =
    "MiniProf .mpt files are not supported; export .whl/.ban from MiniProf";

// A header key that states a length of the wheel, in mm.
struct HeaderLength {
  std::string_view key;
  std::optional<double> RawProfile::*field;
  std::string_view what;  // the quantity, for notes and messages
  double lo, hi;          // plausible range [m]
  std::string_view why;   // why values outside the range are refused
};

// The keys and their meaning come from public files (docs/profiles.md): CONTACT's MiniProf reader
// knows both names, and a MiniProf for Windows 2.43 wheel export in CONTACT's test bank writes
// DiameterTaperline=719.1924 next to DiameterFlange=774.9396 (= 719.1924 + 2 Sh, Sh=27.8749: a
// diameter at the taping line) and WheelDiameterTaperline=70.0000 (where that diameter is taken,
// from the internal face, as its X axis runs).
constexpr std::array<HeaderLength, 2> kHeaderLengths = {{
    {"DiameterTaperline", &RawProfile::wheel_diameter, "wheel diameter at the taping line", 0.2,
     2.5, "railway wheels measure about 0.3 ... 1.3 m; a value outside is a wrong unit or key"},
    {"WheelDiameterTaperline", &RawProfile::taping_line_distance,
     "taping line distance from the internal face", 0.03, 0.11,
     "EN 13715 puts the taping line 70 mm from the internal face; the range is that of "
     "LoadOptions::taping_line_distance"},
}};

// Fills the RawProfile field that header key `key` states (kHeaderLengths; names compared
// without case, as CONTACT's reader does). An empty value states nothing: MiniProf writes keys it
// has no value for empty. Throws InputError naming the file, line and key for anything that is
// not a length in range.
void read_header_length(RawProfile& raw, std::string_view key, std::string_view value, int line) {
  for (const HeaderLength& h : kHeaderLengths) {
    if (to_lower(key) != to_lower(h.key)) continue;
    if (value.empty()) return;
    const std::string where = raw.source + ":" + std::to_string(line) + ": " + std::string(key) +
                              "=" + std::string(value);
    const std::optional<double> mm = parse_number(value);
    if (!mm || !std::isfinite(*mm))
      throw InputError(where + ": the " + std::string(h.what) + " must be a number in mm");
    const double metres = *mm * 1e-3;
    if (metres < h.lo || metres > h.hi)
      throw InputError(where + " mm: the " + std::string(h.what) + " must lie in " +
                       format_number(h.lo * 1e3) + " ... " + format_number(h.hi * 1e3) + " mm (" +
                       std::string(h.why) + ")");
    raw.*(h.field) = metres;
    raw.notes.push_back("line " + std::to_string(line) + ": " + std::string(key) + "=" +
                        std::string(value) + ": " + std::string(h.what) + " " +
                        format_number(metres) + " m");
  }
}

// Records a body the file states on `line` ("#MINIWHEELPROF", wheelwear's "# body:"); refuses a
// second statement that contradicts the first.
void state_body(RawProfile& raw, Body body, int line, std::string evidence) {
  if (raw.body_line > 0 && raw.body != body)
    throw InputError(raw.source + ":" + std::to_string(line) + ": the file says it is a " +
                     std::string(to_string(body)) + " profile, but line " +
                     std::to_string(raw.body_line) + " says " + std::string(to_string(*raw.body)));
  raw.body = body;
  raw.body_line = line;
  raw.body_evidence = std::move(evidence);
}

}  // namespace

bool is_miniprof_mpt(std::string_view extension, std::string_view text) {
  return to_lower(extension) == ".mpt" ||
         mpt_marker_line(split_lines(text.substr(0, std::min<std::size_t>(text.size(), 4096)))) > 0;
}

RawProfile parse_miniprof(std::string_view text, std::string_view source,
                          std::string_view extension, const ReadOptions& options) {
  (void)options;
  const std::string src(source);
  const std::string ext = to_lower(extension);
  if (ext == ".mpt") throw InputError(src + ": " + kMptRefusal);
  check_text(text, source);
  const auto lines = split_lines(text);
  if (const int marker = mpt_marker_line(lines))
    throw InputError(src + ":" + std::to_string(marker) + ": \"" +
                     quote_line(lines[static_cast<std::size_t>(marker - 1)]) +
                     "\" begins a MiniProf multi-profile (.mpt) file; " + kMptRefusal);
  RawProfile raw;
  raw.source = src;
  raw.format = "miniprof";
  raw.lateral_name = "X";
  raw.vertical_name = "Y";
  raw.written_unit = "mm";
  bool old_layout = false;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, lines.size()); ++i)
    if (lines[i].find("MINIPROF") != std::string_view::npos) old_layout = true;
  // MiniProf names its exports by body; the content, when it says, comes first.
  if (ext == ".whl" || ext == ".ban") {
    raw.body = ext == ".whl" ? Body::wheel : Body::rail;
    raw.body_evidence = ext == ".whl" ? "extension .whl: a MiniProf wheel export"
                                      : "extension .ban: a MiniProf rail export";
  }
  if (!lines.empty() && lines.front().rfind("#MINIWHEELPROF", 0) == 0)
    state_body(raw, Body::wheel, 1, "#MINIWHEELPROF: a MiniProf wheel export");

  bool in_data = false;
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<std::string>> row_tokens;
  std::vector<int> row_lines, comment_lines, text_lines;
  std::string column_def = "X,Y";
  std::optional<double> declared_points;
  int declared_line = 0;
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
        read_header_length(raw, key, value, number);
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
    if (line.front() == '%' || line.front() == '!' || line.front() == '#') {  // comment
      // wheelwear's own "# body: rail" (format_miniprof) says what the name may not.
      const std::string comment = to_lower(trim(line.substr(1)));
      if (line.front() == '#' && (comment == "body: wheel" || comment == "body: rail"))
        state_body(raw, comment == "body: wheel" ? Body::wheel : Body::rail, number, "");
      continue;
    }
    // A row of numbers, possibly followed by a comment, is a point row; in the header only with
    // two values or more (the points may follow the header without the empty line).
    bool commented = false;
    const std::string_view content = strip_row_comment(line, commented);
    std::vector<std::string> tokens = split_values(content);
    std::optional<std::vector<double>> values = numbers_of(tokens);
    if (values && !values->empty() && (in_data || values->size() >= 2)) {
      if (!in_data && rows.empty())
        raw.add_repair("no_blank_line", {number},
                       "the points follow the header without an empty line; this line is taken "
                       "as the first point");
      in_data = true;
      if (commented) comment_lines.push_back(number);
      if (!rows.empty() && values->size() != rows.front().size())
        throw InputError(where() + ": " + std::to_string(values->size()) + " values, but line " +
                         std::to_string(row_lines.front()) + " has " +
                         std::to_string(rows.front().size()) + " (truncated line?)");
      rows.push_back(std::move(*values));
      row_tokens.push_back(std::move(tokens));
      row_lines.push_back(number);
      continue;
    }
    const auto eq = line.find('=');
    if (eq != std::string_view::npos) {
      const std::string key(trim(line.substr(0, eq)));
      const std::string value(trim(line.substr(eq + 1)));
      raw.header.emplace_back(key, value);
      if (key == "ColumnDef") column_def = value;
      read_header_length(raw, key, value, number);
      if (key == "XYPoints" && !value.empty()) {
        declared_points = parse_number(value);
        declared_line = number;
        if (!declared_points || *declared_points < 0.0 ||
            *declared_points != std::floor(*declared_points))
          throw InputError(where() + ": XYPoints=" + value +
                           " is not a point count (a whole number of points)");
      }
      continue;
    }
    if (in_data && !rows.empty() && tokens.size() > rows.front().size()) {
      // A full row of numbers followed by words without a comment character ("add point to
      // extend gauge face" in a file of CONTACT's test bank): CONTACT reads the numbers and
      // ignores the rest, and so does this reader, with a warning naming the lines.
      const std::size_t width = rows.front().size();
      std::vector<std::string> head(tokens.begin(), tokens.begin() + static_cast<long>(width));
      const auto first = static_cast<unsigned char>(tokens[width].front());
      if (auto numbers = numbers_of(head); numbers && std::isalpha(first)) {
        text_lines.push_back(number);
        rows.push_back(std::move(*numbers));
        row_tokens.push_back(std::move(head));
        row_lines.push_back(number);
        continue;
      }
    }
    if (!in_data) {
      if (old_layout) continue;  // free header text of the older layout
      throw InputError(where() + ": \"" + quote_line(line) +
                       "\" is neither a key=value header line nor a point row");
    }
    throw InputError(where() + ": \"" + quote_line(line) +
                     "\" is not a row of numbers (text after \", %, ! or # is a comment)");
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
  if (declared_points && static_cast<double>(rows.size()) != *declared_points) {
    const std::string counts = "the header declares XYPoints=" + format_number(*declared_points) +
                               " but " + std::to_string(rows.size()) + " points were read";
    // One row more or less is accepted with a warning: the points read are complete rows, and a
    // count one off does not make a profile unusable. More than that means a damaged file.
    if (std::abs(static_cast<double>(rows.size()) - *declared_points) > 1.0)
      throw InputError(src + ": " + counts + " (truncated or damaged file?)");
    raw.add_repair("point_count", {declared_line},
                   counts + "; accepted (off by one), check that no point is missing", true);
  }
  if (!comment_lines.empty())
    raw.add_repair("trailing_comments", comment_lines,
                   trailing_comment_text(comment_lines.size(), "\", %, ! or #"));
  if (!text_lines.empty())
    raw.add_repair("trailing_text", text_lines,
                   std::to_string(text_lines.size()) +
                       " point rows carry words after their numbers without a comment character; "
                       "the words are ignored (as CONTACT does): check that these points belong "
                       "to the measurement",
                   true);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    raw.points.emplace_back(rows[r][xi] * 1e-3, rows[r][yi] * 1e-3);
    raw.written.push_back({row_lines[r], row_tokens[r][xi], row_tokens[r][yi]});
  }
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
    // "# body: rail" keeps a rail a rail under any name (a .whl name says wheel).
    out = "Filename=wheelwear\nProgramName=wheelwear\nXYPoints=" + std::to_string(points.size()) +
          "\nColumnDef=X,Y\n# body: rail\n\n";
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
