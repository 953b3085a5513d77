#pragma once
/// Profile points as a file gives them, before orientation, cleaning and fitting.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "wheelwear/profiles/types.hpp"

namespace wheelwear::profiles {

/// Length unit of a plain-text profile file.
enum class LengthUnit {
  automatic,   ///< from the header (a "mm" or "m" unit on the columns), else from the magnitudes
  millimetre,  ///< values in mm
  metre,       ///< values in m
};

/// "auto", "mm" or "m" to LengthUnit; nullopt for anything else.
std::optional<LengthUnit> parse_length_unit(std::string_view text);

/// `line` for quoting in a message: whole (a cut could hide the text that caused the error), or
/// its first 200 characters and "..." when longer.
std::string quote_line(std::string_view line);

/// The text of a "trailing_comments" repair: "3 point rows carry text after their numbers, read
/// as a comment (after <characters>)".
std::string trailing_comment_text(std::size_t rows, std::string_view characters);

/// Splits a point row at its first comment character, '"', '%', '!' or '#' (CONTACT's profile
/// readers treat each as the start of a comment). Returns the text before it (trimmed) and sets
/// `comment` when there was one.
std::string_view strip_row_comment(std::string_view line, bool& comment);

/// Which column of a plain-text file is lateral and which vertical.
enum class ColumnOrder {
  automatic,  ///< from the header names (y/z, x/y, lateral/vertical), else y first unless the
              ///< second column spans clearly more (real profiles are wider than tall)
  y_z,        ///< first column y (lateral), second z (vertical)
  z_y,        ///< first column z, second y
};

/// How to read a profile file.
struct ReadOptions {
  LengthUnit unit = LengthUnit::automatic;       ///< plain-text files only; others carry a unit
  ColumnOrder columns = ColumnOrder::automatic;  ///< plain-text files only
  /// The body expected: given to a file that does not say; a file that says another is refused
  /// (parse_profile_text).
  std::optional<Body> body{};
};

/// A departure from the strict format that a reader accepted in a real file; the loader reports it
/// with the cleaning (CleaningReport::reading).
struct ReadRepair {
  std::string name;     ///< "trailing_comments", "trailing_text", "point_count" or "no_blank_line"
  std::string message;  ///< what was accepted, naming the file and the first line concerned
  std::vector<int> lines;  ///< lines concerned, in file order (at most 20)
  std::size_t count = 0;   ///< how many lines are concerned
  bool warning = false;    ///< the data may be incomplete: worth checking the file
};

/// A point row's coordinates as the file writes them, for messages.
struct WrittenPoint {
  int line = 0;          ///< 1-based line
  std::string lateral;   ///< the lateral value's text (MiniProf X, y otherwise)
  std::string vertical;  ///< the vertical value's text (MiniProf Y, z otherwise)
};

/// Points of one profile in metres, in the file's order and axes after the format's own header
/// transformations (Simpack flags), each with the line it came from.
struct RawProfile {
  std::string source;              ///< file name or label, for messages
  std::string format;              ///< "columns", "simpack" or "miniprof"
  PointList points;                ///< (y, z) [m]
  std::vector<int> lines;          ///< 1-based line of each point in the source
  std::optional<Body> body;        ///< what the file says it is, if it says
  std::optional<Side> side;        ///< what the file says, if it says
  std::vector<std::string> notes;  ///< what the reader established (unit, columns, flags applied)
  std::vector<std::pair<std::string, std::string>> header;  ///< header keys and values as read
  /// Line of the header entry that states the body (Simpack "type", "# body:", MiniProf's
  /// "#MINIWHEELPROF"); 0 when the body comes from the extension or nowhere.
  int body_line = 0;
  /// What states the body, quoted in the refusal of another body ("type = 0", "#MINIWHEELPROF:
  /// a MiniProf wheel export", "extension .ban: a MiniProf rail export"); empty when nothing does
  /// or when the line alone says it (wheelwear's "# body:"). A body stated by a line or by such
  /// evidence is never overridden: parse_profile_text refuses another body (profile_io.hpp).
  std::string body_evidence;
  /// Wheels: the wheel's diameter at the taping line [m], where a header states it (MiniProf
  /// "DiameterTaperline", docs/profiles.md); the rolling radius is half of it.
  std::optional<double> wheel_diameter;
  /// Wheels: the taping line's distance from the internal face (flange back) [m], where a header
  /// states it (MiniProf "WheelDiameterTaperline", where DiameterTaperline is measured).
  std::optional<double> taping_line_distance;
  std::vector<ReadRepair> repairs;    ///< what the reader accepted beyond the strict format
  std::vector<WrittenPoint> written;  ///< every point row as written, in file order
  std::string lateral_name = "y";     ///< the file's name of the lateral coordinate
  std::string vertical_name = "z";    ///< the file's name of the vertical coordinate
  std::string written_unit;           ///< unit of the written values ("mm", "m"), if known

  /// "source:line" of point i (or just the source when the line is unknown).
  std::string where(std::size_t i) const;
  /// Point i's coordinates as the file writes them, "X = 46.3400, Y = -23.9200"; for points
  /// without a written row, "y = -2 mm" in metres converted to mm in the current frame.
  std::string as_written(std::size_t i) const;
  /// " (values as written in the file, mm)" when as_written() quotes the file, else "".
  std::string written_note() const;
  /// Value of a header key, if present (last occurrence).
  std::optional<std::string> header_value(std::string_view key) const;
  /// Records a repair of `lines` (file order; the message starts "<source>:<first line>: ").
  void add_repair(std::string name, std::vector<int> lines, std::string_view text,
                  bool warning = false);
  /// Removes the points whose flag is set, keeping points and lines aligned.
  void erase_if(const std::vector<bool>& remove);
};

}  // namespace wheelwear::profiles
