#pragma once
// Readers of a scene's TOML keys: numbers with their range, whole numbers, strings, booleans,
// and tables whose unknown keys are refused with the allowed ones and a unit hint. Every
// message starts with the scene line and the key's full name.

#include <toml++/toml.h>

#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace wheelwear::pipeline::detail {

// "scene line N: key".
std::string where(const toml::source_region& source, std::string_view key);

// A number as messages print it.
std::string format(double v);

// One key's reader: it receives the node and the key's full name for messages.
using KeyHandler = std::function<void(const toml::node&, const std::string&)>;

// A number in [lo, hi] (integers convert); InputError naming the key, the value and `meaning`.
double number(const toml::node& node, const std::string& key, double lo, double hi,
              std::string_view meaning);
// A whole number in [lo, hi].
int integer(const toml::node& node, const std::string& key, int lo, int hi,
            std::string_view meaning);
// A quoted string.
std::string text(const toml::node& node, const std::string& key);
// true or false.
bool boolean(const toml::node& node, const std::string& key);

// Calls each key's handler; an unknown key is refused with the allowed ones (and "did you mean
// radius_m" when only its unit suffix is wrong).
void read_table(const toml::table& table, const std::string& section,
                const std::map<std::string, KeyHandler>& handlers);

}  // namespace wheelwear::pipeline::detail
