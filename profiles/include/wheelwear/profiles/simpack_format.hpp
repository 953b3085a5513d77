#pragma once
/// SIMPACK / CONTACT rail and wheel profile files (.prr, .prw).
///
/// Axes (docs/profiles.md), after the file's processing keys: y lateral, + towards the field side
/// (mirror.y brings a file there; orientation.hpp turns one that is not), z vertical, + down
/// (CONTACT takes SIMPACK z as down without testing it); the origin is the wheel's taping line (0
/// at its height) or the top of rail, or for files made from MiniProf wheels the internal face
/// (the loader's origin rule). No header key states a wheel's diameter or taping line.
///
/// Layout: '!' starts a comment; "header.begin ... header.end" holds `type` (0 rail, 1 wheel);
/// "spline.begin ... spline.end" holds processing keys and the "point.begin ... point.end" block
/// of "y z [weight]" rows. The reader applies the processing keys in SIMPACK's order (the order
/// CONTACT's read_simpack follows): point.dist.min (drop points closer than that in y), shift.y /
/// shift.z, rotate (about the origin, units.ang.f = user/rad), bound.y (drop outside) and bound.z
/// (clip) when min < max, mirror.y (y -> -y), mirror.z (z -> -z), inversion (reverse the order),
/// units.len.f (user/m; 1000 means mm, the default when absent). The points it returns are in that
/// resulting frame, which for CONTACT's files is CONTACT's profile frame: z down, wheel flange
/// and rail gauge face at -y (MBench_S1002_v3.prw: flange back near y = -70 mm after its
/// mirror.y = 1; MBench_UIC60_v3.prr: origin on the top of the canted rail).

#include <filesystem>
#include <string_view>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Parses a SIMPACK profile. Throws InputError naming source and line on malformed content, a
/// missing point block or a point block that does not end (truncated file). Text after '"', '%'
/// or '#' on a point row is a comment too (recorded in RawProfile::repairs). The body comes from
/// `type`, which RawProfile::body_line points to: read_profile_file refuses a file whose type is
/// not the body asked for.
RawProfile parse_simpack(std::string_view text, std::string_view source,
                         const ReadOptions& options = {});

/// SIMPACK text for `points` [m]: type from `body`, lengths in mm, no processing flags set.
std::string format_simpack(const PointList& points, Body body, std::string_view comment = "");

/// Writes format_simpack() to `path` atomically.
void write_simpack(const std::filesystem::path& path, const PointList& points, Body body,
                   std::string_view comment = "");

}  // namespace wheelwear::profiles
