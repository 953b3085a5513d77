#pragma once
/// Reading and writing profile files of any supported format, chosen by extension or content.

#include <filesystem>
#include <string_view>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Supported file formats.
enum class FileFormat {
  columns,   ///< plain two-column text or CSV (columns_format.hpp)
  simpack,   ///< SIMPACK / CONTACT .prr, .prw (simpack_format.hpp)
  miniprof,  ///< MiniProf .whl, .ban (miniprof_format.hpp)
};

/// The format of a file: by extension (.prr/.prw, .whl/.ban, any case), otherwise by content
/// ("header.begin"/"spline.begin" lines: SIMPACK; "MINIPROF", "XYPoints=" or "ColumnDef=":
/// MiniProf), otherwise plain columns. MiniProf .mpt files (is_miniprof_mpt) come out as miniprof,
/// whose reader refuses them by name.
FileFormat detect_format(const std::filesystem::path& path, std::string_view text);

/// Parses `text` in `format`; `source` names it in messages and its extension may give the body.
/// options.body sets the body of a file that does not state one, but a body the file states
/// (Simpack "type", wheelwear's "# body:", MiniProf's "#MINIWHEELPROF" or its .whl/.ban name:
/// RawProfile::body_line, body_evidence) that differs is refused: InputError naming the file,
/// what it says it is, the expected body and what to give instead.
RawProfile parse_profile_text(std::string_view text, std::string_view source, FileFormat format,
                              const ReadOptions& options = {});

/// Reads a profile file of any supported format (read_text_file, detect_format,
/// parse_profile_text). options.body, if set, is the body expected (parse_profile_text).
RawProfile read_profile_file(const std::filesystem::path& path, const ReadOptions& options = {});

/// Writes `points` [m] to `path` in the format its extension names (.prr/.prw SIMPACK,
/// .whl/.ban MiniProf, anything else CSV in mm), atomically.
void write_profile_file(const std::filesystem::path& path, const PointList& points, Body body);

}  // namespace wheelwear::profiles
