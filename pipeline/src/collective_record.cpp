#include "collective_record.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>

#include "load_collective.hpp"
#include "wheelwear/core/csv.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One column of the collective: its value in a state (NaN for an optional value not given).
struct CollectiveColumn {
  const char* name;  // the load collective's column name (load_collective.cpp)
  const char* units;
  const char* description;
  std::function<double(const WheelsetStateSpec&)> get;
};

const std::vector<CollectiveColumn>& collective_columns() {
  using S = WheelsetStateSpec;
  static const std::vector<CollectiveColumn> columns = {
      {"dy_m", "m", "wheelset lateral shift, + to the left", [](const S& s) { return s.dy; }},
      {"yaw_rad", "rad", "yaw angle", [](const S& s) { return s.yaw; }},
      {"load_left_N", "N", "vertical force on the left wheel",
       [](const S& s) { return s.load_left; }},
      {"load_right_N", "N", "vertical force on the right wheel",
       [](const S& s) { return s.load_right; }},
      {"lateral_force_left_N", "N", "prescribed lateral force of the left wheel (NaN: not given)",
       [](const S& s) { return s.lateral_force_left.value_or(kNaN); }},
      {"lateral_force_right_N", "N", "prescribed lateral force of the right wheel (NaN: not given)",
       [](const S& s) { return s.lateral_force_right.value_or(kNaN); }},
      {"speed_m_s", "m/s", "forward speed", [](const S& s) { return s.speed; }},
      {"curve_radius_m", "m", "0 tangent, + right-hand curve",
       [](const S& s) { return s.curve_radius; }},
      {"lateral_velocity_m_s", "m/s", "dy/dt, + to the left",
       [](const S& s) { return s.lateral_velocity; }},
      {"angular_velocity_rad_s", "rad/s",
       "axle angular velocity (NaN: rolling on the nominal radius)",
       [](const S& s) { return s.angular_velocity.value_or(kNaN); }},
      {"yaw_rate_rad_s", "rad/s", "d(yaw)/dt relative to the track",
       [](const S& s) { return s.yaw_rate; }},
      {"roll_rad", "rad", "wheelset roll as given (NaN: not given)",
       [](const S& s) { return s.roll.value_or(kNaN); }},
      {"friction", "1", "friction on the rail top (NaN: the scene's)",
       [](const S& s) { return s.friction.value_or(kNaN); }},
      {"friction_flange", "1", "friction on the gauge face (NaN: the state's rail top's)",
       [](const S& s) { return s.friction_flange.value_or(kNaN); }},
      {"weight", "1", "share of the running distance (unnormalised)",
       [](const S& s) { return s.weight; }},
      {"wheelset", "1",
       "physical wheelset (1-4, forward order of travel) whose own profiles the state wears "
       "(-1: not given)",
       [](const S& s) { return s.wheelset < 0 ? kNaN : s.wheelset + 1.0; }},
      {"reversed", "1", "1: the vehicle runs the route backwards (left in travel = physical right)",
       [](const S& s) { return s.reversed ? 1.0 : 0.0; }},
  };
  return columns;
}

}  // namespace

namespace detail {

void add_collective(GroupRecord& g, const std::string& prefix,
                    const std::vector<WheelsetStateSpec>& states) {
  for (const CollectiveColumn& c : collective_columns()) {
    std::vector<double> values;
    for (const WheelsetStateSpec& s : states) values.push_back(c.get(s));
    g.arrays.push_back(vector(prefix + c.name, std::move(values), c.units, c.description));
    const std::string_view name = c.name;
    g.arrays.back().integer = name == "wheelset" || name == "reversed";
  }
  std::vector<double> line;
  std::string labels;
  for (const WheelsetStateSpec& s : states) {
    line.push_back(s.line);
    labels += s.label + '\n';
  }
  g.arrays.push_back(
      as_integer(vector(prefix + "line", line, "1", "line of the state in its scene or file")));
  g.texts.push_back({prefix + "label", labels, "the states' labels, one per line"});
}

std::vector<WheelsetStateSpec> read_collective(const ResultsFile& file, int step,
                                               const std::string& prefix) {
  std::vector<WheelsetStateSpec> states;
  const std::string where =
      "results file " + file.path().string() + ", step " + std::to_string(step) + ", " + prefix;
  for (const CollectiveColumn& c : collective_columns()) {
    // Files written before the wheelset and direction columns existed hold neither; every
    // other column must be there.
    const std::string_view name = c.name;
    const std::string column = ResultsFile::step_group(step) + "/" + prefix + c.name;
    if ((name == "wheelset" || name == "reversed") && !file.has(column)) continue;
    const std::vector<double> values = file.read_step_array(step, prefix + c.name);
    if (states.empty()) states.resize(values.size());
    if (values.size() != states.size())
      throw InputError(where + c.name + ": " + std::to_string(values.size()) + " rows, " +
                       std::to_string(states.size()) + " expected");
    for (std::size_t i = 0; i < values.size(); ++i)
      if (value_given(c.name, values[i]))
        set_state_field(states[i], {c.name, values[i], {}}, where);
  }
  const std::vector<double> line = file.read_step_array(step, prefix + "line");
  std::istringstream labels(
      file.read_text(ResultsFile::step_group(step) + "/" + prefix + "label").value_or(""));
  for (std::size_t i = 0; i < states.size(); ++i) {
    states[i].line = i < line.size() ? static_cast<int>(line[i]) : 0;
    std::getline(labels, states[i].label);
  }
  return states;
}

}  // namespace detail

std::string collective_csv(const std::vector<WheelsetStateSpec>& states) {
  std::string out = "label";
  for (const auto& column : collective_columns()) out += std::string(",") + column.name;
  out += '\n';
  char cell[40];
  for (const WheelsetStateSpec& state : states) {
    out += core::csv_field(state.label);
    for (const auto& column : collective_columns()) {
      const double value = column.get(state);
      out += ',';
      if (std::isnan(value)) continue;  // an optional value left unset
      std::snprintf(cell, sizeof cell, "%.17g", value);
      out += cell;
    }
    out += '\n';
  }
  return out;
}

}  // namespace wheelwear::pipeline
