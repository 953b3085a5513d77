#include "vehicle_record.hpp"

#include <sstream>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline::detail {

namespace {

// Per case, one value of each wheelset (shape [cases, 4]).
template <class Value>
std::vector<double> per_wheelset(const VehicleCollective& v, Value value) {
  std::vector<double> out;
  for (const vehicle::VehicleCurving& c : v.curving)
    for (const vehicle::CurvingWheelset& w : c.wheelsets) out.push_back(value(w));
  return out;
}

// Per case, one value of each wheel of each wheelset (shape [cases, 4, 2]: left, right).
template <class Value>
std::vector<double> per_wheel(const VehicleCollective& v, Value value) {
  std::vector<double> out;
  for (const vehicle::VehicleCurving& c : v.curving)
    for (const vehicle::CurvingWheelset& w : c.wheelsets)
      for (const vehicle::WheelForces& wheel : w.forces.wheels) out.push_back(value(wheel));
  return out;
}

template <class Value>
std::vector<double> per_case(const VehicleCollective& v, Value value) {
  std::vector<double> out;
  for (std::size_t i = 0; i < v.cases.size(); ++i) out.push_back(value(v.cases[i], v.curving[i]));
  return out;
}

ArrayRecord shaped(std::string name, std::vector<double> values, std::vector<std::size_t> shape,
                   std::string units, std::string description) {
  ArrayRecord a =
      vector(std::move(name), std::move(values), std::move(units), std::move(description));
  a.shape = std::move(shape);
  return a;
}

}  // namespace

void add_vehicle_record(GroupRecord& g, const VehicleCollective& vehicle, bool solved,
                        double depth_since_solve) {
  g.arrays.push_back(scalar("vehicle/solved", solved ? 1.0 : 0.0, "1",
                            "1 when the vehicle was solved on this step's profiles"));
  g.arrays.back().integer = true;
  g.arrays.push_back(scalar("vehicle/unconverged_cases", static_cast<double>(vehicle.unconverged),
                            "1",
                            "running conditions whose quasi-static solve did not converge "
                            "(their last iterate is used)"));
  g.arrays.back().integer = true;
  g.arrays.push_back(scalar("vehicle/kept_cases", static_cast<double>(vehicle.kept), "1",
                            "running conditions whose solve on this solve's profiles did not "
                            "converge from their last converged solution, which they keep"));
  g.arrays.back().integer = true;
  g.arrays.push_back(scalar("vehicle/depth_since_solve", depth_since_solve, "m",
                            "deepest wear since the vehicle's last solve, this step's "
                            "included (an upper bound: the steps' deepest increments summed)"));
  if (!vehicle.pieces.empty())
    g.arrays.push_back(as_integer(
        scalar("vehicle/incomplete_pieces", static_cast<double>(vehicle.incomplete()), "1",
               "time-domain pieces whose simulation stopped early (the "
               "vehicle left the rails); their samples up to there keep their weight, and "
               "the start state stands for the rest")));
  g.arrays.push_back(scalar("vehicle/critical_speed", vehicle.critical_speed, "m/s",
                            "linear critical speed on tangent track on the profiles of the "
                            "vehicle's last solve; NaN: not computed or not found "
                            "(vehicle/critical_speed_note)"));
  g.texts.push_back({"vehicle/critical_speed_note", vehicle.critical_speed_note,
                     "how the critical speed was found, or why not"});
  add_collective(g, "collective/", vehicle.states);
  add_vehicle_cases(g, vehicle);
  add_vehicle_pieces(g, vehicle);
}

void add_vehicle_cases(GroupRecord& g, const VehicleCollective& v) {
  const std::size_t n = v.cases.size();
  const std::string p = "vehicle/cases/";
  std::string labels;
  for (const RouteCase& c : v.cases) labels += c.label + '\n';
  g.texts.push_back({p + "label", labels, "running condition: the route section it stands for"});
  using C = RouteCase;
  using V = vehicle::VehicleCurving;
  g.arrays.push_back(
      vector(p + "curve_radius_m",
             per_case(v, [](const C& c, const V&) { return c.curve.running.curve_radius; }), "m",
             "0 tangent, + right-hand"));
  g.arrays.push_back(vector(p + "cant_m",
                            per_case(v, [](const C& c, const V&) { return c.curve.cant; }), "m",
                            "outer rail above the inner"));
  g.arrays.push_back(vector(p + "speed_m_s",
                            per_case(v, [](const C& c, const V&) { return c.curve.running.speed; }),
                            "m/s", "running speed"));
  g.arrays.push_back(vector(
      p + "friction", per_case(v, [](const C& c, const V&) { return c.curve.running.friction; }),
      "1", "friction on the rail top"));
  g.arrays.push_back(vector(
      p + "friction_flange",
      per_case(v, [](const C& c, const V&) { return c.curve.running.rail_friction().flange; }), "1",
      "friction on the gauge face"));
  g.arrays.push_back(vector(p + "share", per_case(v, [](const C& c, const V&) { return c.share; }),
                            "1", "share of the route's length"));
  g.arrays.push_back(vector(
      p + "reversed", per_case(v, [](const C& c, const V&) { return c.reversed ? 1.0 : 0.0; }), "1",
      "1: met running the route backwards (radius and wheelsets as seen "
      "in travel)"));
  g.arrays.back().integer = true;
  g.arrays.push_back(vector(p + "cant_deficiency_m",
                            per_case(v, [](const C&, const V& c) { return c.cant_deficiency; }),
                            "m", "cant deficiency (EN 13803's approximation)"));
  g.arrays.push_back(vector(
      p + "converged", per_case(v, [](const C&, const V& c) { return c.converged ? 1.0 : 0.0; }),
      "1", "1 when the quasi-static solve converged (else its last iterate)"));
  g.arrays.back().integer = true;
  g.arrays.push_back(
      vector(p + "iterations",
             per_case(v, [](const C&, const V& c) { return static_cast<double>(c.iterations); }),
             "1", "Newton iterations of the solve"));
  g.arrays.back().integer = true;
  g.arrays.push_back(vector(p + "car_body_y",
                            per_case(v, [](const C&, const V& c) { return c.car_body.y; }), "m",
                            "car body's lateral shift, + left"));
  g.arrays.push_back(vector(p + "car_body_yaw",
                            per_case(v, [](const C&, const V& c) { return c.car_body.yaw; }), "rad",
                            "car body's yaw relative to the track"));
  std::vector<double> bogie_y, bogie_yaw;
  for (const V& c : v.curving)
    for (const vehicle::BodyPlacement& b : c.bogies) {
      bogie_y.push_back(b.y);
      bogie_yaw.push_back(b.yaw);
    }
  g.arrays.push_back(shaped(p + "bogie_y", bogie_y, {n, vehicle::kBogies}, "m",
                            "bogies' lateral shift [case, bogie], + left"));
  g.arrays.push_back(shaped(p + "bogie_yaw", bogie_yaw, {n, vehicle::kBogies}, "rad",
                            "bogies' yaw relative to the track [case, bogie]"));
  using W = vehicle::CurvingWheelset;
  const std::vector<std::size_t> ws{n, vehicle::kWheelsets};
  g.arrays.push_back(shaped(p + "dy", per_wheelset(v, [](const W& w) { return w.state.dy; }), ws,
                            "m", "wheelset shift [case, wheelset in order of travel], + left"));
  g.arrays.push_back(shaped(p + "angle_of_attack",
                            per_wheelset(v, [](const W& w) { return w.state.yaw; }), ws, "rad",
                            "wheelset yaw relative to the radial direction [case, wheelset]"));
  g.arrays.push_back(shaped(p + "spin", per_wheelset(v, [](const W& w) { return w.state.spin; }),
                            ws, "rad/s", "axle angular velocity, free rolling [case, wheelset]"));
  g.arrays.push_back(shaped(p + "sum_Y",
                            per_wheelset(v, [](const W& w) { return w.forces.lateral; }), ws, "N",
                            "sum of the rails' lateral forces on the wheelset, + left "
                            "[case, wheelset]"));
  g.arrays.push_back(shaped(p + "Fx_axle",
                            per_wheelset(v, [](const W& w) { return w.forces.Fx_axle; }), ws, "N",
                            "longitudinal creep force of the axle, + forward [case, wheelset]"));
  // What a case's states carry beyond the placement (motion_state): a resumed run that keeps a
  // case's solution makes its states from these.
  g.arrays.push_back(shaped(p + "roll",
                            per_wheelset(v, [](const W& w) { return w.forces.contact.roll; }), ws,
                            "rad", "wheelset roll, + left wheel down [case, wheelset]"));
  std::vector<double> vertical;
  for (const vehicle::VehicleCurving& c : v.curving)
    for (const vehicle::CurvingWheelset& w : c.wheelsets)
      for (const contactgeom::WheelRailContact* wheel :
           {&w.forces.contact.left, &w.forces.contact.right})
        vertical.push_back(wheel->vertical_force);
  const std::vector<std::size_t> wheels{n, vehicle::kWheelsets, 2};
  g.arrays.push_back(shaped(p + "vertical_force", std::move(vertical), wheels, "N",
                            "vertical force the wheel's contact was solved for (Q less the creep "
                            "forces' vertical part) [case, wheelset, left|right]"));
  using F = vehicle::WheelForces;
  g.arrays.push_back(shaped(p + "Q", per_wheel(v, [](const F& w) { return w.Q; }), wheels, "N",
                            "wheel load, normal to the track plane [case, wheelset, left|right]"));
  g.arrays.push_back(shaped(p + "Y", per_wheel(v, [](const F& w) { return w.Y; }), wheels, "N",
                            "lateral force of the rail on the wheel, + towards the track centre "
                            "[case, wheelset, left|right]"));
  g.arrays.push_back(shaped(p + "contact_angle",
                            per_wheel(v, [](const F& w) { return w.contact_angle; }), wheels, "rad",
                            "contact angle of the most loaded patch [case, wheelset, left|right]"));
}

namespace {

// Per piece, one value of each wheelset (shape [pieces, 4]).
template <class Value>
std::vector<double> per_piece_wheelset(const VehicleCollective& v, Value value) {
  std::vector<double> out;
  for (const PieceRun& r : v.piece_runs)
    for (std::size_t k = 0; k < vehicle::kWheelsets; ++k) out.push_back(value(r, k));
  return out;
}

// A message as one line of a text dataset.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

void add_vehicle_pieces(GroupRecord& g, const VehicleCollective& v) {
  if (v.pieces.empty()) return;
  const std::size_t n = v.pieces.size();
  const std::string p = "vehicle/pieces/";
  std::string labels, messages;
  for (std::size_t i = 0; i < n; ++i) {
    labels += v.pieces[i].label + '\n';
    messages += one_line(v.piece_runs[i].message) + '\n';
  }
  g.texts.push_back({p + "label", labels, "the route section each piece belongs to"});
  g.texts.push_back(
      {p + "message", messages, "why a piece's simulation stopped early, else empty"});
  const auto per_piece = [&](const std::string& name, auto value, const std::string& units,
                             const std::string& description, bool integer = false) {
    std::vector<double> values;
    for (std::size_t i = 0; i < n; ++i) values.push_back(value(v.pieces[i], v.piece_runs[i]));
    g.arrays.push_back(vector(p + name, std::move(values), units, description));
    g.arrays.back().integer = integer;
  };
  using D = DynamicPiece;
  per_piece(
      "section", [](const D& d, const PieceRun&) { return static_cast<double>(d.section) + 1.0; },
      "1", "the route section (1-based)", true);
  per_piece(
      "tangent", [](const D& d, const PieceRun&) { return d.tangent ? 1.0 : 0.0; }, "1",
      "1 for a tangent's stretch, 0 for a whole transition", true);
  per_piece(
      "reversed", [](const D& d, const PieceRun&) { return d.reversed ? 1.0 : 0.0; }, "1",
      "1: run backwards (section and distances along the reversed route)", true);
  per_piece(
      "start_m", [](const D& d, const PieceRun&) { return d.start_m; }, "m",
      "where the simulated stretch starts along the route");
  per_piece(
      "length_m", [](const D& d, const PieceRun&) { return d.length_m; }, "m",
      "length of the stretch");
  per_piece(
      "share", [](const D& d, const PieceRun&) { return d.share; }, "1",
      "share of the route's length its samples stand for");
  per_piece(
      "speed_m_s", [](const D& d, const PieceRun&) { return d.speed; }, "m/s", "running speed");
  per_piece(
      "completed", [](const D&, const PieceRun& r) { return r.completed ? 1.0 : 0.0; }, "1",
      "1 when the simulation ran through the whole stretch", true);
  per_piece(
      "time_step", [](const D&, const PieceRun& r) { return r.time_step; }, "s",
      "integration step");
  per_piece(
      "steps", [](const D&, const PieceRun& r) { return static_cast<double>(r.steps); }, "1",
      "integration steps", true);
  const std::vector<std::size_t> ws{n, vehicle::kWheelsets};
  using R = PieceRun;
  g.arrays.push_back(
      shaped(p + "samples",
             per_piece_wheelset(v, [](const R& r, std::size_t k) { return 1.0 * r.samples[k]; }),
             ws, "1", "states sampled in the stretch [piece, wheelset in order of travel]"));
  g.arrays.back().integer = true;
  g.arrays.push_back(shaped(
      p + "dy_rms", per_piece_wheelset(v, [](const R& r, std::size_t k) { return r.dy_rms[k]; }),
      ws, "m", "root mean square of the wheelset's shift [piece, wheelset]"));
  g.arrays.push_back(shaped(
      p + "dy_max", per_piece_wheelset(v, [](const R& r, std::size_t k) { return r.dy_max[k]; }),
      ws, "m", "largest |shift| of the wheelset [piece, wheelset]"));
  g.arrays.push_back(
      shaped(p + "angle_of_attack_rms",
             per_piece_wheelset(v, [](const R& r, std::size_t k) { return r.yaw_rms[k]; }), ws,
             "rad", "root mean square of the wheelset's angle of attack [piece, wheelset]"));
  g.arrays.push_back(
      shaped(p + "Y_over_Q_max",
             per_piece_wheelset(v, [](const R& r, std::size_t k) { return r.y_over_q[k]; }), ws,
             "1", "largest Y/Q of the wheelset's two wheels [piece, wheelset]"));
  g.arrays.push_back(
      shaped(p + "load_jump_samples",
             per_piece_wheelset(v, [](const R& r, std::size_t k) { return 1.0 * r.load_jumps[k]; }),
             ws, "1",
             "samples whose contact kept a side of a jump of Q across the wheel's load [piece, "
             "wheelset]"));
  g.arrays.back().integer = true;
}

std::vector<PieceRun> read_vehicle_pieces(const ResultsFile& file, int step, std::size_t pieces) {
  if (pieces == 0) return {};
  const std::string p = "vehicle/pieces/";
  const std::size_t w = vehicle::kWheelsets;
  auto read = [&](const std::string& name, std::size_t per_piece) {
    std::vector<double> values = file.read_step_array(step, p + name);
    if (values.size() != pieces * per_piece)
      throw InputError("results file " + file.path().string() + ", step " + std::to_string(step) +
                       ": " + p + name + " has " + std::to_string(values.size()) + " values, " +
                       std::to_string(pieces * per_piece) +
                       " expected; the scene's route or [time_domain] has changed, or the file "
                       "is damaged: start a new run with -o");
    return values;
  };
  const auto completed = read("completed", 1);
  const auto time_step = read("time_step", 1);
  const auto steps = read("steps", 1);
  const auto samples = read("samples", w);
  const auto dy_rms = read("dy_rms", w);
  const auto dy_max = read("dy_max", w);
  const auto yaw_rms = read("angle_of_attack_rms", w);
  const auto y_over_q = read("Y_over_Q_max", w);
  // Files of earlier version-5 programs have no count of samples at a jump: none counted.
  const bool jumps_recorded =
      file.has(ResultsFile::step_group(step) + "/" + p + "load_jump_samples");
  const auto load_jumps =
      jumps_recorded ? read("load_jump_samples", w) : std::vector<double>(pieces * w, 0.0);
  std::vector<std::string> messages;
  std::istringstream text(
      file.read_text(ResultsFile::step_group(step) + "/" + p + "message").value_or(""));
  for (std::string line; std::getline(text, line);) messages.push_back(line);
  messages.resize(pieces);
  std::vector<PieceRun> out(pieces);
  for (std::size_t i = 0; i < pieces; ++i) {
    PieceRun& r = out[i];
    r.completed = completed[i] != 0.0;
    r.message = messages[i];
    r.time_step = time_step[i];
    r.steps = static_cast<long>(steps[i]);
    for (std::size_t k = 0; k < w; ++k) {
      r.samples[k] = static_cast<int>(samples[i * w + k]);
      r.dy_rms[k] = dy_rms[i * w + k];
      r.dy_max[k] = dy_max[i * w + k];
      r.yaw_rms[k] = yaw_rms[i * w + k];
      r.y_over_q[k] = y_over_q[i * w + k];
      r.load_jumps[k] = static_cast<int>(load_jumps[i * w + k]);
    }
  }
  return out;
}

namespace {

std::vector<std::optional<vehicle::VehiclePlacement>> read_vehicle_starts(const ResultsFile& file,
                                                                          int step) {
  const std::string p = "vehicle/cases/";
  const auto body_y = file.read_step_array(step, p + "car_body_y");
  const auto body_yaw = file.read_step_array(step, p + "car_body_yaw");
  const auto bogie_y = file.read_step_array(step, p + "bogie_y");
  const auto bogie_yaw = file.read_step_array(step, p + "bogie_yaw");
  const auto dy = file.read_step_array(step, p + "dy");
  const auto yaw = file.read_step_array(step, p + "angle_of_attack");
  const auto spin = file.read_step_array(step, p + "spin");
  const std::size_t n = body_y.size();
  const std::size_t b = vehicle::kBogies, w = vehicle::kWheelsets;
  if (body_yaw.size() != n || bogie_y.size() != n * b || bogie_yaw.size() != n * b ||
      dy.size() != n * w || yaw.size() != n * w || spin.size() != n * w)
    throw InputError("results file " + file.path().string() + ", step " + std::to_string(step) +
                     ": the vehicle's case arrays do not match; the file is damaged");
  std::vector<std::optional<vehicle::VehiclePlacement>> starts(n);
  for (std::size_t i = 0; i < n; ++i) {
    vehicle::VehiclePlacement& s = starts[i].emplace();
    s.car_body = {body_y[i], body_yaw[i]};
    for (std::size_t k = 0; k < b; ++k) s.bogies[k] = {bogie_y[i * b + k], bogie_yaw[i * b + k]};
    for (std::size_t k = 0; k < w; ++k) {
      s.wheelsets[k].dy = dy[i * w + k];
      s.wheelsets[k].yaw = yaw[i * w + k];
      s.wheelsets[k].spin = spin[i * w + k];
    }
  }
  return starts;
}

}  // namespace

std::vector<vehicle::VehicleCurving> read_vehicle_cases(const ResultsFile& file, int step,
                                                        std::size_t cases) {
  const std::string p = "vehicle/cases/";
  const auto starts = read_vehicle_starts(file, step);
  const std::size_t w = vehicle::kWheelsets;
  auto read = [&](const std::string& name, std::size_t per_case) {
    std::vector<double> values = file.read_step_array(step, p + name);
    if (values.size() != cases * per_case)
      throw InputError("results file " + file.path().string() + ", step " + std::to_string(step) +
                       ": " + p + name + " has " + std::to_string(values.size()) + " values, " +
                       std::to_string(cases * per_case) + " expected; the file is damaged");
    return values;
  };
  if (starts.size() != cases)
    throw InputError("results file " + file.path().string() + ", step " + std::to_string(step) +
                     " holds " + std::to_string(starts.size()) +
                     " running conditions, the scene's route has " + std::to_string(cases) +
                     "; its route file has changed: start a new run with -o");
  const auto deficiency = read("cant_deficiency_m", 1);
  const auto converged = read("converged", 1);
  const auto iterations = read("iterations", 1);
  const auto sum_Y = read("sum_Y", w);
  const auto Fx_axle = read("Fx_axle", w);
  const auto Q = read("Q", 2 * w);
  const auto Y = read("Y", 2 * w);
  const auto angle = read("contact_angle", 2 * w);
  // Files of earlier programs hold neither: the loads, and no roll, stand in.
  const bool solved_for = file.has(ResultsFile::step_group(step) + "/" + p + "vertical_force");
  const auto vertical = solved_for ? read("vertical_force", 2 * w) : Q;
  const auto roll = solved_for ? read("roll", w) : std::vector<double>(cases * w, 0.0);
  std::vector<vehicle::VehicleCurving> out(cases);
  for (std::size_t i = 0; i < cases; ++i) {
    vehicle::VehicleCurving& c = out[i];
    c.cant_deficiency = deficiency[i];
    c.converged = converged[i] != 0.0;
    c.iterations = static_cast<int>(iterations[i]);
    c.car_body = starts[i]->car_body;
    c.bogies = starts[i]->bogies;
    for (std::size_t k = 0; k < w; ++k) {
      vehicle::CurvingWheelset& ws = c.wheelsets[k];
      ws.state = starts[i]->wheelsets[k];
      ws.forces.lateral = sum_Y[i * w + k];
      ws.forces.Fx_axle = Fx_axle[i * w + k];
      ws.forces.contact.roll = roll[i * w + k];
      for (std::size_t side = 0; side < 2; ++side) {
        const std::size_t at = (i * w + k) * 2 + side;
        ws.forces.wheels[side].Q = Q[at];
        ws.forces.wheels[side].Y = Y[at];
        ws.forces.wheels[side].contact_angle = angle[at];
        (side == 0 ? ws.forces.contact.left : ws.forces.contact.right).vertical_force =
            vertical[at];
      }
    }
  }
  return out;
}

VehicleCollective read_vehicle_collective(const ResultsFile& file, int step,
                                          const VehicleRun& run) {
  VehicleCollective v;
  RoutePlan plan = route_plan(run);
  v.cases = std::move(plan.cases);
  v.pieces = std::move(plan.pieces);
  v.piece_runs = read_vehicle_pieces(file, step, v.pieces.size());
  v.states = read_collective(file, step, "collective/");
  // The cases' solved states as recorded: the records of the steps until the next solve, and
  // where that solve starts.
  v.curving = read_vehicle_cases(file, step, v.cases.size());
  v.unconverged = static_cast<int>(file.read_step_array(step, "vehicle/unconverged_cases").at(0));
  v.kept = static_cast<int>(file.read_step_array(step, "vehicle/kept_cases").at(0));
  v.critical_speed = file.read_step_array(step, "vehicle/critical_speed").at(0);
  v.critical_speed_note =
      file.read_text(ResultsFile::step_group(step) + "/vehicle/critical_speed_note").value_or("");
  return v;
}

}  // namespace wheelwear::pipeline::detail
