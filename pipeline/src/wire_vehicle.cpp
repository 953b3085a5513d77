// The wire format of a vehicle solve's work: its running conditions and their solutions, its
// time-domain pieces and their outcomes (wire.hpp).

#include <algorithm>
#include <stdexcept>

#include "wire.hpp"

namespace wheelwear::pipeline::detail {

namespace {

void write(WireWriter& w, const vehicle::BodyPlacement& b) {
  w.f64(b.y);
  w.f64(b.yaw);
}

vehicle::BodyPlacement read_body(WireReader& r) {
  vehicle::BodyPlacement b;
  b.y = r.f64();
  b.yaw = r.f64();
  return b;
}

void write(WireWriter& w, const vehicle::WheelsetMotionState& m) {
  for (double v : {m.dy, m.yaw, m.spin, m.lateral_velocity, m.yaw_rate}) w.f64(v);
}

vehicle::WheelsetMotionState read_motion(WireReader& r) {
  vehicle::WheelsetMotionState m;
  for (double* v : {&m.dy, &m.yaw, &m.spin, &m.lateral_velocity, &m.yaw_rate}) *v = r.f64();
  return m;
}

void write(WireWriter& w, const vehicle::VehiclePlacement& p) {
  write(w, p.car_body);
  for (const vehicle::BodyPlacement& b : p.bogies) write(w, b);
  for (const vehicle::WheelsetMotionState& m : p.wheelsets) write(w, m);
}

vehicle::VehiclePlacement read_placement(WireReader& r) {
  vehicle::VehiclePlacement p;
  p.car_body = read_body(r);
  for (vehicle::BodyPlacement& b : p.bogies) b = read_body(r);
  for (vehicle::WheelsetMotionState& m : p.wheelsets) m = read_motion(r);
  return p;
}

// A wheel's contact: its status, message and forces, not its patches.
void write(WireWriter& w, const contactgeom::WheelRailContact& c) {
  w.u64(static_cast<std::uint64_t>(c.status));
  w.text(c.message);
  for (double v : {c.vertical_force, c.lateral_force, c.approach}) w.f64(v);
}

void read_into(WireReader& r, contactgeom::WheelRailContact& c) {
  c.status = static_cast<contactgeom::WheelRailStatus>(r.u64());
  c.message = r.text();
  for (double* v : {&c.vertical_force, &c.lateral_force, &c.approach}) *v = r.f64();
}

void write(WireWriter& w, const vehicle::WheelsetForces& f) {
  w.f64(f.contact.roll);
  write(w, f.contact.left);
  write(w, f.contact.right);
  for (const vehicle::WheelForces& wheel : f.wheels) {
    w.u64(static_cast<std::uint64_t>(wheel.status));
    for (double v :
         {wheel.Q, wheel.Y, wheel.Fx, wheel.Fy, wheel.N, wheel.contact_angle, wheel.torque})
      w.f64(v);
  }
  for (double v : {f.lateral, f.yaw_moment, f.Fx_axle, f.axle_torque}) w.f64(v);
  w.i64(f.load_iterations);
  w.flag(f.loads_met);
  w.flag(f.load_jump);
  w.f64(f.vertical_forces[0]);
  w.f64(f.vertical_forces[1]);
  w.flag(f.tabulated);
  w.text(f.message);
}

void read_into(WireReader& r, vehicle::WheelsetForces& f) {
  f.contact.roll = r.f64();
  read_into(r, f.contact.left);
  read_into(r, f.contact.right);
  for (vehicle::WheelForces& wheel : f.wheels) {
    wheel.status = static_cast<contactgeom::WheelRailStatus>(r.u64());
    for (double* v :
         {&wheel.Q, &wheel.Y, &wheel.Fx, &wheel.Fy, &wheel.N, &wheel.contact_angle, &wheel.torque})
      *v = r.f64();
  }
  for (double* v : {&f.lateral, &f.yaw_moment, &f.Fx_axle, &f.axle_torque}) *v = r.f64();
  f.load_iterations = static_cast<int>(r.i64());
  f.loads_met = r.flag();
  f.load_jump = r.flag();
  f.vertical_forces[0] = r.f64();
  f.vertical_forces[1] = r.f64();
  f.tabulated = r.flag();
  f.message = r.text();
}

}  // namespace

void write(WireWriter& w, const std::vector<CaseTask>& tasks) {
  w.u64(tasks.size());
  for (const CaseTask& t : tasks) {
    w.u64(t.index);
    w.flag(t.start.has_value());
    if (t.start) write(w, *t.start);
  }
}

std::vector<CaseTask> read_case_tasks(WireReader& r) {
  std::vector<CaseTask> tasks(r.count(16));
  for (CaseTask& t : tasks) {
    t.index = r.u64();
    if (r.flag()) t.start = read_placement(r);
  }
  return tasks;
}

void write(WireWriter& w, const std::vector<vehicle::VehicleCurving>& curvings) {
  w.u64(curvings.size());
  for (const vehicle::VehicleCurving& c : curvings) {
    w.flag(c.converged);
    w.i64(c.iterations);
    w.i64(c.continuation_steps);
    w.flag(c.from_start);
    w.flag(c.finished_directly);
    w.i64(c.wheelset_evaluations);
    w.text(c.message);
    w.f64(c.cant_deficiency);
    write(w, c.car_body);
    for (const vehicle::BodyPlacement& b : c.bogies) write(w, b);
    for (const vehicle::BodyBalance& b : c.body_balances) {
      w.f64(b.lateral);
      w.f64(b.yaw_moment);
    }
    for (const vehicle::CurvingWheelset& ws : c.wheelsets) {
      w.f64(ws.x);
      write(w, ws.state);
      w.f64(ws.load_left);
      w.f64(ws.load_right);
      write(w, ws.forces);
      w.f64(ws.balance.lateral);
      w.f64(ws.balance.yaw_moment);
      w.f64(ws.suspension_lateral);
      w.f64(ws.suspension_yaw);
    }
  }
}

std::vector<vehicle::VehicleCurving> read_curvings(WireReader& r) {
  std::vector<vehicle::VehicleCurving> curvings(r.count(8));
  for (vehicle::VehicleCurving& c : curvings) {
    c.converged = r.flag();
    c.iterations = static_cast<int>(r.i64());
    c.continuation_steps = static_cast<int>(r.i64());
    c.from_start = r.flag();
    c.finished_directly = r.flag();
    c.wheelset_evaluations = static_cast<int>(r.i64());
    c.message = r.text();
    c.cant_deficiency = r.f64();
    c.car_body = read_body(r);
    for (vehicle::BodyPlacement& b : c.bogies) b = read_body(r);
    for (vehicle::BodyBalance& b : c.body_balances) {
      b.lateral = r.f64();
      b.yaw_moment = r.f64();
    }
    for (vehicle::CurvingWheelset& ws : c.wheelsets) {
      ws.x = r.f64();
      ws.state = read_motion(r);
      ws.load_left = r.f64();
      ws.load_right = r.f64();
      read_into(r, ws.forces);
      ws.balance.lateral = r.f64();
      ws.balance.yaw_moment = r.f64();
      ws.suspension_lateral = r.f64();
      ws.suspension_yaw = r.f64();
    }
  }
  return curvings;
}

void write(WireWriter& w, const std::vector<PieceTask>& tasks) {
  w.u64(tasks.size());
  for (const PieceTask& t : tasks) {
    w.u64(t.piece);
    write(w, t.start);
    write(w, std::vector<WheelsetStateSpec>(t.start_states.begin(), t.start_states.end()));
  }
}

std::vector<PieceTask> read_piece_tasks(WireReader& r) {
  std::vector<PieceTask> tasks(r.count(8));
  for (PieceTask& t : tasks) {
    t.piece = r.u64();
    t.start = read_placement(r);
    const std::vector<WheelsetStateSpec> states = read_specs(r);
    if (states.size() != t.start_states.size())
      throw std::runtime_error("a piece's message holds " + std::to_string(states.size()) +
                               " start states");
    std::copy(states.begin(), states.end(), t.start_states.begin());
  }
  return tasks;
}

void write(WireWriter& w, const std::vector<PieceOutcome>& outcomes) {
  w.u64(outcomes.size());
  for (const PieceOutcome& o : outcomes) {
    const PieceRun& run = o.run;
    w.flag(run.completed);
    w.text(run.message);
    w.f64(run.time_step);
    w.i64(run.steps);
    for (std::size_t k = 0; k < run.samples.size(); ++k) {
      w.i64(run.samples[k]);
      w.i64(run.load_jumps[k]);
      for (double v : {run.dy_rms[k], run.dy_max[k], run.yaw_rms[k], run.y_over_q[k]}) w.f64(v);
    }
    write(w, o.states);
  }
}

std::vector<PieceOutcome> read_piece_outcomes(WireReader& r) {
  std::vector<PieceOutcome> outcomes(r.count(8));
  for (PieceOutcome& o : outcomes) {
    PieceRun& run = o.run;
    run.completed = r.flag();
    run.message = r.text();
    run.time_step = r.f64();
    run.steps = static_cast<long>(r.i64());
    for (std::size_t k = 0; k < run.samples.size(); ++k) {
      run.samples[k] = static_cast<int>(r.i64());
      run.load_jumps[k] = static_cast<int>(r.i64());
      for (double* v : {&run.dy_rms[k], &run.dy_max[k], &run.yaw_rms[k], &run.y_over_q[k]})
        *v = r.f64();
    }
    o.states = read_specs(r);
  }
  return outcomes;
}

}  // namespace wheelwear::pipeline::detail
