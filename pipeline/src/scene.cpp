#include "wheelwear/pipeline/scene.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "load_collective.hpp"
#include "scene_keys.hpp"
#include "scene_states_source.hpp"
#include "scene_tables.hpp"
#include "scene_values.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/tangential/tangential.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

using detail::boolean;
using detail::format;
using detail::integer;
using detail::KeyHandler;
using detail::named;
using detail::number;
using detail::one_of;
using detail::read_table;
using detail::text;
using detail::where;

using detail::builtin_or_file;
using detail::file_smoothing;
using detail::inline_states;
using detail::max_drop;
using detail::profile_spec;
using detail::scene_tangential_method;
using detail::wheel_origin;

// What reading the scene's profile files noticed (a dropped point, a header that disagrees, a
// wavy flank): read once here, so that every command a scene drives says it, where the profiles
// read later for the work kept it to themselves.
void append_profile_warnings(Scene& s) {
  if (s.wheel_file.text)
    (void)profiles::wheel_profile(s.wheel_profile, s.wheel_radius, s.wheel_file, &s.warnings);
  if (s.rail_file.text)
    (void)profiles::rail_profile(s.rail_profile, s.rail_inclination, s.rail_file, &s.warnings);
}

}  // namespace

Scene parse_scene(std::string_view toml_text, const fs::path& base_directory,
                  const SceneFileReader& read, SceneUse use) {
  toml::table root;
  try {
    root = toml::parse(toml_text, std::string_view("scene"));
  } catch (const toml::parse_error& error) {
    std::ostringstream out;
    out << "scene line " << error.source().begin.line << ": " << error.description();
    throw InputError(out.str());
  }
  Scene s;
  detail::SceneFiles files(base_directory, read);
  bool inclination_given = false;
  std::optional<int> collective_line;
  int tangential_line = 0;
  bool model_given = false;
  std::optional<tangential::ContactModel> method_model;  // named by tangential_method
  std::string law_table;
  std::optional<int> vehicle_line, route_line;
  // [vehicle] and [route] fill one VehicleRun, made on first use.
  auto vehicle_run = [&]() -> VehicleRun& {
    if (!s.vehicle_run) s.vehicle_run.emplace();
    return *s.vehicle_run;
  };
  // [hook] fills one CosimulationHook, made on first use; its program runs where the scene is.
  auto hook = [&]() -> CosimulationHook& {
    if (!s.hook) {
      s.hook.emplace();
      s.hook->working_directory = base_directory;
    }
    return *s.hook;
  };

  auto section = [&](const std::string& name, std::map<std::string, KeyHandler> handlers) {
    return [name, handlers](const toml::node& node, const std::string& key) {
      const toml::table* table = node.as_table();
      if (!table) throw InputError(where(node.source(), key) + ": expected a table [" + name + "]");
      read_table(*table, name, handlers);
    };
  };

  const std::map<std::string, KeyHandler> top = {
      {"title", [&](const auto& n, const auto& k) { s.title = text(n, k); }},
      {"wheel", section("wheel",
                        {{"profile",
                          [&](const auto& n, const auto& k) {
                            s.wheel_profile = profile_spec(n, k, files, "S1002", s.wheel_file);
                          }},
                         {"radius_m",
                          [&](const auto& n, const auto& k) {
                            s.wheel_radius = number(n, k, 0.2, 1.0, "the rolling radius in m");
                          }},
                         {"origin",
                          [&](const auto& n, const auto& k) {
                            s.wheel_file.origin = wheel_origin(n, k);
                          }},
                         {"taping_line_distance_m",
                          [&](const auto& n, const auto& k) {
                            s.wheel_file.taping_line_distance =
                                number(n, k, 0.03, 0.11,
                                       "the taping line's distance from the internal face in m");
                          }},
                         {"max_drop",
                          [&](const auto& n, const auto& k) {
                            s.wheel_file.max_drop_fraction = max_drop(n, k);
                          }},
                         {"smoothing_length_m",
                          [&](const auto& n, const auto& k) {
                            s.wheel_file.smoothing_length = file_smoothing(n, k);
                          }}})},
      {"rail", section("rail",
                       {{"profile",
                         [&](const auto& n, const auto& k) {
                           s.rail_profile = profile_spec(n, k, files, "60E1", s.rail_file);
                         }},
                        {"max_drop",
                         [&](const auto& n, const auto& k) {
                           s.rail_file.max_drop_fraction = max_drop(n, k);
                         }},
                        {"smoothing_length_m",
                         [&](const auto& n, const auto& k) {
                           s.rail_file.smoothing_length = file_smoothing(n, k);
                         }},
                        {"gauge_side",
                         [&](const auto& n, const auto& k) {
                           const std::string side = text(n, k);
                           const auto mirror = profiles::gauge_side_mirror(side);
                           if (!mirror)
                             throw InputError(where(n.source(), k) + " = \"" + side +
                                              "\": use auto, left (the gauge face at the file's "
                                              "smaller lateral values) or right (larger)");
                           s.rail_file.rail_gauge_side = *mirror;
                         }},
                        {"inclination",
                         [&](const auto& n, const auto& k) {
                           // A slope (0.025) or, as the commands take it, "1:40".
                           s.rail_inclination =
                               n.is_string()
                                   ? core::parse_inclination(text(n, k), where(n.source(), k))
                                   : std::atan(number(n, k, -0.1, 0.1,
                                                      "the inclination as a slope (1:40 = 0.025)"));
                           inclination_given = true;
                         }}})},
      {"track",
       section("track",
               {{"gauge_m",
                 [&](const auto& n, const auto& k) {
                   s.gauge = number(n, k, 0.6, 2.0, "the track gauge in m");
                 }},
                {"back_to_back_m",
                 [&](const auto& n, const auto& k) {
                   s.back_to_back = number(n, k, 0.5, 2.0, "the wheels' back-to-back in m");
                 }},
                {"lateral_arm_m",
                 [&](const auto& n, const auto& k) {
                   s.lateral_arm = number(n, k, 0.3, 1.2, "the half distance of the contacts in m");
                 }}})},
      {"material",
       section("material",
               {{"youngs_modulus_Pa",
                 [&](const auto& n, const auto& k) {
                   s.youngs_modulus = number(n, k, 1e9, 1e12, "Young's modulus in Pa");
                 }},
                {"poisson", [&](const auto& n, const auto& k) {
                   s.poisson = number(n, k, 0.0, 0.5, "Poisson's ratio");
                 }}})},
      {"contact",
       section(
           "contact",
           {{"model",
             [&](const auto& n, const auto& k) {
               const std::string name = text(n, k);
               const auto model = tangential::parse_contact_model(name);
               if (!model) {
                 throw InputError(where(n.source(), k) + " = \"" + name +
                                  "\": unknown contact model; use " +
                                  core::list_names(tangential::kContactModelNames));
               }
               s.model = *model;
               model_given = true;
             }},
            {"friction",
             [&](const auto& n, const auto& k) {
               s.friction = number(n, k, 1e-6, 2.0, "the coefficient of friction (> 0)");
             }},
            {"friction_flange",
             [&](const auto& n, const auto& k) {
               s.friction_flange = number(n, k, 1e-6, 2.0,
                                          "the gauge face's coefficient of friction (> 0; "
                                          "lubricated about 0.1)");
             }},
            {"grid_nx",
             [&](const auto& n, const auto& k) {
               s.grid_nx = integer(n, k, 2, 1000, "FASTSIM cells along x");
             }},
            {"grid_ny",
             [&](const auto& n, const auto& k) {
               s.grid_ny = integer(n, k, 2, 1000, "FASTSIM strips across y");
             }},
            {"scheme",
             [&](const auto& n, const auto& k) {
               s.scheme = named(n, k, tangential::kSchemeNames, "FASTSIM scheme");
             }},
            {"tangential_method",
             [&](const auto& n, const auto& k) {
               const std::string name = text(n, k);
               const auto method = scene_tangential_method(name);
               if (!method) {
                 throw InputError(where(n.source(), k) + " = \"" + name +
                                  "\": unknown tangential method; use fastsim (with the contact "
                                  "model), best or exact, or one of fastsim-sdec, fastsim-eql, "
                                  "fastsim-eqe, fastsim-eqe-shifted (which name the model too)");
               }
               s.tangential = method->method;
               if (method->names_model) method_model = method->model;
               tangential_line = static_cast<int>(n.source().begin.line);
             }},
            {"strip_width_m",
             [&](const auto& n, const auto& k) {
               s.strip_width = number(n, k, 1e-5, 2e-3, "the strip width in m");
             }},
            {"slip_point",
             [&](const auto& n, const auto& k) {
               s.slip_point = named(n, k, contactgeom::kSlipPointNames, "slip point");
             }},
            {"normal_method",
             [&](const auto& n, const auto& k) {
               s.normal_method = named(n, k, contactgeom::kNormalMethodNames, "normal method");
             }},
            {"contact_plane",
             [&](const auto& n, const auto& k) {
               s.contact_plane = named(n, k, contactgeom::kContactPlaneNames, "contact plane");
             }},
            {"virtual_penetration",
             [&](const auto& n, const auto& k) {
               s.virtual_penetration = number(n, k, 0.05, 1.0, "Kik-Piotrowski's epsilon");
             }},
            {"max_contact_angle_rad", [&](const auto& n, const auto& k) {
               s.max_contact_angle = number(n, k, 1.0, 1.56,
                                            "the steepest contact angle taken as contact, in rad");
             }}})},
      {"wear", section("wear",
                       {{"law",
                         [&](const auto& n, const auto& k) {
                           s.wear_law = one_of(n, k, {"usfd", "archard"},
                                               "unknown wear law; use usfd or archard") == 0
                                            ? "usfd"
                                            : "archard";
                         }},
                        {"law_table", [&](const auto& n, const auto& k) {
                           const fs::path file = files.resolve(text(n, k));
                           auto content = files.read(k, file);
                           if (!content) {
                             throw InputError(where(n.source(), k) + ": no such file " +
                                              file.string());
                           }
                           law_table = file.string();
                           s.wear_law_text = std::move(*content);
                         }}})},
      {"run",
       section(
           "run",
           {{"distance_m",
             [&](const auto& n, const auto& k) {
               s.distance = number(n, k, 1.0, 1e9, "the running distance in m");
             }},
            {"step_distance_m",
             [&](const auto& n, const auto& k) {
               s.step_distance = number(n, k, 1e-3, 1e9, "the longest step in m");
             }},
            {"max_depth_step_m",
             [&](const auto& n, const auto& k) {
               s.max_depth_step = number(n, k, 1e-9, 2e-3, "the deepest increment of a step in m");
             }},
            {"smoothing_length_m",
             [&](const auto& n, const auto& k) {
               s.smoothing_length = number(n, k, 0.0, 0.02, "the smoothing length in m");
             }},
            {"wheels", [&](const auto& n, const auto& k) {
               s.separate_wheels =
                   one_of(n, k, {"shared", "separate"},
                          "use shared (one profile worn by both wheels) or separate") == 1;
             }}})},
      {"limits",
       section("limits",
               {{"Sd_min_m",
                 [&](const auto& n, const auto& k) {
                   s.limits.Sd_min = number(n, k, 0.0, 0.05, "the least flange thickness in m");
                 }},
                {"Sh_max_m",
                 [&](const auto& n, const auto& k) {
                   s.limits.Sh_max = number(n, k, 0.0, 0.1, "the largest flange height in m");
                 }},
                {"qR_min_m",
                 [&](const auto& n, const auto& k) {
                   s.limits.qR_min = number(n, k, 0.0, 0.05, "the least qR in m");
                 }},
                {"stop", [&](const auto& n, const auto& k) { s.limits.stop = boolean(n, k); }}})},
      {"output",
       section("output",
               {{"state_summaries",
                 [&](const auto& n, const auto& k) { s.state_summaries = boolean(n, k); }},
                {"tgamma_maps",
                 [&](const auto& n, const auto& k) { s.tgamma_maps = boolean(n, k); }}})},
      {"vehicle",
       section("vehicle",
               {{"file",
                 [&](const auto& n, const auto& k) {
                   vehicle_line = static_cast<int>(n.source().begin.line);
                   const auto file = builtin_or_file(
                       n, k, files, "the built-in coach",
                       "a vehicle file (wheelwear curving --export-default-vehicle DIR writes "
                       "one to start from)");
                   VehicleRun& run = vehicle_run();
                   run.vehicle =
                       file ? vehicle::parse_vehicle(file->content, "vehicle file " +
                                                                        file->path.string())
                            : vehicle::default_vehicle();
                   run.vehicle_file = file ? file->path.string() : std::string();
                 }},
                {"wheelsets",
                 [&](const auto& n, const auto& k) {
                   vehicle_run().wheelsets =
                       one_of(n, k, {"all", "leading"},
                              "use all (the four wheelsets) or leading (the leading wheelset of "
                              "each bogie)") == 0
                           ? WheelsetSelection::all
                           : WheelsetSelection::leading;
                 }},
                {"contact_table",
                 [&](const auto& n, const auto& k) {
                   vehicle_run().contact_table = boolean(n, k);
                 }},
                {"wear_from_table",
                 [&](const auto& n, const auto& k) {
                   vehicle_run().wear_from_table = boolean(n, k);
                 }},
                {"critical_speed",
                 [&](const auto& n, const auto& k) {
                   vehicle_run().critical_speed = boolean(n, k);
                 }},
                {"resolve_depth_m",
                 [&](const auto& n, const auto& k) {
                   vehicle_run().resolve_depth =
                       number(n, k, 0.0, 1e-3,
                              "the wear depth between two solves of the vehicle in m (0: "
                              "every step)");
                 }}})},
      {"route", section("route",
                        {{"file",
                          [&](const auto& n, const auto& k) {
                            route_line = static_cast<int>(n.source().begin.line);
                            const auto file = builtin_or_file(
                                n, k, files, "the built-in mixed line",
                                "a route file (docs/routes.md)");
                            VehicleRun& run = vehicle_run();
                            run.route = file ? vehicle::parse_route(file->content,
                                                                    file->path.string())
                                             : vehicle::default_route();
                            run.route_file = file ? file->path.string() : std::string();
                          }},
                         {"direction", [&](const auto& n, const auto& k) {
                            vehicle_run().direction = static_cast<RunningDirection>(one_of(
                                n, k, {"forward", "reverse", "both"},
                                "use forward (start to end), reverse (end to start, the last "
                                "wheelset leading) or both (half the distance each way)"));
                          }}})},
      {"time_domain", section("time_domain",
                              detail::time_domain_keys(
                                  [&]() -> TimeDomainKeys& { return vehicle_run().time_domain; },
                                  files))},
      {"hook", section("hook", detail::hook_keys(hook))},
      {"load_collective",
       section("load_collective",
               {{"file",
                 [&](const auto& n, const auto& k) {
                   collective_line = static_cast<int>(n.source().begin.line);
                   const fs::path file = files.resolve(text(n, k));
                   const std::string ext = core::to_lower(file.extension().string());
                   const bool hdf5 = ext == ".h5" || ext == ".hdf5";
                   const auto content = files.read(k, file, !hdf5);
                   if (!content)
                     throw InputError(where(n.source(), k) + ": no such file " + file.string());
                   if (hdf5) {
                     auto states = detail::read_collective_hdf5(*content, file.string(), "/");
                     s.states.insert(s.states.end(), states.begin(), states.end());
                     return;
                   }
                   auto states = detail::read_collective_csv(*content, file.filename().string());
                   s.states.insert(s.states.end(), states.begin(), states.end());
                 }},
                {"state", [&](const auto& n, const auto& k) {
                   collective_line = static_cast<int>(n.source().begin.line);
                   auto states = inline_states(n, k);
                   s.states.insert(s.states.end(), states.begin(), states.end());
                 }}})},
  };
  read_table(root, "", top);

  if (!inclination_given) s.rail_inclination.reset();
  if (method_model) {
    if (model_given && s.model != *method_model) {
      throw InputError("scene line " + std::to_string(tangential_line) +
                       ": contact.tangential_method names the contact model " +
                       std::string(tangential::model_name(*method_model)) +
                       " but contact.model = \"" + std::string(tangential::model_name(s.model)) +
                       "\"; give one of them");
    }
    s.model = *method_model;
  }
  if (s.tangential != TangentialMethod::fastsim && s.model != tangential::ContactModel::sdec) {
    const char* name = s.tangential == TangentialMethod::best ? "best" : "exact";
    throw InputError("scene line " + std::to_string(tangential_line) +
                     ": contact.tangential_method = \"" + name +
                     "\" needs contact.model = \"sdec\" (it solves the SDEC patch); use "
                     "tangential_method = \"fastsim\" with model = \"" +
                     std::string(tangential::model_name(s.model)) + "\"");
  }
  if (s.tangential == TangentialMethod::exact && std::max(s.grid_nx, s.grid_ny) > 400) {
    throw InputError("scene line " + std::to_string(tangential_line) +
                     ": contact.tangential_method = \"exact\" solves grid_nx x grid_ny elements "
                     "per patch; " +
                     std::to_string(s.grid_nx) + " x " + std::to_string(s.grid_ny) +
                     " is beyond 400 x 400 (seconds and gigabytes per patch): use at most 400");
  }
  s.wear_law_table = law_table;
  s.inputs = files.take();
  append_profile_warnings(s);
  s.step_distance = std::min(s.step_distance, s.distance);  // one step need not exceed the run
  const double steps = std::ceil(s.distance / s.step_distance);
  if (steps > kStepsLimit) {
    throw InputError("scene: [run] distance_m = " + core::format_number(s.distance) +
                     " in steps of step_distance_m = " + core::format_number(s.step_distance) +
                     " makes " + core::format_number(steps) +
                     " steps, more than 100000; give a longer step_distance_m (each step is "
                     "also kept below max_depth_step_m of wear)");
  }
  if (steps > kStepsWarning) {
    s.warnings.push_back("scene: [run] distance_m / step_distance_m makes " +
                         core::format_number(steps) +
                         " steps (more than 10000): every step evaluates the whole collective "
                         "and writes its group; a longer step_distance_m runs faster");
  }
  detail::settle_states_source(s, {collective_line, vehicle_line, route_line}, use);
  return s;
}

Scene load_scene(const fs::path& path, SceneUse use) {
  if (!fs::is_regular_file(path)) throw InputError("scene " + path.string() + ": no such file");
  const std::string text = core::read_text_file(path);
  try {
    // Absolute: the files it names are recorded by the paths a resumed run looks them up by.
    return parse_scene(text, fs::absolute(path).parent_path(), {}, use);
  } catch (const InputError& error) {
    throw InputError(path.string() + ": " + error.what());
  }
}

profiles::WheelLimits LimitKeys::resolve(double diameter) const {
  // Below the standard's smallest wheel the unset limits are not watched: NaN reaches nothing.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  profiles::WheelLimits limits{kNaN, kNaN, kNaN};
  if (diameter >= profiles::kSmallestStandardWheel) limits = profiles::in_service_limits(diameter);
  limits.Sd_min = Sd_min.value_or(limits.Sd_min);
  limits.Sh_max = Sh_max.value_or(limits.Sh_max);
  limits.qR_min = qR_min.value_or(limits.qR_min);
  return limits;
}

}  // namespace wheelwear::pipeline
