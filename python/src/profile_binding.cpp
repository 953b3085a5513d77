// Profiles: the standard ones generated, measured files read and cleaned as the command line
// reads them, the fitted curve as arrays, and EN 15313's Sh, Sd, qR.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "choices.hpp"
#include "profile_file_kwargs.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::python {

namespace {

using profiles::Profile;

py::array_t<double> points_array(const profiles::PointList& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto v = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    v(static_cast<py::ssize_t>(i), 0) = points[i][0];
    v(static_cast<py::ssize_t>(i), 1) = points[i][1];
  }
  return out;
}

}  // namespace

void bind_profiles(py::module_& m) {
  py::class_<Profile>(m, "Profile",
                      "A wheel or rail profile: a C2 curve in the profile's own frame (y lateral, "
                      "+ towards the field side; z vertical, + downwards; metres), parametrised by "
                      "its arc length s from the flange/gauge side.")
      .def_property_readonly("name", [](const Profile& p) { return p.info().name; })
      .def_property_readonly(
          "body",
          [](const Profile& p) { return p.body() == profiles::Body::wheel ? "wheel" : "rail"; })
      .def_property_readonly(
          "nominal_radius", [](const Profile& p) { return p.info().nominal_radius; },
          "wheels: rolling radius at the taping line [m]; 0 for rails")
      .def_property_readonly("length", &Profile::length, "arc length of the curve [m]")
      .def_property_readonly(
          "y_range", [](const Profile& p) { return std::pair(p.y_min(), p.y_max()); },
          "lateral extent (y_min, y_max) [m]")
      .def(
          "sample",
          [](const Profile& p, double spacing) {
            if (!(spacing > 0.0))
              throw InputError("spacing = " + core::format_number(spacing) +
                               " m: give a positive spacing along the curve, e.g. 0.5e-3");
            return points_array(p.resample(spacing));
          },
          py::arg("spacing") = 0.5e-3,
          "Points (y, z) [m] every `spacing` metres of arc length, as an (n, 2) array.")
      .def(
          "knots", [](const Profile& p) { return points_array(p.knot_points()); },
          "The cleaned measured (or generated) points the curve passes through, (n, 2) [m].")
      .def(
          "position",
          [](const Profile& p, py::array_t<double> s) {
            return py::vectorize([&p](double t) { return p.position(t)[0]; })(s);
          },
          py::arg("s"), "Lateral position y [m] at arc length s [m] (array or float).")
      .def(
          "height",
          [](const Profile& p, py::array_t<double> s) {
            return py::vectorize([&p](double t) { return p.position(t)[1]; })(s);
          },
          py::arg("s"), "Vertical position z [m] (+ down) at arc length s [m].")
      .def(
          "curvature",
          [](const Profile& p, py::array_t<double> s) {
            return py::vectorize([&p](double t) { return p.curvature(t); })(s);
          },
          py::arg("s"), "Signed curvature [1/m] at arc length s [m] (> 0 convex towards the mate).")
      .def(
          "parameters",
          [](const Profile& p) {
            const profiles::WheelParameters w = profiles::wheel_parameters(p);
            py::dict out;
            out["Sh"] = w.Sh;
            out["Sd"] = w.Sd;
            out["qR"] = w.qR;
            return out;
          },
          "Wheels: EN 15313's flange height Sh, flange thickness Sd and qR [m], as a dict.")
      .def("__repr__", [](const Profile& p) {
        return "<wheelwear.Profile " + p.info().name + " (" +
               (p.body() == profiles::Body::wheel ? "wheel" : "rail") + ")>";
      });

  m.def(
      "wheel_profile",
      [](const std::string& spec, std::optional<double> radius, std::optional<std::string> origin,
         std::optional<double> taping_line_distance, std::optional<double> max_drop,
         std::optional<double> smoothing) {
        const cli::ProfileFileArgs files =
            profile_file_args({origin, taping_line_distance, max_drop, std::nullopt, smoothing},
                              spec != "S1002", false);
        std::vector<std::string> warnings;
        Profile p = profiles::wheel_profile(spec, radius, files.options(), &warnings);
        return std::pair(std::move(p), warnings);
      },
      py::arg("spec"), py::arg("radius"), py::arg("origin"), py::arg("taping_line_distance"),
      py::arg("max_drop"), py::arg("smoothing"));
  m.def(
      "rail_profile",
      [](const std::string& spec, std::optional<std::string> inclination,
         std::optional<std::string> gauge_side, std::optional<double> max_drop,
         std::optional<double> smoothing) {
        const cli::ProfileFileArgs files =
            profile_file_args({std::nullopt, std::nullopt, max_drop, gauge_side, smoothing}, false,
                              spec != "60E1" && spec != "UIC60");
        const std::optional<double> incl =
            inclination ? std::optional(core::parse_inclination(*inclination, "--incl"))
                        : std::nullopt;
        std::vector<std::string> warnings;
        Profile p = profiles::rail_profile(spec, incl, files.options(), &warnings);
        return std::pair(std::move(p), warnings);
      },
      py::arg("spec"), py::arg("inclination"), py::arg("gauge_side"), py::arg("max_drop"),
      py::arg("smoothing"));
}

}  // namespace wheelwear::python
