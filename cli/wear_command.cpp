// `wheelwear wear`: the wear of one wheel position, per contact patch, mapped onto the wheel.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "contact_inputs.hpp"
#include "contact_wear.hpp"
#include "json_writer.hpp"
#include "output_path.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace wheelwear::cli {

namespace {

struct WearArgs {
  ContactInputs in;
  std::string law = "usfd";
  std::string law_table;
  std::string model = "sdec";
  bool compare = false;
  bool exact = false;  // --exact: also Kalker's exact theory on the gap
  ExactPatchOptions exact_options;
  // To refuse them without --exact.
  std::vector<const CLI::Option*> exact_flags;
  int cells = 50;
  std::string map;
  bool json = false;
  bool overwrite = false;
};

// Lateral position on the wheel in its profile frame (+ towards the field side, 0 at the taping
// line), as every output gives it.
double wheel_y(const profiles::Profile& wheel, double s) {
  return wheel.position(s).x();
}

ModelWear wear_of(const WearArgs& args, const contactgeom::WheelRailPair& pair,
                  const contactgeom::WheelRailPatch& p, tangential::ContactModel model,
                  const wear::WearLaw& law) {
  return model_wear(args.in, pair, p, model, law, args.cells, !args.map.empty());
}

std::string model_json(const ModelWear& w, const profiles::Profile& wheel) {
  JsonObject o;
  o.add("model", w.model)
      .add("worn_volume_per_metre", w.summary.volume_per_metre)
      .add("peak_depth_per_metre", w.summary.peak_depth)
      .add("peak_y_wheel", wheel_y(wheel, w.summary.peak_s))
      .add("centroid_y_wheel", wheel_y(wheel, w.summary.centroid_s))
      .add("band_width", w.summary.band_width)
      .add("frictional_work", w.solution.frictional_work)
      .add("Fx", w.solution.forces.Fx)
      .add("Fy", w.solution.forces.Fy);
  return o.str();
}

// Long-format CSV: one row per cell (T gamma) and per wheel bin (depth); written to a
// temporary file and renamed, so an existing map is replaced whole or not at all.
void write_map(const std::string& path, const std::vector<std::vector<ModelWear>>& per_patch,
               const profiles::Profile& wheel) {
  const std::filesystem::path target(path);
  std::filesystem::path partial = target;
  partial += ".partial";
  try {
    std::ofstream out(partial);
    if (!out) throw InputError("--map " + path + ": cannot write there");
    out << "# wheelwear wear map. kind=tgamma: frictional work density per metre rolled [J/m^2/m]"
           " at cell (x_m, y_m) of the patch frame (+y towards the flange); kind=depth: worn"
           " depth per metre running [m/m] at wheel arc length s_wheel_m, lateral position "
           "y_wheel_m"
           " (profile frame, + towards the field side, 0 at the taping line)\n";
    out << "patch,model,kind,x_m,y_m,s_wheel_m,y_wheel_m,value\n";
    out.precision(10);
    for (std::size_t k = 0; k < per_patch.size(); ++k) {
      for (const ModelWear& w : per_patch[k]) {
        const auto& f = *w.solution.fields;
        const std::string& name = w.model;
        for (std::size_t c = 0; c < f.work.size(); ++c)
          out << k + 1 << ',' << name << ",tgamma," << f.x[c] << ',' << f.y[c] << ",,," << f.work[c]
              << '\n';
        for (std::size_t b = 0; b < w.distribution.depth.size(); ++b) {
          const double s = w.distribution.s(b);
          out << k + 1 << ',' << name << ",depth,,," << s << ',' << wheel_y(wheel, s) << ','
              << w.distribution.depth[b] << '\n';
        }
      }
    }
    if (!out) throw std::runtime_error("--map " + path + ": write failed");
    out.close();
    std::filesystem::rename(partial, target);
  } catch (...) {
    std::filesystem::remove(partial);  // an existing map stays as it was
    throw;
  }
}

// A contact computed but not ok (a load jump, flange climb, past the flange): its wear is
// printed, and the command fails with exit status 3 (docs/cli.md).
void require_ok(const contactgeom::WheelRailContact& contact) {
  if (contact.status == contactgeom::WheelRailStatus::ok) return;
  throw std::runtime_error(std::string("contact ") + contactgeom::status_name(contact.status) +
                           (contact.message.empty() ? "" : ": " + contact.message) +
                           " (its wear is printed above)");
}

void run_wear(const WearArgs& args) {
  refuse_existing(args.map, "--map", args.overwrite);
  check_wear_grid(args.in.motion.speed, args.cells);
  if (args.exact) {
    check_exact_patch_options(args.exact_options);
  } else {
    for (const CLI::Option* given : args.exact_flags)
      if (given->count() > 0) throw InputError(given->get_name() + ": applies only with --exact");
  }
  const wear::WearLaw law = wear_law_named(args.law, args.law_table);
  const tangential::ContactModel chosen = contact_model_named(args.model);
  const SolvedContact solved = solve_contact(args.in);
  const auto& contact = solved.contact;
  std::vector<std::string> warnings = solved.warnings;
  for (const std::string& w : warnings) std::cerr << "wheelwear: warning: " << w << '\n';
  if (!contactgeom::carries_load(contact.status)) {
    throw std::runtime_error(std::string("contact ") + contactgeom::status_name(contact.status) +
                             ": " + contact.message);
  }
  if (!contact.message.empty()) {
    std::cerr << "wheelwear: warning: " << contact.message << '\n';
    warnings.push_back(contact.message);
  }
  const profiles::Profile& wheel = solved.pair.wheel;

  std::vector<std::vector<ModelWear>> per_patch;
  for (const auto& p : contact.patches) {
    std::vector<ModelWear> models;
    if (args.compare) {
      for (tangential::ContactModel m : tangential::kContactModels) {
        if (m == tangential::ContactModel::hertz && !p.hertz) continue;
        models.push_back(wear_of(args, solved.pair, p, m, law));
      }
    } else {
      models.push_back(wear_of(args, solved.pair, p, chosen, law));
    }
    if (args.exact) models.push_back(exact_wear(args.in, solved.pair, p, law, args.exact_options));
    per_patch.push_back(std::move(models));
  }
  if (!args.map.empty()) write_map(args.map, per_patch, wheel);

  if (args.json) {
    std::vector<std::string> patches;
    for (std::size_t k = 0; k < per_patch.size(); ++k) {
      const auto& p = contact.patches[k];
      std::vector<std::string> models;
      for (const ModelWear& w : per_patch[k]) models.push_back(model_json(w, wheel));
      const ModelWear& first = per_patch[k].front();
      JsonObject o;
      o.add("N", p.normal_force)
          .add("y_wheel", -p.y_wheel)
          .add("contact_angle", p.contact_angle)
          .add("worn_volume_per_metre", first.summary.volume_per_metre)
          .add("peak_depth_per_metre", first.summary.peak_depth)
          .add("peak_y_wheel", wheel_y(wheel, first.summary.peak_s))
          .add("centroid_y_wheel", wheel_y(wheel, first.summary.centroid_s))
          .add_raw("models", json_array(models));
      patches.push_back(o.str());
    }
    JsonObject out;
    out.add("status", contactgeom::status_name(contact.status))
        .add("law", args.law)
        .add("V", args.in.motion.speed)
        .add_raw("warnings", json_strings(warnings))
        .add_raw("patches", json_array(patches));
    std::cout << out.str() << '\n';
    require_ok(contact);
    return;
  }
  std::printf("wear law %s, V = %g m/s\n", args.law.c_str(), args.in.motion.speed);
  for (std::size_t k = 0; k < per_patch.size(); ++k) {
    const auto& p = contact.patches[k];
    std::printf(
        "patch %zu: N %.5g N, O at y = %.2f mm on the wheel (profile frame, + towards the "
        "field side)\n",
        k + 1, p.normal_force, -p.y_wheel * 1e3);
    std::printf("  %-12s %14s %14s %12s %12s %10s\n", "model", "volume mm2/km", "peak um/km",
                "peak y mm", "centroid mm", "band mm");
    for (const ModelWear& w : per_patch[k]) {
      std::printf("  %-12s %14.5g %14.5g %12.3f %12.3f %10.2f\n", w.model.c_str(),
                  w.summary.volume_per_metre * 1e6 * 1e3, w.summary.peak_depth * 1e6 * 1e3,
                  wheel_y(wheel, w.summary.peak_s) * 1e3,
                  wheel_y(wheel, w.summary.centroid_s) * 1e3, w.summary.band_width * 1e3);
    }
  }
  require_ok(contact);
}

}  // namespace

void add_wear_command(CLI::App& app) {
  auto args = std::make_shared<WearArgs>();
  CLI::App* cmd = app.add_subcommand(
      "wear",
      "Wear of one wheel position: the contact patches of `wheelwear contact`, the tangential\n"
      "problem with a contact model, a wear law per cell, and the worn depth per metre of\n"
      "running distance across the wheel profile. `--compare` sets the five contact models\n"
      "side by side: sdec (FASTSIM-SDEC on the SDEC region), eql, eqe (equivalent ellipse at\n"
      "O), eqe-shifted (ellipse at O'), hertz (Hertz ellipse from the curvatures at O).\n"
      "Example: wheelwear wear --dy 0.004 --load 55000 --vx 1e-3 --phi 0.1 --V 20 --compare");
  add_contact_options(cmd, args->in);
  cmd->add_option("--law", args->law, "wear law: usfd (T gamma) or archard (KTH map)")
      ->capture_default_str();
  cmd->add_option("--law-table", args->law_table,
                  "your own table for the law (CSV, the format of data/wear/usfd.csv for usfd,\n"
                  "data/wear/archard.csv for archard)");
  cmd->add_option("--model", args->model,
                  "contact model: " + core::list_names(tangential::kContactModelNames))
      ->capture_default_str();
  cmd->add_flag("--compare", args->compare, "all five contact models side by side");
  cmd->add_flag("--exact", args->exact,
                "also wear each patch with Kalker's exact theory on the real gap (model exact,\n"
                "last): the exact normal problem on the undeformed distance in the patch's\n"
                "contact plane and steady rolling (as `contact --tangential exact`), each\n"
                "element worn by the law and mapped onto the wheel as FASTSIM's cells are; the\n"
                "reference for where the SDEC chain puts the wear. 0.02-2 s per patch");
  args->exact_flags = {
      cmd->add_option("--exact-grid", args->exact_options.grid,
                      "--exact: elements per side, 8 ... 400")
          ->capture_default_str(),
      cmd->add_option("--exact-margin", args->exact_options.margin,
                      "--exact: the grid covers the patch times this, 1 ... 5; raise it when\n"
                      "the exact contact area reaches the grid's border")
          ->capture_default_str(),
      cmd->add_flag("--exact-radius-variation", args->exact_options.radius_variation,
                    kRadiusVariationHelp)};
  cmd->add_option("--cells", args->cells, "FASTSIM cells per direction")->capture_default_str();
  cmd->add_option("--map", args->map, "write the T gamma map and the depth distribution (CSV)");
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing --map file");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run_wear(*args); });
}

}  // namespace wheelwear::cli
