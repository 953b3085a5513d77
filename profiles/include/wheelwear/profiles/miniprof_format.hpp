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
/// Axes, established from the two files in tests/data/measured: in the wheel file X runs from the
/// flange back (X = 0, the back face is the first 70 points at X = -0.1 ... 0.1 mm) to the field
/// side (X = 131 mm) and Y points down: the flange tip is at Y = +27.8 mm, the tread near X = 70
/// mm at Y = 0, the back face top and the chamfer at Y = -22 mm. In the rail file X points towards
/// the gauge face (the steep face measured down to Y = -25 mm is at X = 44 ... 46 mm, the field
/// side stops at Y = -1.5 mm) and Y points up (top of rail at Y = -0.2 mm). The reader returns X
/// and Y as they are; orientation.hpp turns such points into the profile frame.

#include <filesystem>
#include <string_view>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Whether a file is a MiniProf multi-profile .mpt file: by its extension (any case), or by a
/// "[FileInfo]" section in its first three lines (how CONTACT's read_miniprof tells them).
bool is_miniprof_mpt(std::string_view extension, std::string_view text);

/// Parses a MiniProf export; `extension` (".whl", ".ban", any case) gives the body when the file
/// does not. Throws InputError naming source and line on malformed rows, a ColumnDef without X
/// and Y, or a point count that differs from XYPoints by more than one (truncated file), and
/// refuses .mpt files (is_miniprof_mpt: their layout is not publicly documented).
///
/// Accepted beyond the strict layout, each recorded in RawProfile::repairs: text after '"', '%',
/// '!' or '#' on a point row (a comment, as CONTACT reads it; lines starting with '%', '!' or '#'
/// are comments too); points that follow the header without the empty line (the first row of
/// two numbers or more starts them); a point count one off XYPoints (a warning).
RawProfile parse_miniprof(std::string_view text, std::string_view source,
                          std::string_view extension, const ReadOptions& options = {});

/// MiniProf text for `points` [m] in the profile frame. Wheels use the older layout with axes as
/// the frame's (X = y, Y = z); rails use the key=value layout with MiniProf's rail axes
/// (X = -y towards the gauge face, Y = -z up). Values in mm; the origin is kept.
std::string format_miniprof(const PointList& points, Body body);

/// Writes format_miniprof() to `path` atomically.
void write_miniprof(const std::filesystem::path& path, const PointList& points, Body body);

}  // namespace wheelwear::profiles
