#pragma once
/// Plain two-column text and CSV profile files.
///
/// Axes (docs/profiles.md): the file's own, returned as written. wheelwear writes the profile frame
/// (y lateral, + towards the field side, 0 at a wheel's taping line or a rail's top; z vertical,
/// + down, 0 at the taping-line height or the top of rail); other files may have y or z the other
/// way (orientation.hpp turns them) and a wheel's y = 0 at its internal face (the loader's origin
/// rule, profile_loader.hpp). No header states a wheel's diameter or taping line.
///
/// Reading: one point per line, values separated by commas, blanks or tabs (or semicolons, with
/// decimal commas allowed then). Lines starting with '#', '%', '!' or "//" are comments, and so is
/// text after '"', '%', '!' or '#' on a row of numbers (recorded in RawProfile::repairs);
/// wheelwear's own comments "# body: wheel", "# side: left" are understood. An optional header line
/// names the columns: y/z (or lateral/vertical, or x/y as MiniProf does) fix the order, and a unit
/// on a name
/// ("y_mm", "y [mm]", "z (m)") fixes the unit. Further columns are ignored. Without a header the
/// unit comes from the magnitudes (a lateral extent above 1 means mm: real profiles span 0.03 to
/// 0.2 m) and the order from the spans (y first unless the second column spans 1.2 times more).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Parses a plain-text profile. Throws InputError naming source and line on malformed rows
/// (non-numeric text after the data began, fewer than two values, changing column count).
RawProfile parse_columns(std::string_view text, std::string_view source,
                         const ReadOptions& options = {});

/// What to put in a written CSV file.
struct CsvWriteOptions {
  LengthUnit unit = LengthUnit::millimetre;  ///< millimetre or metre
  std::string name{};                        ///< written as a comment if not empty
  std::optional<Body> body{};                ///< written as "# body: ..." if set
  std::optional<Side> side{};                ///< written as "# side: ..." if set
};

/// CSV text: comment lines, a header "y_mm,z_mm" (or "y_m,z_m"), then one "y,z" line per point,
/// each number written exactly (shortest round-trip form).
std::string format_csv(const PointList& points, const CsvWriteOptions& options = {});

/// Writes format_csv() to `path` atomically (text_file.hpp).
void write_csv(const std::filesystem::path& path, const PointList& points,
               const CsvWriteOptions& options = {});

}  // namespace wheelwear::profiles
