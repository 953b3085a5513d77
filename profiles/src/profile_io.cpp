#include "wheelwear/profiles/profile_io.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/miniprof_format.hpp"
#include "wheelwear/profiles/simpack_format.hpp"

namespace wheelwear::profiles {

using core::read_text_file;
using core::to_lower;

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  return to_lower(path.extension().string());
}

// The refusal of a file whose stated body is not the one asked for: where and how the file says
// it, and what to give instead (a MiniProf export's body is in its name, .whl or .ban).
std::string body_refusal(const RawProfile& raw, Body expected_body) {
  const std::string stated(to_string(*raw.body)), expected(to_string(expected_body));
  std::string message = raw.source;
  if (raw.body_line > 0) {
    message += ':';  // appended piece by piece: GCC 12 warns falsely on ":" + std::string
    message += std::to_string(raw.body_line);
  }
  message += ": the file says it is a " + stated + " profile";
  if (!raw.body_evidence.empty()) message += " (" + raw.body_evidence + ")";
  message +=
      ", but a " + expected + " profile is expected here; give a " + expected + " profile file";
  if (raw.format == "miniprof") {
    const std::string extension = expected_body == Body::wheel ? ".whl" : ".ban";
    message += " (MiniProf exports " + expected + "s as " + extension + " files)";
    if (raw.body_line == 0)  // only the name says it: the file may be misnamed
      message += ", or rename this file to " + extension + " if it does hold a " + expected;
  }
  return message;
}

}  // namespace

FileFormat detect_format(const std::filesystem::path& path, std::string_view text) {
  const std::string ext = lower_extension(path);
  if (ext == ".prr" || ext == ".prw") return FileFormat::simpack;
  if (ext == ".whl" || ext == ".ban") return FileFormat::miniprof;
  if (is_miniprof_mpt(ext, text)) return FileFormat::miniprof;  // to be refused by name
  const std::string_view head = text.substr(0, std::min<std::size_t>(text.size(), 8192));
  if (head.find("header.begin") != std::string_view::npos ||
      head.find("spline.begin") != std::string_view::npos)
    return FileFormat::simpack;
  if (head.find("MINIPROF") != std::string_view::npos ||
      head.find("XYPoints=") != std::string_view::npos ||
      head.find("ColumnDef=") != std::string_view::npos)
    return FileFormat::miniprof;
  return FileFormat::columns;
}

RawProfile parse_profile_text(std::string_view text, std::string_view source, FileFormat format,
                              const ReadOptions& options) {
  RawProfile raw;
  switch (format) {
    case FileFormat::simpack:
      raw = parse_simpack(text, source, options);
      break;
    case FileFormat::miniprof:
      raw = parse_miniprof(text, source, lower_extension(std::filesystem::path(source)), options);
      break;
    case FileFormat::columns:
      raw = parse_columns(text, source, options);
      break;
  }
  if (options.body && raw.body && *raw.body != *options.body &&
      (raw.body_line > 0 || !raw.body_evidence.empty()))
    throw InputError(body_refusal(raw, *options.body));
  if (options.body) raw.body = options.body;
  return raw;
}

RawProfile read_profile_file(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string text = read_text_file(path);
  return parse_profile_text(text, path.string(), detect_format(path, text), options);
}

void write_profile_file(const std::filesystem::path& path, const PointList& points, Body body) {
  const std::string ext = lower_extension(path);
  if (ext == ".prr" || ext == ".prw") {
    write_simpack(path, points, body);
  } else if (ext == ".whl" || ext == ".ban") {
    write_miniprof(path, points, body);
  } else {
    CsvWriteOptions options;
    options.body = body;
    write_csv(path, points, options);
  }
}

}  // namespace wheelwear::profiles
