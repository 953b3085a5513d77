#pragma once
/// MiniProf text exports: wheels (.whl) and rails (.ban).
///
/// Two layouts exist. The older one (".whl" from MiniProf 2020, first line "#MINIWHEELPROF",
/// "MINIPROF" within the first three lines) has free header lines, a line starting with '"' that
/// holds the instrument's Sd, Sh, qR (mm) with "(Sd/Sh/qR)" on the next line, then the points after
/// the first empty line. The other (".ban", ".whl" of newer versions) has "key=value" header
/// lines, some quoted ("\"ColumnDef=X,Y,A\""), then the points after the first empty line. In both,
/// values are in mm and ColumnDef (the last one wins; default "X,Y") names the columns: X lateral,
/// Y vertical, A the surface angle, C the curvature. XYPoints, when given, is the point count.
///
/// Axes (docs/profiles.md), from the measured files in tests/data/measured, MiniProf for Windows
/// exports in CONTACT's test bank and CONTACT's user guide; the reader returns X and Y as written
/// and orientation.hpp turns them into the profile frame:
/// - wheel (.whl): X lateral, 0 at the internal face (flange back), + towards the field side
///   (X = 131 ... 143 mm at the field side); Y vertical, + towards the flange tip (down: the tip
///   at Y = +28 mm), 0 at about the taping-line height (|Y| <= 0.3 mm at X = 70 mm).
/// - rail (.ban): X lateral, + towards the gauge face (the track centre: the face measured down to
///   Y = -25 mm lies at X = 44 ... 46.6 mm), 0 where the instrument puts it (not a rail feature);
///   Y vertical, + up, 0 at about the top of rail (Y = -0.2 mm there).
/// Header keys (either layout, names without case): DiameterTaperline fills
/// RawProfile::wheel_diameter and WheelDiameterTaperline RawProfile::taping_line_distance (mm;
/// refused outside 200 ... 2500 mm and 30 ... 110 mm). The body comes from "#MINIWHEELPROF" or
/// wheelwear's "# body:" line, else from the extension (.whl wheel, .ban rail); either binds
/// (RawProfile::body_evidence).

#include <filesystem>
#include <string_view>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Whether a file is a MiniProf multi-profile .mpt file: by its extension (any case), or by a
/// "[FileInfo]" section in its first three lines (how CONTACT's read_miniprof tells them).
bool is_miniprof_mpt(std::string_view extension, std::string_view text);

/// Parses a MiniProf export; `extension` (".whl", ".ban", any case) gives the body when the file
/// does not say it, and either is binding (RawProfile::body_evidence). Throws InputError naming
/// source and line on malformed rows, a ColumnDef without X and Y, a point count that differs from
/// XYPoints by more than one (truncated file), a header length (DiameterTaperline,
/// WheelDiameterTaperline) that is no number in its range, or two lines that state different
/// bodies, and refuses .mpt files (is_miniprof_mpt: their layout is not publicly documented).
///
/// Accepted beyond the strict layout, each recorded in RawProfile::repairs: text after '"', '%',
/// '!' or '#' on a point row (a comment, as CONTACT reads it; lines starting with '%', '!' or '#'
/// are comments too); points that follow the header without the empty line (the first row of
/// two numbers or more starts them); a point count one off XYPoints (a warning).
RawProfile parse_miniprof(std::string_view text, std::string_view source,
                          std::string_view extension, const ReadOptions& options = {});

/// MiniProf text for `points` [m] in the profile frame. Wheels use the older layout with axes as
/// the frame's (X = y, Y = z: the origin stays at the taping line, where MiniProf's own exports
/// put X = 0 at the internal face); rails use the key=value layout with MiniProf's rail axes
/// (X = -y towards the gauge face, Y = -z up) and a "# body: rail" line. Values in mm; the
/// origin is kept.
std::string format_miniprof(const PointList& points, Body body);

/// Writes format_miniprof() to `path` atomically.
void write_miniprof(const std::filesystem::path& path, const PointList& points, Body body);

}  // namespace wheelwear::profiles
