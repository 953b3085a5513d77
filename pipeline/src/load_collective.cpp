#include "load_collective.hpp"

#include <H5Cpp.h>

#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "wheelwear/core/csv.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/plausibility.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::pipeline::detail {

namespace {

// Limits that catch unit mistakes (mm for m, kN for N) as much as impossible values; yaw, loads,
// speed and creepages are the plausibility table's (core/plausibility.hpp), which also judges
// those columns (plausible_column) for its messages with the reason and the likely fix.
constexpr double kMaxShift = 0.05;  // [m]: beyond it no wheel is on its rail
constexpr double kMaxYaw = core::kYawLimit.refuse;
constexpr double kMaxLoad = core::kWheelLoadLimit.refuse;  // [N] on one wheel
constexpr double kMaxSpeed = core::kSpeedLimit.refuse;
constexpr double kMaxCreepage = core::kCreepageLimit.refuse;
constexpr double kMaxLateralSpeed = 5.0;  // [m/s]
constexpr double kMinCurveRadius = 50.0;  // [m]

struct Column {
  const char* name;
  const char* meaning;
  std::function<void(WheelsetStateSpec&, double)> set;
  double lo, hi;  // accepted range (inclusive)
};

std::optional<tangential::Creepages>& creepages(WheelsetStateSpec& s, bool left) {
  std::optional<tangential::Creepages>& c = left ? s.creepages_left : s.creepages_right;
  // Components not given are marked NaN until finish_state checks all three arrived.
  if (!c) c = tangential::Creepages{NAN, NAN, NAN};
  return c;
}

const std::vector<Column>& columns() {
  static const std::vector<Column> table = {
      {"dy_m", "lateral shift, + to the left [m]", [](auto& s, double v) { s.dy = v; }, -kMaxShift,
       kMaxShift},
      {"yaw_rad", "yaw angle [rad]", [](auto& s, double v) { s.yaw = v; }, -kMaxYaw, kMaxYaw},
      {"load_left_N", "vertical force on the left wheel [N]",
       [](auto& s, double v) { s.load_left = v; }, 1.0, kMaxLoad},
      {"load_right_N", "vertical force on the right wheel [N]",
       [](auto& s, double v) { s.load_right = v; }, 1.0, kMaxLoad},
      {"axle_load_N", "vertical axle force, split evenly [N]",
       [](auto& s, double v) { s.load_left = s.load_right = 0.5 * v; }, 2.0, 2 * kMaxLoad},
      {"lateral_force_left_N",
       "lateral force of the left rail on its wheel, + towards the track centre [N]",
       [](auto& s, double v) { s.lateral_force_left = v; }, -kMaxLoad, kMaxLoad},
      {"lateral_force_right_N",
       "lateral force of the right rail on its wheel, + towards the track centre [N]",
       [](auto& s, double v) { s.lateral_force_right = v; }, -kMaxLoad, kMaxLoad},
      {"speed_m_s", "forward speed [m/s]", [](auto& s, double v) { s.speed = v; }, 1e-3, kMaxSpeed},
      {"curve_radius_m", "curve radius, 0 on tangent track, + right-hand [m]",
       [](auto& s, double v) { s.curve_radius = v; }, -1e12, 1e12},
      {"lateral_velocity_m_s", "dy/dt, + to the left [m/s]",
       [](auto& s, double v) { s.lateral_velocity = v; }, -kMaxLateralSpeed, kMaxLateralSpeed},
      {"angular_velocity_rad_s", "axle angular velocity, > 0 rolling forward [rad/s]",
       [](auto& s, double v) { s.angular_velocity = v; }, 1e-3, 1e4},
      {"yaw_rate_rad_s", "d(yaw)/dt relative to the track [rad/s]",
       [](auto& s, double v) { s.yaw_rate = v; }, -10.0, 10.0},
      {"roll_rad", "wheelset roll, + left wheel down, recorded only [rad]",
       [](auto& s, double v) { s.roll = v; }, -0.1, 0.1},
      {"friction", "coefficient of friction on the rail top [-]",
       [](auto& s, double v) { s.friction = v; }, 1e-6, 2.0},
      {"friction_flange", "coefficient of friction on the gauge face [-]",
       [](auto& s, double v) { s.friction_flange = v; }, 1e-6, 2.0},
      {"vx_left", "longitudinal creepage of the left wheel [-]",
       [](auto& s, double v) { creepages(s, true)->vx = v; }, -kMaxCreepage, kMaxCreepage},
      {"vy_left", "lateral creepage of the left wheel [-]",
       [](auto& s, double v) { creepages(s, true)->vy = v; }, -kMaxCreepage, kMaxCreepage},
      {"spin_left_1_m", "spin creepage of the left wheel [1/m]",
       [](auto& s, double v) { creepages(s, true)->phi = v; }, -100.0, 100.0},
      {"vx_right", "longitudinal creepage of the right wheel [-]",
       [](auto& s, double v) { creepages(s, false)->vx = v; }, -kMaxCreepage, kMaxCreepage},
      {"vy_right", "lateral creepage of the right wheel [-]",
       [](auto& s, double v) { creepages(s, false)->vy = v; }, -kMaxCreepage, kMaxCreepage},
      {"spin_right_1_m", "spin creepage of the right wheel [1/m]",
       [](auto& s, double v) { creepages(s, false)->phi = v; }, -100.0, 100.0},
      {"weight", "share of the running distance [-]", [](auto& s, double v) { s.weight = v; }, 0.0,
       1e12},
      {"wheelset", "physical wheelset 1 ... 4 whose own profiles the state wears [-]",
       [](auto& s, double v) { s.wheelset = static_cast<int>(std::lround(v)) - 1; }, 1.0, 4.0},
      {"reversed", "1 when the vehicle runs backwards (left in travel = physical right) [-]",
       [](auto& s, double v) { s.reversed = v > 0.5; }, 0.0, 1.0},
  };
  return table;
}

// The row of the plausibility table that also judges a column, if one does. The axle load keeps
// its range only (twice a wheel's).
const core::PlausibilityLimit* plausible_column(std::string_view name) {
  if (name == "yaw_rad") return &core::kYawLimit;
  if (name == "load_left_N" || name == "load_right_N") return &core::kWheelLoadLimit;
  if (name == "speed_m_s") return &core::kSpeedLimit;
  if (name == "vx_left" || name == "vy_left" || name == "vx_right" || name == "vy_right")
    return &core::kCreepageLimit;
  return nullptr;
}

bool is_label(std::string_view name) {
  return name == "label" || name == "section";
}

std::string format_value(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

bool is_state_field(std::string_view name) {
  if (is_label(name)) return true;
  for (const Column& c : columns())
    if (name == c.name) return true;
  return false;
}

std::string state_field_names() {
  std::string names = "label (or section)";
  for (const Column& c : columns()) names += std::string(", ") + c.name;
  return names;
}

void set_state_field(WheelsetStateSpec& state, const StateField& field, const std::string& where) {
  if (is_label(field.name)) {
    // A label is one line of free text (the results file lists them one per line).
    state.label = field.text;
    for (char& c : state.label)
      if (c == '\n' || c == '\r') c = ' ';
    return;
  }
  for (const Column& c : columns()) {
    if (field.name != c.name) continue;
    if (const core::PlausibilityLimit* limit = plausible_column(c.name))
      core::require_plausible(*limit, where + ": " + c.name, field.number);
    if (!std::isfinite(field.number) || field.number < c.lo || field.number > c.hi) {
      throw InputError(where + ": " + c.name + " = " + format_value(field.number) + ": the " +
                       c.meaning + " must be finite and within [" + format_value(c.lo) + ", " +
                       format_value(c.hi) + "] (SI units)");
    }
    const std::string_view name = c.name;
    if ((name == "wheelset" || name == "reversed") && field.number != std::floor(field.number))
      throw InputError(where + ": " + c.name + " = " + format_value(field.number) +
                       ": give a whole number (" + c.meaning + ")");
    c.set(state, field.number);
    return;
  }
  throw InputError(where + ": unknown state key '" + field.name + "'; a state has " +
                   state_field_names());
}

void finish_state(WheelsetStateSpec& state, const std::string& where) {
  if (!(state.load_left > 0.0) || !(state.load_right > 0.0)) {
    throw InputError(where +
                     ": the wheel loads are missing; give load_left_N and load_right_N "
                     "(or axle_load_N), in newtons");
  }
  if (!(state.speed > 0.0))
    throw InputError(where + ": speed_m_s is missing; give the forward speed in m/s");
  if (state.curve_radius != 0.0 && std::abs(state.curve_radius) < kMinCurveRadius) {
    throw InputError(where + ": curve_radius_m = " + format_value(state.curve_radius) +
                     ": a curve radius must be at least 50 m (0 on tangent track)");
  }
  for (bool left : {true, false}) {
    const auto& c = left ? state.creepages_left : state.creepages_right;
    if (c && (std::isnan(c->vx) || std::isnan(c->vy) || std::isnan(c->phi))) {
      const char* side = left ? "left" : "right";
      throw InputError(where + ": creepages of the " + side + " wheel are incomplete; give vx_" +
                       side + ", vy_" + side + " and spin_" + side + "_1_m together");
    }
  }
}

std::vector<WheelsetStateSpec> read_collective_csv(std::string_view text,
                                                   const std::string& file_name) {
  const std::vector<core::CsvRecord> records = core::read_csv(text, file_name);
  if (records.empty()) throw InputError(file_name + ": empty load collective (no header line)");
  const std::vector<std::string>& header = records.front().fields;
  const std::string head = file_name + " line " + std::to_string(records.front().line);
  for (std::size_t k = 0; k < header.size(); ++k) {
    // Check the names before any row, so a misspelt column is reported as such.
    if (!is_state_field(header[k])) {
      throw InputError(head + ": unknown column '" + header[k] + "'; a state has " +
                       state_field_names());
    }
    for (std::size_t j = 0; j < k; ++j)
      if (header[j] == header[k] || (is_label(header[j]) && is_label(header[k])))
        throw InputError(head + ": column '" + header[k] + "' appears twice (columns " +
                         std::to_string(j + 1) + " and " + std::to_string(k + 1) +
                         "); give each once");
  }
  std::vector<WheelsetStateSpec> states;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const std::vector<std::string>& cells = records[r].fields;
    const std::string where = file_name + " line " + std::to_string(records[r].line);
    if (cells.size() != header.size()) {
      throw InputError(where + ": " + std::to_string(cells.size()) + " cells but the header has " +
                       std::to_string(header.size()) +
                       " columns (a field with a comma goes in double quotes)");
    }
    WheelsetStateSpec state;
    state.line = records[r].line;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (is_label(header[k])) {
        set_state_field(state, {header[k], 0.0, cells[k]}, where);
        continue;
      }
      if (cells[k].empty()) continue;  // an optional column left blank
      const auto value = core::parse_number(cells[k]);
      if (!value) {
        throw InputError(where + ": column " + header[k] + ": '" + cells[k] +
                         "' is not a number (SI units, e.g. 0.002 or 55e3)");
      }
      set_state_field(state, {header[k], *value, {}}, where);
    }
    finish_state(state, where);
    states.push_back(std::move(state));
  }
  return states;
}

bool value_given(std::string_view column, double value) {
  return !std::isnan(value) && !(column == "wheelset" && value == -1.0);
}

std::vector<WheelsetStateSpec> read_collective_hdf5(const std::string& image,
                                                    const std::string& file_name,
                                                    const std::string& group) {
  try {
    H5::Exception::dontPrint();
    // Opened from the bytes the scene read (its stored copy on resume), not from the disk.
    H5::FileAccPropList access;
    H5Pset_fapl_core(access.getId(), 1 << 16, false);
    H5Pset_file_image(access.getId(), const_cast<char*>(image.data()), image.size());
    // The core driver refuses a name that exists on disk: the image gets one that cannot.
    H5::H5File file("/dev/null/wheelwear-collective-image", H5F_ACC_RDONLY,
                    H5::FileCreatPropList::DEFAULT, access);
    if (!file.nameExists(group))
      throw InputError(file_name + ": no group '" + group + "' with the collective's columns");
    H5::Group g = file.openGroup(group);
    std::map<std::string, std::vector<double>> data;
    std::size_t rows = 0;
    for (hsize_t i = 0; i < g.getNumObjs(); ++i) {
      const std::string name = g.getObjnameByIdx(i);
      if (g.getObjTypeByIdx(i) != H5G_DATASET || is_label(name)) continue;
      H5::DataSet set = g.openDataSet(name);
      const H5::DataSpace space = set.getSpace();
      if (space.getSimpleExtentNdims() != 1)
        throw InputError(file_name + ": dataset " + group + "/" + name + " must be 1-D");
      std::vector<double> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
      if (!values.empty()) set.read(values.data(), H5::PredType::NATIVE_DOUBLE);
      if (!data.empty() && values.size() != rows) {
        throw InputError(file_name + ": dataset " + group + "/" + name + " has " +
                         std::to_string(values.size()) + " rows, the others " +
                         std::to_string(rows));
      }
      rows = values.size();
      data.emplace(name, std::move(values));
    }
    if (data.empty()) throw InputError(file_name + ": no datasets in group '" + group + "'");
    std::vector<WheelsetStateSpec> states(rows);
    for (std::size_t r = 0; r < rows; ++r) {
      const std::string where = file_name + " row " + std::to_string(r);
      states[r].line = static_cast<int>(r);
      for (const auto& [name, values] : data) {
        // NaN (or -1 in the integer wheelset column) marks a value not given in an optional
        // column, as blank cells do in CSV.
        if (!value_given(name, values[r])) continue;
        set_state_field(states[r], {name, values[r], {}}, where);
      }
      finish_state(states[r], where);
    }
    return states;
  } catch (const H5::Exception& error) {
    throw InputError(file_name + ": cannot read the load collective (" + error.getDetailMsg() +
                     ")");
  }
}

}  // namespace wheelwear::pipeline::detail
