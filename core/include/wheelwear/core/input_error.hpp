#pragma once
/// Errors for bad input, shared by every wheelwear module.

#include <stdexcept>
#include <string>
#include <string_view>

namespace wheelwear {

/// Thrown when an input violates a documented constraint. The message names the field, the
/// offending value and the constraint, so a user can fix the input without reading the code.
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

/// Thrown when the system fails an operation on a valid input: a file that cannot be written
/// (permissions, a full disk, a read-only file system), an output another process holds. The
/// message names the path and the cause. (The command line exits with status 4.)
class IoError : public std::runtime_error {
 public:
  explicit IoError(const std::string& message) : std::runtime_error(message) {}
};

/// Throws InputError("<field> = <value>: <constraint>") unless `condition` holds.
void require(bool condition, std::string_view field, double value, std::string_view constraint);

/// Throws InputError unless `value` is finite (not NaN, not infinite).
void require_finite(std::string_view field, double value);

}  // namespace wheelwear
