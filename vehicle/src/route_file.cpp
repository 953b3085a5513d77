// Route files: the TOML reader of a route and the built-in default route.

#include <toml++/toml.h>

#include <cmath>
#include <optional>
#include <sstream>

#include "route_checks.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/core/toml_keys.hpp"
#include "wheelwear/vehicle/route.hpp"

namespace wheelwear::vehicle {

namespace {

using detail::check_route;
using detail::in_quotes;
using detail::kMaxSpeed_m_s;
using detail::number_text;
using detail::section_label;

// A finite number of any value; the range is checked by check_route with the section's context.
double finite_number(const core::TomlKeys& keys, const toml::node& node, const std::string& key,
                     std::string_view meaning) {
  const auto value = node.value<double>();  // integers convert too
  if (!value || node.is_boolean())
    throw InputError(keys.where(node.source(), key) + ": expected a number (" +
                     std::string(meaning) + ")");
  if (!std::isfinite(*value))
    throw InputError(keys.where(node.source(), key) + " = " + number_text(*value) +
                     ": expected a finite number (" + std::string(meaning) + ")");
  return *value;
}

// A number in (lo, hi] for the [route] defaults.
double number_above(const core::TomlKeys& keys, const toml::node& node, const std::string& key,
                    double lo, double hi, std::string_view meaning) {
  const double value = finite_number(keys, node, key, meaning);
  if (!(value > lo && value <= hi))
    throw InputError(keys.where(node.source(), key) + " = " + number_text(value) + ": " +
                     std::string(meaning) + " must lie in (" + number_text(lo) + ", " +
                     number_text(hi) + "]");
  return value;
}

// The keys one [[section]] gave, before the [route] defaults fill the rest.
struct SectionKeys {
  std::optional<SectionKind> kind;
  std::optional<double> length_m, radius_m, cant_m, speed_m_s, friction, friction_flange,
      traction_N;
  std::optional<std::string> name;
};

// The key is unknown; the struct's name for the rail top's coefficient is a likely slip.
void refuse_aliases(const core::TomlKeys& keys, const toml::table& table,
                    const std::string& section) {
  for (auto&& [key, node] : table) {
    if (key.str() == "friction_top")
      throw InputError(keys.where(key.source(), section + ".friction_top") +
                       ": unknown key; the rail top's coefficient of friction is 'friction' (the "
                       "gauge face's 'friction_flange')");
  }
}

}  // namespace

Route parse_route(std::string_view text, std::string_view origin_name) {
  const std::string origin(origin_name);
  toml::table root;
  try {
    root = toml::parse(text, origin_name);
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << origin << " line " << error.source().begin.line << ": " << error.description();
    throw InputError(out.str());
  }
  const core::TomlKeys keys(origin);

  const toml::table* route_table = nullptr;
  const toml::array* section_array = nullptr;
  const toml::node* section_node = nullptr;
  keys.read_table(
      root, "",
      {{"route",
        [&](const toml::node& node, const std::string& key) {
          route_table = node.as_table();
          if (!route_table)
            throw InputError(keys.where(node.source(), key) +
                             ": expected a table [route] (name and the sections' defaults)");
        }},
       {"section", [&](const toml::node& node, const std::string& key) {
          section_array = node.as_array();
          section_node = &node;
          if (!section_array || !section_array->is_array_of_tables())
            throw InputError(keys.where(node.source(), key) +
                             ": expected [[section]] tables, one per section in running order "
                             "(note the double brackets)");
        }}});

  Route route;
  std::optional<double> default_speed, default_friction, default_flange;
  if (route_table) {
    keys.read_table(
        *route_table, "route",
        {{"name", [&](const toml::node& n, const std::string& k) { route.name = keys.text(n, k); }},
         {"speed_m_s",
          [&](const toml::node& n, const std::string& k) {
            default_speed =
                number_above(keys, n, k, 0.0, kMaxSpeed_m_s, "the running speed in m/s");
          }},
         {"friction",
          [&](const toml::node& n, const std::string& k) {
            default_friction =
                number_above(keys, n, k, 0.0, 1.0, "the rail top's coefficient of friction");
          }},
         {"friction_flange", [&](const toml::node& n, const std::string& k) {
            default_flange =
                number_above(keys, n, k, 0.0, 1.0, "the gauge face's coefficient of friction");
          }}});
  }
  if (!section_array || section_array->empty()) {
    throw InputError(origin +
                     (section_node ? " line " + std::to_string(section_node->source().begin.line)
                                   : std::string()) +
                     ": no [[section]] tables; give one per section in running order, each with "
                     "kind and length_m");
  }

  std::vector<int> lines;
  for (const toml::node& element : *section_array) {
    const toml::table& table = *element.as_table();
    const std::size_t number = route.sections.size() + 1;
    const int line = static_cast<int>(table.source().begin.line);
    const std::string name = "section[" + std::to_string(number) + "]";
    refuse_aliases(keys, table, name);
    SectionKeys given;
    const auto num = [&](std::optional<double>& target, std::string meaning) {
      return [&target, &keys, meaning](const toml::node& n, const std::string& k) {
        target = finite_number(keys, n, k, meaning);
      };
    };
    keys.read_table(
        table, name,
        {{"kind",
          [&](const toml::node& n, const std::string& k) {
            const std::string kind = keys.text(n, k);
            for (SectionKind candidate :
                 {SectionKind::tangent, SectionKind::transition, SectionKind::curve})
              if (kind == section_kind_name(candidate)) given.kind = candidate;
            if (!given.kind)
              throw InputError(keys.where(n.source(), k) + " = " + in_quotes(kind) +
                               ": unknown kind; use \"tangent\", \"transition\" or \"curve\"");
          }},
         {"length_m", num(given.length_m, "the section's length in m")},
         {"radius_m", num(given.radius_m, "the radius in m, > 0 right-hand, < 0 left-hand")},
         {"cant_m", num(given.cant_m, "the outer rail's height above the inner in m")},
         {"speed_m_s", num(given.speed_m_s, "the running speed in m/s")},
         {"friction", num(given.friction, "the rail top's coefficient of friction")},
         {"friction_flange",
          num(given.friction_flange, "the gauge face's coefficient of friction")},
         {"traction_N", num(given.traction_N, "the longitudinal force per powered axle in N")},
         {"name",
          [&](const toml::node& n, const std::string& k) { given.name = keys.text(n, k); }}});

    const std::string place = origin + " line " + std::to_string(line) + ": section " +
                              std::to_string(number) +
                              (given.name ? " (" + in_quotes(*given.name) + ")" : std::string());
    if (!given.kind)
      throw InputError(place +
                       ": kind is missing; give kind = \"tangent\", \"transition\" or \"curve\"");
    if (!given.length_m) throw InputError(place + ": length_m is missing; give its length in m");
    RouteSection s;
    s.kind = *given.kind;
    s.length_m = *given.length_m;
    if (s.kind == SectionKind::curve && !given.radius_m)
      throw InputError(place +
                       ": radius_m is missing; a curve gives its radius in m (> 0 right-hand, < "
                       "0 left-hand)");
    if (s.kind == SectionKind::transition && !given.radius_m)
      throw InputError(place +
                       ": radius_m is missing; a transition gives the radius at its end in m (0 "
                       "when it ends on tangent track)");
    s.radius_m = given.radius_m.value_or(0.0);
    s.cant_m = given.cant_m.value_or(0.0);
    if (!given.speed_m_s && !default_speed)
      throw InputError(place + ": speed_m_s is missing; give it in the section or once in [route]");
    s.speed_m_s = given.speed_m_s ? *given.speed_m_s : *default_speed;
    s.friction_top = given.friction ? *given.friction : default_friction.value_or(0.3);
    s.friction_flange =
        given.friction_flange ? *given.friction_flange : default_flange.value_or(s.friction_top);
    s.traction_N = given.traction_N.value_or(0.0);
    s.name = given.name.value_or("");
    route.sections.push_back(std::move(s));
    lines.push_back(line);
  }
  check_route(route, [&](std::size_t i) {
    return origin + " line " + std::to_string(lines[i]) + ": " +
           section_label(route.sections[i], i);
  });
  return route;
}

Route read_route(const std::filesystem::path& path) {
  return parse_route(core::read_text_file(path), path.string());
}

Route default_route() {
  return parse_route(default_route_text(), "built-in default route");
}

}  // namespace wheelwear::vehicle
