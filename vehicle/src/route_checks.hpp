#pragma once
// What the route's checks and its file reader share: the checks of a whole route and the words
// their messages use.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/vehicle/route.hpp"

namespace wheelwear::vehicle::detail {

inline constexpr double kMaxSpeed_m_s = 100.0;  // 360 km/h, the top of EN 13803's speed range

// A number as the messages print it.
std::string number_text(double v);
// "text" with its quotes.
std::string in_quotes(std::string_view text);
// "section 3 (\"R1000\")".
std::string section_label(const RouteSection& section, std::size_t i);
// Checks every section and every join (InputError naming the section by `label`); returns the
// warnings (a cant deficiency beyond kCantDeficiencyWarning_m).
std::vector<std::string> check_route(const Route& route,
                                     const std::function<std::string(std::size_t)>& label);

}  // namespace wheelwear::vehicle::detail
