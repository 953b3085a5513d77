#pragma once
// A value that must be one of a list of names, refused in the words of the command line's parser
// (CLI11's IsMember check), so that the Python module's message for a keyword equals the command
// line's for the option of the same name.

#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::cli {

/// Throws InputError "OPTION: VALUE not in {a,b,c}" unless `value` is one of `names`.
inline void require_choice(std::string_view option, const std::string& value,
                           const std::vector<std::string>& names) {
  for (const std::string& name : names)
    if (name == value) return;
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ",") + name;
  throw InputError(std::string(option) + ": " + value + " not in {" + list + "}");
}

}  // namespace wheelwear::cli
