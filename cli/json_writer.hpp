#pragma once
/// A small writer for the flat JSON objects the CLI prints (`--json`).

#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::cli {

/// Builds one JSON object member by member. Numbers are written with 17 significant digits
/// (round-trip exact); non-finite numbers become null, which JSON readers accept.
class JsonObject {
 public:
  JsonObject& add(std::string_view key, double value);
  JsonObject& add(std::string_view key, int value);
  JsonObject& add(std::string_view key, bool value);
  JsonObject& add(std::string_view key, std::string_view value);
  JsonObject& add(std::string_view key, const char* value) {
    return add(key, std::string_view(value));
  }
  /// Adds a member whose value is an already-serialised JSON text (an object or array).
  JsonObject& add_raw(std::string_view key, std::string_view json);

  /// The serialised object, e.g. {"Fx": -1.5, "method": "fastsim-sdec"}.
  std::string str() const;

 private:
  std::vector<std::string> members_;
};

/// Serialises a list of already-serialised JSON values as an array.
std::string json_array(const std::vector<std::string>& elements);

/// Serialises a list of texts as a JSON array of strings, e.g. ["a", "b"].
std::string json_strings(const std::vector<std::string>& texts);

/// Escapes a string for a JSON string literal (without the quotes).
std::string json_escape(std::string_view text);

}  // namespace wheelwear::cli
