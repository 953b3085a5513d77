#pragma once
/// Readers of the keys of a TOML input (a scene, a vehicle, a route): numbers with their range,
/// whole numbers, strings, booleans, and tables whose unknown keys are refused with the allowed
/// ones and a unit hint. Every message starts with "<document> line N: <key>".

#include <toml++/toml.h>

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace wheelwear::core {

/// One key's reader: it receives the node and the key's full name for messages.
using TomlKeyHandler = std::function<void(const toml::node&, const std::string&)>;

/// The key readers of one kind of document; `document` names it in messages ("scene",
/// "vehicle file").
class TomlKeys {
 public:
  explicit TomlKeys(std::string document) : document_(std::move(document)) {}

  /// "<document> line N: key".
  std::string where(const toml::source_region& source, std::string_view key) const;
  /// A number in [lo, hi] (integers convert); InputError naming the key, the value and
  /// `meaning`.
  double number(const toml::node& node, const std::string& key, double lo, double hi,
                std::string_view meaning) const;
  /// A whole number in [lo, hi].
  int integer(const toml::node& node, const std::string& key, int lo, int hi,
              std::string_view meaning) const;
  /// A quoted string.
  std::string text(const toml::node& node, const std::string& key) const;
  /// true or false.
  bool boolean(const toml::node& node, const std::string& key) const;
  /// Calls each key's handler; an unknown key is refused with the allowed ones (and "did you
  /// mean radius_m" when only its unit suffix is wrong).
  void read_table(const toml::table& table, const std::string& section,
                  const std::map<std::string, TomlKeyHandler>& handlers) const;
  /// A number as the messages print it (6 significant digits).
  static std::string format(double v);

 private:
  std::string document_;
};

}  // namespace wheelwear::core
