#include "wheelwear/vehicle/vehicle_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/core/toml_keys.hpp"

namespace wheelwear::vehicle {

namespace {

using core::TomlKeyHandler;
using Handlers = std::map<std::string, TomlKeyHandler>;

// Reads one file; remembers which keys it met so the required ones can be checked after.
class VehicleReader {
 public:
  explicit VehicleReader(std::string document) : document_(document), keys_(std::move(document)) {}

  Vehicle read(const toml::table& root) {
    Vehicle v;
    keys_.read_table(root, "", top_level(v));
    for (const char* key :
         {"car_body.mass_kg", "car_body.cg_height_m", "bogie.mass_kg", "bogie.cg_height_m",
          "bogie.wheelbase_m", "bogie.pivot_spacing_m", "wheelset.mass_kg",
          "wheelset.wheel_radius_m", "wheelset.lateral_arm_m", "primary.kx_N_m", "primary.ky_N_m",
          "primary.lateral_spacing_m", "secondary.kx_N_m", "secondary.ky_N_m",
          "secondary.lateral_spacing_m"}) {
      if (!seen_.count(key))
        throw InputError(document() + ": " + key +
                         " is missing (every vehicle gives it; see `wheelwear curving "
                         "--export-default-vehicle DIR` for a complete file)");
    }
    v.wheelset.body.cg_height = v.wheelset.wheel_radius;
    for (const std::string& key : seen_)
      if (key.rfind("contact.", 0) == 0) v.contact.given.insert(key.substr(8));
    if (!stop_deflection_.empty() || !stop_force_.empty()) {
      v.lateral_stop.deflection = stop_deflection_;
      v.lateral_stop.force = stop_force_;
      if (stop_clearance_ && !stop_deflection_.empty() &&
          std::abs(*stop_clearance_ - stop_deflection_.front()) > 1e-12) {
        throw InputError(document() + ": stops.lateral_clearance_m = " +
                         core::TomlKeys::format(*stop_clearance_) +
                         " must equal the first of stops.lateral_deflection_m (" +
                         core::TomlKeys::format(stop_deflection_.front()) + ")");
      }
    }
    try {
      v.validate();
    } catch (const InputError& e) {
      throw InputError(document() + ": " + e.what());
    }
    return v;
  }

 private:
  const std::string& document() const { return document_; }

  // A number handler that stores into `target` and marks the key seen.
  TomlKeyHandler number(double& target, double lo, double hi, std::string meaning) {
    return [this, &target, lo, hi, meaning](const toml::node& node, const std::string& key) {
      target = keys_.number(node, key, lo, hi, meaning);
      seen_.insert(key);
    };
  }
  // A documented key the model does not use (yet): its value is checked, not kept.
  TomlKeyHandler checked(double lo, double hi, std::string meaning) {
    return [this, lo, hi, meaning](const toml::node& node, const std::string& key) {
      keys_.number(node, key, lo, hi, meaning);
    };
  }
  TomlKeyHandler text(std::string& target) {
    return [this, &target](const toml::node& node, const std::string& key) {
      target = keys_.text(node, key);
      seen_.insert(key);
    };
  }
  TomlKeyHandler expect_text(std::string expected) {
    return [this, expected](const toml::node& node, const std::string& key) {
      const std::string value = keys_.text(node, key);
      if (value != expected)
        throw InputError(keys_.where(node.source(), key) + " = \"" + value + "\": only \"" +
                         expected + "\" is supported (values per " + expected.substr(4) + ")");
    };
  }
  TomlKeyHandler array(std::vector<double>& target, double lo, double hi, std::string meaning) {
    return [this, &target, lo, hi, meaning](const toml::node& node, const std::string& key) {
      const toml::array* values = node.as_array();
      if (!values || values->empty())
        throw InputError(keys_.where(node.source(), key) + ": expected a list of numbers (" +
                         meaning + ")");
      target.clear();
      for (const toml::node& value : *values)
        target.push_back(keys_.number(value, key, lo, hi, meaning));
      seen_.insert(key);
    };
  }
  // A list of wheelset numbers, 1 to 4 in order of travel, each at most once.
  TomlKeyHandler wheelsets(std::array<bool, kWheelsets>& target, std::string meaning) {
    return [this, &target, meaning](const toml::node& node, const std::string& key) {
      const toml::array* values = node.as_array();
      if (!values)
        throw InputError(keys_.where(node.source(), key) +
                         ": expected a list of wheelset numbers, 1 to 4 in order of travel (" +
                         meaning + "), e.g. [1, 2, 3, 4]; [] for none");
      target.fill(false);
      for (const toml::node& value : *values) {
        const double number = keys_.number(value, key, 1, kWheelsets, meaning);
        const auto k = static_cast<int>(number);
        if (k != number || target[k - 1])
          throw InputError(keys_.where(node.source(), key) +
                           ": give each wheelset's number (a whole number, 1 to 4) once");
        target[k - 1] = true;
      }
      seen_.insert(key);
    };
  }
  TomlKeyHandler table(Handlers handlers) {
    return [this, handlers](const toml::node& node, const std::string& key) {
      const toml::table* t = node.as_table();
      if (!t)
        throw InputError(keys_.where(node.source(), key) + ": expected a table [" + key + "]");
      keys_.read_table(*t, key, handlers);
    };
  }

  Handlers body(RigidBody& b) {
    return {{"mass_kg", number(b.mass, 1.0, 1e6, "mass")},
            {"roll_inertia_kg_m2", number(b.roll_inertia, 0.0, 1e8, "roll inertia")},
            {"pitch_inertia_kg_m2", number(b.pitch_inertia, 0.0, 1e8, "pitch inertia")},
            {"yaw_inertia_kg_m2", number(b.yaw_inertia, 0.0, 1e8, "yaw inertia")},
            {"cg_height_m", number(b.cg_height, 0.0, 5.0, "centre of gravity above the rail")}};
  }

  Handlers stage(SuspensionStage& s, const std::string& basis, bool secondary) {
    Handlers h{{"basis", expect_text(basis)},
               {"kx_N_m", number(s.kx, 0.0, 1e10, "longitudinal stiffness")},
               {"ky_N_m", number(s.ky, 0.0, 1e10, "lateral stiffness")},
               {"kz_N_m", number(s.kz, 0.0, 1e10, "vertical stiffness")},
               {"cx_N_s_m", number(s.cx, 0.0, 1e8, "longitudinal damping")},
               {"cy_N_s_m", number(s.cy, 0.0, 1e8, "lateral damping")},
               {"cz_N_s_m", number(s.cz, 0.0, 1e8, "vertical damping")},
               {"kpsi_N_m_rad", number(s.kpsi, 0.0, 1e10, "yaw stiffness")},
               {"lateral_spacing_m", number(s.lateral_spacing, 0.2, 4.0, "lateral spacing")},
               {"height_m", number(s.height, 0.0, 5.0, "height above the rail")}};
    if (secondary) {
      h["yaw_damper_c_N_s_m"] = number(s.yaw_damper, 0.0, 1e8, "yaw damper");
      h["kroll_antiroll_N_m_rad"] = number(s.antiroll, 0.0, 1e10, "anti-roll bar");
      h["height_upper_m"] = checked(0.0, 5.0, "body-side attachment height");
      h["height_lower_m"] = checked(0.0, 5.0, "bogie-side attachment height");
    }
    return h;
  }

  Handlers top_level(Vehicle& v) {
    return {
        {"vehicle", table({{"name", text(v.name)},
                           {"source", text(v.source)},
                           {"verified_against_primary",
                            [this](const toml::node& node, const std::string& key) {
                              keys_.boolean(node, key);
                            }}})},
        {"car_body", table(body(v.car_body))},
        {"bogie", table([&] {
           Handlers h = body(v.bogie);
           h["wheelbase_m"] = number(v.bogie_wheelbase, 0.5, 6.0, "distance between the axles");
           h["pivot_spacing_m"] =
               number(v.pivot_spacing, 1.0, 40.0, "distance between the bogie centres");
           return h;
         }())},
        {"wheelset",
         table(
             {{"mass_kg", number(v.wheelset.body.mass, 1.0, 1e5, "mass")},
              {"roll_inertia_kg_m2",
               number(v.wheelset.body.roll_inertia, 0.0, 1e6, "roll inertia")},
              {"yaw_inertia_kg_m2", number(v.wheelset.body.yaw_inertia, 0.0, 1e6, "yaw inertia")},
              {"spin_inertia_kg_m2", number(v.wheelset.spin_inertia, 0.0, 1e5, "spin inertia")},
              {"wheel_radius_m", number(v.wheelset.wheel_radius, 0.2, 0.8, "nominal radius")},
              {"back_to_back_m", number(v.wheelset.back_to_back, 1.0, 2.0, "back-to-back")},
              {"taping_line_from_back_m", checked(0.0, 0.2, "taping line from the internal face")},
              {"lateral_arm_m", number(v.wheelset.lateral_arm, 0.3, 1.2, "contact arm e0")},
              {"powered_wheelsets",
               wheelsets(v.powered, "the motored or braked axles a route's traction_N acts on")}})},
        {"primary", table(stage(v.primary, "per_axlebox", false))},
        {"secondary", table(stage(v.secondary, "per_bogie_side", true))},
        {"stops",
         table({{"lateral_clearance_m",
                 [this](const toml::node& node, const std::string& key) {
                   stop_clearance_ = keys_.number(node, key, 0.0, 0.2, "lateral clearance");
                 }},
                {"lateral_height_m", number(v.lateral_stop.height, 0.0, 5.0, "stop height")},
                {"lateral_deflection_m", array(stop_deflection_, 0.0, 0.5, "stop deflections")},
                {"lateral_force_N", array(stop_force_, 0.0, 1e7, "stop forces")}})},
        {"contact",
         table({{"wheel_profile", text(v.contact.wheel_profile)},
                {"rail_profile", text(v.contact.rail_profile)},
                {"rail_inclination",
                 number(v.contact.rail_inclination, 0.0, 0.1, "rail inclination")},
                {"gauge_m", number(v.contact.gauge, 1.0, 1.8, "track gauge")},
                {"gauge_measuring_depth_m", checked(0.0, 0.03, "gauge depth")},
                {"back_to_back_m", number(v.contact.back_to_back, 1.0, 1.8, "back-to-back")},
                {"friction", number(v.contact.friction, 0.01, 1.0, "friction coefficient")}})},
    };
  }

  std::string document_;
  core::TomlKeys keys_;
  std::set<std::string> seen_;
  std::vector<double> stop_deflection_, stop_force_;
  std::optional<double> stop_clearance_;
};

}  // namespace

Vehicle parse_vehicle(std::string_view text, std::string_view document) {
  toml::table root;
  try {
    root = toml::parse(text);
  } catch (const toml::parse_error& e) {
    throw InputError(std::string(document) + " line " + std::to_string(e.source().begin.line) +
                     ": " + std::string(e.description()));
  }
  return VehicleReader(std::string(document)).read(root);
}

Vehicle read_vehicle(const std::filesystem::path& path) {
  return parse_vehicle(core::read_text_file(path), "vehicle file " + path.string());
}

}  // namespace wheelwear::vehicle
