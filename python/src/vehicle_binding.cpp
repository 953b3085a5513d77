// curving(): the quasi-static curving of `wheelwear curving`, as nested dicts of the same names.

#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "curving_request.hpp"

namespace wheelwear::python {

namespace {

py::dict wheel_dict(const vehicle::WheelForces& w, const char* side) {
  py::dict o;
  o["side"] = side;
  o["Q"] = w.Q;
  o["Y"] = w.Y;
  o["contact_angle"] = w.contact_angle;
  o["Fx"] = w.Fx;
  o["Fy"] = w.Fy;
  o["N"] = w.N;
  o["status"] = std::string(contactgeom::status_name(w.status));
  o["patches"] = static_cast<int>(w.patches.size());
  return o;
}

std::string wheelset_status(const vehicle::WheelsetForces& f) {
  for (const vehicle::WheelForces& w : f.wheels)
    if (w.status != contactgeom::WheelRailStatus::ok) return contactgeom::status_name(w.status);
  return "ok";
}

py::dict curving_dict(const cli::CurvingAnswer& answer) {
  const vehicle::VehicleCurving& c = answer.curving;
  py::list wheelsets;
  for (const vehicle::CurvingWheelset& w : c.wheelsets) {
    py::dict o;
    o["x"] = w.x;
    o["dy"] = w.state.dy;
    o["angle_of_attack"] = w.state.yaw;
    o["spin"] = w.state.spin;
    o["roll"] = w.forces.contact.roll;
    o["Fx_axle"] = w.forces.Fx_axle;
    o["axle_torque"] = w.forces.axle_torque;
    o["sum_Y"] = w.forces.lateral;  // Y_right - Y_left, as the results file
    o["status"] = wheelset_status(w.forces);
    py::list wheels;
    wheels.append(wheel_dict(w.forces.wheels[0], "left"));
    wheels.append(wheel_dict(w.forces.wheels[1], "right"));
    o["wheels"] = wheels;
    wheelsets.append(o);
  }
  py::dict body;
  body["y"] = c.car_body.y;
  body["yaw"] = c.car_body.yaw;
  py::list bogies;
  for (const vehicle::BodyPlacement& b : c.bogies) {
    py::dict d;
    d["y"] = b.y;
    d["yaw"] = b.yaw;
    bogies.append(d);
  }
  py::dict out;
  out["converged"] = c.converged;
  out["message"] = c.message;
  out["cant_deficiency"] = c.cant_deficiency;
  out["iterations"] = c.iterations;
  out["wheelset_evaluations"] = c.wheelset_evaluations;
  out["finished_directly"] = c.finished_directly;
  out["car_body"] = body;
  out["bogies"] = bogies;
  out["wheelsets"] = wheelsets;
  out["warnings"] = answer.warnings;
  if (answer.table) {
    py::dict t;
    t["shifts"] = answer.table->shifts;
    t["load_levels"] = answer.table->load_levels;
    t["contact_solves"] = answer.table->contact_solves;
    t["build_seconds"] = answer.table->seconds;
    out["contact_table"] = t;
  }
  return out;
}

}  // namespace

void bind_vehicle(py::module_& m) {
  m.def(
      "curving",
      [](const std::string& scene, const std::string& vehicle, double radius, double cant,
         double speed, std::optional<double> friction, double traction, bool contact_table,
         std::optional<int> threads) {
        cli::CurvingRequest request{scene, vehicle,  radius,   cant,
                                    speed, friction, traction, contact_table};
        std::optional<cli::CurvingAnswer> answer;
        run_on_threads(threads, [&] { answer = cli::solve_curving(request); });
        return curving_dict(*answer);
      },
      py::arg("scene"), py::arg("vehicle"), py::arg("radius"), py::arg("cant"), py::arg("speed"),
      py::arg("friction"), py::arg("traction"), py::arg("contact_table"), py::arg("threads"));
}

}  // namespace wheelwear::python
