// One wheel on its rail: the contact patches of `wheelwear contact` and the wear of
// `wheelwear wear`, with the strips, the T gamma map and the depth as arrays.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "choices.hpp"
#include "contact_inputs.hpp"
#include "contact_wear.hpp"
#include "profile_file_kwargs.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

// The inputs `contact` and `wear` share, from keyword arguments (SI units).
cli::ContactInputs contact_inputs(const py::dict& kw) {
  cli::ContactInputs in;
  const auto get = [&kw](const char* key, auto& target) {
    if (kw.contains(key) && !kw[key].is_none())
      target = kw[key].cast<std::remove_reference_t<decltype(target)>>();
  };
  get("wheel", in.wheel);
  get("rail", in.rail);
  get("dy", in.pose.dy);
  get("yaw", in.pose.yaw);
  get("roll", in.pose.roll);
  get("load", in.load);
  get("inclination", in.inclination);
  get("gauge", in.gauge);
  get("back_to_back", in.back_to_back);
  if (kw.contains("wheel_radius") && !kw["wheel_radius"].is_none())
    in.wheel_radius = kw["wheel_radius"].cast<double>();
  get("E", in.E);
  get("nu", in.nu);
  get("strip_width", in.strip_width);
  get("normal_method", in.normal_method);
  get("contact_plane", in.contact_plane);
  get("epsilon", in.epsilon);
  get("vx", in.creepages.vx);
  get("vy", in.creepages.vy);
  get("phi", in.creepages.phi);
  get("mu", in.mu);
  get("V", in.motion.speed);
  ProfileFileKwargs files;
  get("origin", files.origin);
  get("taping_line_distance", files.taping_line_distance);
  get("max_drop", files.max_drop);
  get("gauge_side", files.gauge_side);
  get("smoothing", files.smoothing);
  in.files = profile_file_args(files, in.wheel != "S1002", in.rail != "60E1" && in.rail != "UIC60");
  cli::require_choice("--normal-method", in.normal_method,
                      core::all_names(contactgeom::kNormalMethodNames));
  cli::require_choice("--contact-plane", in.contact_plane,
                      core::all_names(contactgeom::kContactPlaneNames));
  return in;
}

py::dict patch_dict(const contactgeom::WheelRailPatch& p) {
  py::dict o;
  o["area"] = p.measures.area;
  o["length"] = p.measures.length;
  o["width"] = p.measures.width;
  o["W1"] = p.measures.W1;
  o["W2"] = p.measures.W2;
  o["a"] = p.sdec.a;
  o["b"] = p.sdec.b;
  o["psi"] = p.sdec.psi;
  // Positions on the profiles in each profile's own frame (+ towards the field side), as the
  // command line prints them.
  o["y_wheel"] = -p.y_wheel;
  o["y_rail"] = -p.y_rail;
  o["s_wheel"] = p.s_wheel;
  o["contact_angle"] = p.contact_angle;
  o["contact_angle_centre"] = p.contact_angle_centre;
  o["plane_angle"] = p.plane_angle;
  o["N"] = p.normal_force;
  o["pmax"] = p.pmax;
  o["rolling_radius"] = p.rolling_radius;
  o["share"] = p.share;
  o["hertz_a"] = p.hertz ? p.hertz->a : std::nan("");
  o["hertz_b"] = p.hertz ? p.hertz->b : std::nan("");
  o["hertz_p0"] = p.hertz ? p.hertz->p0 : std::nan("");
  std::vector<double> s, x_lead, p_peak;
  for (const contactgeom::KpStrip& strip : p.kp.strips) {
    // s in the contact plane relative to O, + towards the gauge side (KpPatch's frame).
    s.push_back(strip.s - p.kp.s_O);
    x_lead.push_back(strip.x_lead);
    p_peak.push_back(strip.p_peak);
  }
  py::dict strips;
  strips["s"] = array_of(s);
  strips["x_lead"] = array_of(x_lead);
  strips["p_peak"] = array_of(p_peak);
  o["strips"] = strips;
  return o;
}

py::dict contact_dict(const cli::SolvedContact& solved) {
  const contactgeom::WheelRailContact& c = solved.contact;
  py::dict out;
  out["status"] = std::string(contactgeom::status_name(c.status));
  out["message"] = c.message;
  out["vertical_force"] = c.vertical_force;
  out["lateral_force"] = c.lateral_force;
  out["approach"] = c.approach;
  out["warnings"] = solved.warnings;
  py::list patches;
  for (const auto& p : c.patches) patches.append(patch_dict(p));
  out["patches"] = patches;
  return out;
}

py::dict wear_dict(const cli::ModelWear& w, const profiles::Profile& wheel) {
  py::dict o;
  o["model"] = w.model;
  o["Fx"] = w.solution.forces.Fx;
  o["Fy"] = w.solution.forces.Fy;
  o["frictional_work"] = w.solution.frictional_work;
  o["worn_volume_per_metre"] = w.summary.volume_per_metre;
  o["peak_depth_per_metre"] = w.summary.peak_depth;
  o["peak_y_wheel"] = wheel.position(w.summary.peak_s)[0];
  const tangential::CellFields& f = *w.solution.fields;
  py::dict map;
  map["x"] = array_of(f.x);
  map["y"] = array_of(f.y);
  map["work"] = array_of(f.work);
  o["tgamma"] = map;
  std::vector<double> s, y, depth = w.distribution.depth;
  for (std::size_t b = 0; b < depth.size(); ++b) {
    s.push_back(w.distribution.s(b));
    y.push_back(wheel.position(s.back())[0]);
  }
  py::dict d;
  d["s_wheel"] = array_of(s);
  d["y_wheel"] = array_of(y);
  d["depth_per_metre"] = array_of(depth);
  o["depth"] = d;
  return o;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def(
      "contact",
      [](const py::dict& kw) {
        const cli::ContactInputs in = contact_inputs(kw);
        std::optional<cli::SolvedContact> solved;
        {
          py::gil_scoped_release release;
          solved = cli::solve_contact(in);
        }
        return contact_dict(*solved);
      },
      py::arg("inputs"));
  m.def(
      "wear",
      [](const py::dict& kw, const std::string& law_name, const std::string& model_name, int cells,
         int exact_grid, double exact_margin, bool exact_radius_variation) {
        const cli::ExactPatchOptions exact{exact_grid, exact_margin, exact_radius_variation};
        const cli::ContactInputs in = contact_inputs(kw);
        cli::check_wear_grid(in.motion.speed, cells);
        const wear::WearLaw law = cli::wear_law_named(law_name, "");
        // "exact": Kalker's exact theory on the gap (`wear --exact`), else a contact model.
        const bool exact_chain = model_name == "exact";
        std::optional<tangential::ContactModel> model;
        if (exact_chain) {
          cli::check_exact_patch_options(exact);
        } else {
          model = cli::contact_model_named(model_name);
        }
        std::optional<cli::SolvedContact> solved;
        std::vector<cli::ModelWear> wear;
        {
          py::gil_scoped_release release;
          solved = cli::solve_contact(in);
          // A contact that carries no load has no wear: its status says why (the command line
          // fails with it).
          if (contactgeom::carries_load(solved->contact.status))
            for (const auto& p : solved->contact.patches)
              wear.push_back(exact_chain
                                 ? cli::exact_wear(in, solved->pair, p, law, exact)
                                 : cli::model_wear(in, solved->pair, p, *model, law, cells, true));
        }
        py::dict out = contact_dict(*solved);
        py::list patches = out["patches"];
        for (std::size_t k = 0; k < patches.size(); ++k)
          patches[k]["wear"] = k < wear.size() ? py::object(wear_dict(wear[k], solved->pair.wheel))
                                               : py::object(py::none());
        return out;
      },
      py::arg("inputs"), py::arg("law"), py::arg("model"), py::arg("cells"), py::arg("exact_grid"),
      py::arg("exact_margin"), py::arg("exact_radius_variation"));
}

}  // namespace wheelwear::python
