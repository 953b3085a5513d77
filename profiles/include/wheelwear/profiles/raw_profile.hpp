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
  std::optional<Body> body{};                    ///< overrides what the file or its extension says
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

  /// "source:line" of point i (or just the source when the line is unknown).
  std::string where(std::size_t i) const;
  /// Value of a header key, if present (last occurrence).
  std::optional<std::string> header_value(std::string_view key) const;
  /// Removes the points whose flag is set, keeping points and lines aligned.
  void erase_if(const std::vector<bool>& remove);
};

}  // namespace wheelwear::profiles
