#pragma once
/// Text and number functions shared by every module: file reading and atomic writing, lines,
/// trimming, case folding and locale-independent number parsing and formatting.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::core {

/// The whole file's bytes. Throws InputError naming the file if it is missing, not a regular
/// file or unreadable.
std::string read_file_bytes(const std::filesystem::path& path);

/// The whole file as text. Throws InputError naming the file if it is missing, unreadable, empty
/// or binary (check_text).
std::string read_text_file(const std::filesystem::path& path);

/// Throws InputError("<source>: binary data at byte N ...") if `text` holds a NUL byte or more
/// than 5% control characters (other than tab, CR, LF, FF) in its first 4096 bytes.
void check_text(std::string_view text, std::string_view source);

/// The lines of `text` without their line ends (LF or CRLF).
std::vector<std::string_view> split_lines(std::string_view text);

/// `text` without leading and trailing blanks.
std::string_view trim(std::string_view text);

/// `text` in lower case (ASCII), for case-blind keywords, headers and file extensions.
std::string to_lower(std::string_view text);

/// A decimal number (optional sign, digits, fraction, exponent; also nan and inf), the whole
/// token and nothing else, locale-independent; nullopt otherwise.
std::optional<double> parse_number(std::string_view token);

/// Shortest text that reads back to exactly `value` (std::to_chars).
std::string format_number(double value);

/// A rail's inclination as every command and scene takes it: "1:N" (N >= 5; 1:40 is atan(1/40))
/// or a slope tan(theta) as a number (|slope| <= 0.2; 0.025 is 1:40), "none" or 0 for none.
/// Returns the angle [rad]; throws InputError naming `field` otherwise.
double parse_inclination(std::string_view text, std::string_view field);

/// A length in metres as millimetres with `decimals` places and the unit: "12.3 mm".
std::string format_mm(double metres, int decimals);

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so an
/// existing file is either replaced whole or left untouched. Throws InputError when the path
/// is a folder or its folder does not exist, IoError when the system refuses the file.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace wheelwear::core
