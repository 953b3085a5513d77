#include "wire.hpp"

#include <bit>
#include <stdexcept>

namespace wheelwear::pipeline::detail {

void WireWriter::u64(std::uint64_t v) {
  for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<char>((v >> (8 * i)) & 0xffU));
}

void WireWriter::f64(double v) {
  u64(std::bit_cast<std::uint64_t>(v));
}

void WireWriter::text(const std::string& v) {
  u64(v.size());
  bytes_ += v;
}

void WireWriter::doubles(const std::vector<double>& v) {
  u64(v.size());
  for (double x : v) f64(x);
}

std::size_t WireReader::count(std::size_t bytes_each) {
  const std::uint64_t n = u64();
  if (bytes_each > 0 && n > (bytes_.size() - at_) / bytes_each)
    throw std::runtime_error("a step's message between processes ends early (corrupt)");
  return static_cast<std::size_t>(n);
}

std::uint64_t WireReader::u64() {
  if (bytes_.size() - at_ < 8)
    throw std::runtime_error("a step's message between processes ends early (corrupt)");
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[at_ + i])) << (8 * i);
  at_ += 8;
  return v;
}

double WireReader::f64() {
  return std::bit_cast<double>(u64());
}

std::string WireReader::text() {
  const std::size_t n = count(1);
  std::string v = bytes_.substr(at_, n);
  at_ += n;
  return v;
}

std::vector<double> WireReader::doubles() {
  std::vector<double> v(count(8));
  for (double& x : v) x = f64();
  return v;
}

namespace {

void optional_f64(WireWriter& w, const std::optional<double>& v) {
  w.flag(v.has_value());
  if (v) w.f64(*v);
}

std::optional<double> read_optional_f64(WireReader& r) {
  if (!r.flag()) return std::nullopt;
  return r.f64();
}

void write(WireWriter& w, const tangential::Creepages& c) {
  w.f64(c.vx);
  w.f64(c.vy);
  w.f64(c.phi);
}

tangential::Creepages read_creepages(WireReader& r) {
  tangential::Creepages c;
  c.vx = r.f64();
  c.vy = r.f64();
  c.phi = r.f64();
  return c;
}

void optional_creepages(WireWriter& w, const std::optional<tangential::Creepages>& c) {
  w.flag(c.has_value());
  if (c) write(w, *c);
}

std::optional<tangential::Creepages> read_optional_creepages(WireReader& r) {
  if (!r.flag()) return std::nullopt;
  return read_creepages(r);
}

void write(WireWriter& w, const tangential::CellFields& f) {
  w.i64(f.nx);
  w.i64(f.ny);
  w.f64(f.dy);
  for (const std::vector<double>* v : {&f.dx, &f.strip_y, &f.x, &f.y, &f.px, &f.py, &f.sx, &f.sy,
                                       &f.slip_norm, &f.work, &f.pressure})
    w.doubles(*v);
  w.text(std::string(f.slip.begin(), f.slip.end()));
}

tangential::CellFields read_fields(WireReader& r) {
  tangential::CellFields f;
  f.nx = static_cast<int>(r.i64());
  f.ny = static_cast<int>(r.i64());
  f.dy = r.f64();
  for (std::vector<double>* v : {&f.dx, &f.strip_y, &f.x, &f.y, &f.px, &f.py, &f.sx, &f.sy,
                                 &f.slip_norm, &f.work, &f.pressure})
    *v = r.doubles();
  const std::string slip = r.text();
  f.slip.assign(slip.begin(), slip.end());
  return f;
}

void write(WireWriter& w, const tangential::TangentialSolution& s) {
  w.f64(s.forces.Fx);
  w.f64(s.forces.Fy);
  optional_f64(w, s.forces.Mz);
  w.flag(s.forces.flags.kalker_extrapolated);
  w.flag(s.forces.flags.sdec_held);
  w.u64(static_cast<std::uint64_t>(s.status));
  w.text(s.message);
  w.i64(s.cells);
  w.i64(s.slip_cells);
  w.flag(s.fields.has_value());
  if (s.fields) write(w, *s.fields);
  w.f64(s.frictional_work);
  w.flag(s.from_table);
  w.flag(s.table_outside.has_value());
  if (s.table_outside) w.text(*s.table_outside);
}

tangential::TangentialSolution read_solution(WireReader& r) {
  tangential::TangentialSolution s;
  s.forces.Fx = r.f64();
  s.forces.Fy = r.f64();
  s.forces.Mz = read_optional_f64(r);
  s.forces.flags.kalker_extrapolated = r.flag();
  s.forces.flags.sdec_held = r.flag();
  s.status = static_cast<tangential::SolveStatus>(r.u64());
  s.message = r.text();
  s.cells = static_cast<int>(r.i64());
  s.slip_cells = static_cast<int>(r.i64());
  if (r.flag()) s.fields = read_fields(r);
  s.frictional_work = r.f64();
  s.from_table = r.flag();
  if (r.flag()) s.table_outside = r.text();
  return s;
}

void write(WireWriter& w, const PatchOutcome& p) {
  w.f64(p.normal_force);
  w.f64(p.sdec.a);
  w.f64(p.sdec.b);
  w.f64(p.sdec.psi);
  w.f64(p.y_wheel);
  w.f64(p.contact_angle);
  w.flag(p.solved);
  write(w, p.creepages);
  write(w, p.solution);
  w.u64(p.wear.first);
  w.doubles(p.wear.depth);
}

PatchOutcome read_patch(WireReader& r) {
  PatchOutcome p;
  p.normal_force = r.f64();
  p.sdec.a = r.f64();
  p.sdec.b = r.f64();
  p.sdec.psi = r.f64();
  p.y_wheel = r.f64();
  p.contact_angle = r.f64();
  p.solved = r.flag();
  p.creepages = read_creepages(r);
  p.solution = read_solution(r);
  p.wear.first = r.u64();
  p.wear.depth = r.doubles();
  return p;
}

void write(WireWriter& w, const WheelOutcome& o) {
  w.u64(static_cast<std::uint64_t>(o.status));
  w.f64(o.dy);
  w.f64(o.vertical_force);
  w.f64(o.lateral_force);
  w.u64(static_cast<std::uint64_t>(o.lateral_fit));
  w.u64(o.contact_patches);
  w.i64(o.hertz_dropped);
  w.f64(o.nadal.delta);
  w.f64(o.nadal.limit);
  w.f64(o.nadal.Y_over_Q);
  w.flag(o.nadal.applies);
  w.flag(o.nadal.exceeded);
  w.u64(o.patches.size());
  for (const PatchOutcome& p : o.patches) write(w, p);
}

WheelOutcome read_wheel(WireReader& r) {
  WheelOutcome o;
  o.status = static_cast<contactgeom::WheelRailStatus>(r.u64());
  o.dy = r.f64();
  o.vertical_force = r.f64();
  o.lateral_force = r.f64();
  o.lateral_fit = static_cast<contactgeom::LateralFit>(r.u64());
  o.contact_patches = r.u64();
  o.hertz_dropped = static_cast<int>(r.i64());
  o.nadal.delta = r.f64();
  o.nadal.limit = r.f64();
  o.nadal.Y_over_Q = r.f64();
  o.nadal.applies = r.flag();
  o.nadal.exceeded = r.flag();
  o.patches.resize(r.count(8));
  for (PatchOutcome& p : o.patches) p = read_patch(r);
  return o;
}

}  // namespace

void write(WireWriter& w, const SceneSource& source) {
  w.flag(source.builtin);
  w.text(source.text);
  w.text(source.directory.string());
  w.u64(source.inputs.size());
  for (const SceneInput& in : source.inputs) {
    w.text(in.key);
    w.text(in.path);
    w.text(in.content);
  }
}

SceneSource read_scene_source(WireReader& r) {
  SceneSource source;
  source.builtin = r.flag();
  source.text = r.text();
  source.directory = r.text();
  source.inputs.resize(r.count(24));
  for (SceneInput& in : source.inputs) {
    in.key = r.text();
    in.path = r.text();
    in.content = r.text();
  }
  return source;
}

void write(WireWriter& w, const std::vector<profiles::PointList>& profiles) {
  w.u64(profiles.size());
  for (const profiles::PointList& points : profiles) {
    w.u64(points.size());
    for (const profiles::Point& p : points) {
      w.f64(p.x());
      w.f64(p.y());
    }
  }
}

std::vector<profiles::PointList> read_point_lists(WireReader& r) {
  std::vector<profiles::PointList> profiles(r.count(8));
  for (profiles::PointList& points : profiles) {
    points.resize(r.count(16));
    for (profiles::Point& p : points) {
      const double y = r.f64();
      p = profiles::Point(y, r.f64());
    }
  }
  return profiles;
}

void write(WireWriter& w, const std::vector<WheelsetStateSpec>& specs) {
  w.u64(specs.size());
  for (const WheelsetStateSpec& s : specs) {
    w.text(s.label);
    for (double v : {s.dy, s.yaw, s.load_left, s.load_right}) w.f64(v);
    optional_f64(w, s.lateral_force_left);
    optional_f64(w, s.lateral_force_right);
    for (double v : {s.speed, s.curve_radius, s.lateral_velocity}) w.f64(v);
    optional_f64(w, s.angular_velocity);
    w.f64(s.yaw_rate);
    optional_f64(w, s.roll);
    optional_f64(w, s.friction);
    optional_f64(w, s.friction_flange);
    optional_creepages(w, s.creepages_left);
    optional_creepages(w, s.creepages_right);
    w.f64(s.weight);
    w.i64(s.wheelset);
    w.flag(s.reversed);
    w.i64(s.line);
  }
}

std::vector<WheelsetStateSpec> read_specs(WireReader& r) {
  std::vector<WheelsetStateSpec> specs(r.count(8));
  for (WheelsetStateSpec& s : specs) {
    s.label = r.text();
    for (double* v : {&s.dy, &s.yaw, &s.load_left, &s.load_right}) *v = r.f64();
    s.lateral_force_left = read_optional_f64(r);
    s.lateral_force_right = read_optional_f64(r);
    for (double* v : {&s.speed, &s.curve_radius, &s.lateral_velocity}) *v = r.f64();
    s.angular_velocity = read_optional_f64(r);
    s.yaw_rate = r.f64();
    s.roll = read_optional_f64(r);
    s.friction = read_optional_f64(r);
    s.friction_flange = read_optional_f64(r);
    s.creepages_left = read_optional_creepages(r);
    s.creepages_right = read_optional_creepages(r);
    s.weight = r.f64();
    s.wheelset = static_cast<int>(r.i64());
    s.reversed = r.flag();
    s.line = static_cast<int>(r.i64());
  }
  return specs;
}

void write(WireWriter& w, const std::vector<StateOutcome>& states) {
  w.u64(states.size());
  for (const StateOutcome& s : states) {
    w.f64(s.roll);
    for (const WheelOutcome& wheel : s.wheels) write(w, wheel);
  }
}

std::vector<StateOutcome> read_outcomes(WireReader& r) {
  std::vector<StateOutcome> states(r.count(8));
  for (StateOutcome& s : states) {
    s.roll = r.f64();
    for (WheelOutcome& wheel : s.wheels) wheel = read_wheel(r);
  }
  return states;
}

}  // namespace wheelwear::pipeline::detail
