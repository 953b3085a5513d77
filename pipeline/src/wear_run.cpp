#include "wheelwear/pipeline/wear_run.hpp"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/contactgeom/equivalent_conicity.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/profiles/wear_update.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

constexpr double kConicityAmplitude = 3e-3;  // EN 15302's reference amplitude [m]
constexpr double kDeltaRRange = 6e-3;        // Delta r is sampled over +-6 mm ...
constexpr int kDeltaRSamples = 61;           // ... every 0.2 mm
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Clock = std::chrono::steady_clock;

// A worn wheel profile as the run carries it: the points it is built from (exactly what the
// file records, so a resumed run rebuilds the identical profile).
struct WornProfile {
  std::string name;  // group name in the file
  profiles::ProfileInfo info;
  profiles::CurveOptions curve;
  profiles::PointList points;

  profiles::Profile build() const { return profiles::Profile(points, info, curve); }
};

// Where the loop starts: a new run at step 0 or a resumed one.
struct LoopStart {
  int step = 0;
  double distance = 0.0;
  std::vector<WornProfile> worn;
};

std::vector<WornProfile> new_profiles(const Scene& scene) {
  const profiles::Profile initial = profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius);
  WornProfile w{"wheel", initial.info(), initial.curve_options(), initial.knot_points()};
  // The profile is re-interpolated through its knots: smoothing was applied once, on reading.
  w.curve.smoothing_length = 0.0;
  if (!scene.separate_wheels) return {w};
  WornProfile left = w, right = w;
  left.name = "wheel_left";
  right.name = "wheel_right";
  return {left, right};
}

ArrayRecord scalar(std::string name, double value, std::string units, std::string description) {
  return {std::move(name), {value}, {}, std::move(units), std::move(description)};
}

ArrayRecord vector(std::string name, std::vector<double> values, std::string units,
                   std::string description) {
  const std::size_t n = values.size();
  return {std::move(name), std::move(values), {n}, std::move(units), std::move(description)};
}

// The rate smoothed along the arc length by a Gaussian of standard deviation `length`: each
// bin's wear is spread over its neighbours with weights that sum to one within the profile, so
// the worn area is conserved exactly and no negative lobes appear (a smoothing spline's would
// be clipped at zero and add area).
wear::WearDistribution smoothed(const wear::WearDistribution& rate, double length) {
  if (length <= 0.0) return rate;
  const auto reach = static_cast<long>(std::ceil(4.0 * length / rate.ds));
  std::vector<double> kernel(static_cast<std::size_t>(2 * reach + 1));
  for (long k = -reach; k <= reach; ++k) {
    const double u = static_cast<double>(k) * rate.ds / length;
    kernel[static_cast<std::size_t>(k + reach)] = std::exp(-0.5 * u * u);
  }
  wear::WearDistribution out = rate;
  std::fill(out.depth.begin(), out.depth.end(), 0.0);
  const auto n = static_cast<long>(rate.depth.size());
  for (long i = 0; i < n; ++i) {
    const double d = rate.depth[static_cast<std::size_t>(i)];
    if (d == 0.0) continue;
    const long lo = std::max(0L, i - reach), hi = std::min(n - 1, i + reach);
    double total = 0.0;
    for (long j = lo; j <= hi; ++j) total += kernel[static_cast<std::size_t>(j - i + reach)];
    for (long j = lo; j <= hi; ++j)
      out.depth[static_cast<std::size_t>(j)] +=
          d * kernel[static_cast<std::size_t>(j - i + reach)] / total;
  }
  return out;
}

// The step's depth as a function of the profile's lateral coordinate (what apply_wear takes):
// bins where y does not increase (a vertical flange back) carry no wear and are left out.
profiles::WearDepth depth_on_y(const profiles::Profile& profile, const wear::WearDistribution& rate,
                               double distance) {
  profiles::WearDepth depth;
  for (std::size_t k = 0; k < rate.depth.size(); ++k) {
    const double y = profile.position(rate.s(k)).x();
    if (!depth.y.empty() && !(y > depth.y.back())) continue;
    depth.y.push_back(y);
    depth.depth.push_back(rate.depth[k] * distance);
  }
  return depth;
}

void add_summaries(GroupRecord& g, const StateSummaries& s) {
  const std::vector<std::size_t> per_wheel = {s.states, 2};
  const std::vector<std::size_t> per_patch = {s.states, 2, static_cast<std::size_t>(kPatchSlots)};
  auto add = [&](const char* name, const std::vector<double>& v, const char* units,
                 const char* what, bool patch) {
    g.arrays.push_back(
        {std::string("states/") + name, v, patch ? per_patch : per_wheel, units, what});
  };
  add("status", s.status, "1",
      "[state, wheel (left, right)] contact status: 0 ok, 1 no contact, 2 flange climb, 3 not "
      "converged, 4 load jump, 5 profile end",
      false);
  add("patches", s.patches, "1", "[state, wheel] number of contact patches", false);
  add("dy", s.dy, "m", "[state, wheel] lateral shift of the wheel, + towards its flange", false);
  g.arrays.push_back({"states/roll",
                      s.roll,
                      {s.states},
                      "rad",
                      "[state] wheelset roll, + when the left wheel goes down"});
  add("vertical_force", s.vertical_force, "N", "[state, wheel] vertical force of the contact",
      false);
  add("lateral_force", s.lateral_force, "N",
      "[state, wheel] lateral force of the contact, + pushing the wheel to the track centre",
      false);
  add("lateral_fit", s.lateral_fit, "1",
      "[state, wheel] prescribed lateral force: 0 not given, 1 matched, 2 position kept, 3 "
      "flange just unloaded, 4 not matched",
      false);
  add("normal_force", s.normal_force, "N", "[state, wheel, patch] normal force", true);
  add("a", s.a, "m", "[state, wheel, patch] SDEC semi-axis along x (Eq. 13)", true);
  add("b", s.b, "m", "[state, wheel, patch] SDEC semi-axis along y (Eq. 13)", true);
  add("psi", s.psi, "1", "[state, wheel, patch] SDEC asymmetry psi (Eq. 14)", true);
  add("y_wheel", s.y_wheel, "m", "[state, wheel, patch] O on the wheel, + towards the flange",
      true);
  add("contact_angle", s.contact_angle, "rad", "[state, wheel, patch] contact angle", true);
  add("vx", s.vx, "1", "[state, wheel, patch] longitudinal creepage at O", true);
  add("vy", s.vy, "1", "[state, wheel, patch] lateral creepage at O, + to the gauge side", true);
  add("phi", s.phi, "1/m", "[state, wheel, patch] spin creepage at O", true);
  add("Fx", s.Fx, "N", "[state, wheel, patch] longitudinal creep force on the wheel", true);
  add("Fy", s.Fy, "N", "[state, wheel, patch] lateral creep force on the wheel", true);
  add("frictional_work", s.frictional_work, "J/m",
      "[state, wheel, patch] frictional work per metre rolled", true);
  add("worn_area", s.worn_area, "m^2/m",
      "[state, wheel, patch] worn cross-section per metre running of this contact", true);
  add("from_table", s.from_table, "1",
      "[state, wheel, patch] 1: Fx, Fy and the frictional work from the book of tables of "
      "Kalker's exact theory (tangential_method = best), 0: not from the table",
      true);
}

void add_maps(GroupRecord& g, const TgammaMaps& m, std::size_t states) {
  const std::vector<std::size_t> shape = {states, 2, static_cast<std::size_t>(kPatchSlots),
                                          static_cast<std::size_t>(m.ny),
                                          static_cast<std::size_t>(m.nx)};
  g.arrays.push_back({"tgamma/work", m.work, shape, "J/m^2/m",
                      "[state, wheel, patch, strip, cell] frictional work density T gamma per "
                      "metre rolled"});
  g.arrays.push_back({"tgamma/x", m.x, shape, "m", "cell centre along x (rolling) relative to O"});
  g.arrays.push_back(
      {"tgamma/y", m.y, shape, "m", "cell centre along y relative to O, + towards the flange"});
}

// The states as the run resolved them (from the scene, a CSV or an HDF5 file).
GroupRecord collective_record(const Scene& scene) {
  const std::size_t n = scene.states.size();
  std::vector<double> dy(n), yaw(n), ql(n), qr(n), yl(n), yr(n), v(n), radius(n), vlat(n), w(n),
      line(n);
  std::string labels;
  for (std::size_t i = 0; i < n; ++i) {
    const WheelsetStateSpec& s = scene.states[i];
    dy[i] = s.dy;
    yaw[i] = s.yaw;
    ql[i] = s.load_left;
    qr[i] = s.load_right;
    yl[i] = s.lateral_force_left.value_or(kNaN);
    yr[i] = s.lateral_force_right.value_or(kNaN);
    v[i] = s.speed;
    radius[i] = s.curve_radius;
    vlat[i] = s.lateral_velocity;
    w[i] = s.weight;
    line[i] = s.line;
    labels += s.label + '\n';
  }
  GroupRecord g;
  g.arrays.push_back(vector("dy_m", dy, "m", "wheelset lateral shift, + to the left"));
  g.arrays.push_back(vector("yaw_rad", yaw, "rad", "yaw angle"));
  g.arrays.push_back(vector("load_left_N", ql, "N", "vertical force on the left wheel"));
  g.arrays.push_back(vector("load_right_N", qr, "N", "vertical force on the right wheel"));
  g.arrays.push_back(vector("lateral_force_left_N", yl, "N",
                            "prescribed lateral force of the left wheel (NaN: not given)"));
  g.arrays.push_back(vector("lateral_force_right_N", yr, "N",
                            "prescribed lateral force of the right wheel (NaN: not given)"));
  g.arrays.push_back(vector("speed_m_s", v, "m/s", "forward speed"));
  g.arrays.push_back(vector("curve_radius_m", radius, "m", "0 tangent, + right-hand curve"));
  g.arrays.push_back(vector("lateral_velocity_m_s", vlat, "m/s", "dy/dt, + to the left"));
  g.arrays.push_back(vector("weight", w, "1", "share of the running distance (unnormalised)"));
  g.arrays.push_back(vector("line", line, "1", "line of the state in its scene or file"));
  g.texts.push_back({"label", labels, "the states' labels, one per line"});
  return g;
}

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return text;
}

GroupRecord run_info(const fs::path& scene_directory, bool builtin, double elapsed,
                     std::size_t evaluations, int resumed_from) {
  char host[256] = "unknown";
  ::gethostname(host, sizeof host - 1);
  GroupRecord info;
  info.texts.push_back({"scene_directory", scene_directory.string(),
                        "directory the scene's relative file names are resolved in"});
  info.texts.push_back({"host", host, "machine the run (or its last part) ran on"});
  info.texts.push_back({"written", now_iso8601(), "time of writing (UTC)"});
  info.arrays.push_back(scalar("builtin_scene", builtin ? 1.0 : 0.0, "1",
                               "1 when the run uses the built-in default scene"));
  info.arrays.push_back(scalar("threads", tbb::this_task_arena::max_concurrency(), "1",
                               "worker threads available to this process"));
  info.arrays.push_back(scalar("elapsed", elapsed, "s", "wall time of this process"));
  info.arrays.push_back(scalar("evaluations", static_cast<double>(evaluations), "1",
                               "wheelset states evaluated by this process"));
  info.arrays.push_back(scalar("resumed_from_step", resumed_from, "1",
                               "step this process resumed after; -1 for a run from the start"));
  return info;
}

RunSummary loop(const Scene& scene, const CollectiveEvaluator& evaluator, ResultsFile& file,
                LoopStart start, const fs::path& scene_directory, bool builtin,
                const RunOptions& options) {
  const auto t0 = Clock::now();
  RunSummary summary;
  int step = start.step;
  double distance = start.distance;
  std::vector<WornProfile> worn = std::move(start.worn);
  // The depth arrives smoothed (smoothed() above): the update adds no smoothing of its own.
  const profiles::WearUpdateOptions update{0.0};
  while (true) {
    std::vector<profiles::Profile> wheels;
    for (const WornProfile& w : worn) wheels.push_back(w.build());
    std::vector<const profiles::Profile*> pointers;
    for (const auto& w : wheels) pointers.push_back(&w);
    const CollectiveWear cw = evaluator.evaluate(pointers);
    summary.evaluations += scene.states.size();
    summary.geometry_solves += cw.geometry_solves;

    std::vector<wear::WearDistribution> smooth_rate;
    for (const auto& r : cw.rate) smooth_rate.push_back(smoothed(r, scene.smoothing_length));
    // Step control: the distance that keeps the deepest increment below max_depth_step.
    double peak = 0.0;
    for (const auto& r : smooth_rate)
      for (double d : r.depth) peak = std::max(peak, d);
    const double remaining = scene.distance - distance;
    double step_distance = 0.0;
    if (remaining > 1e-9 * scene.distance) {
      step_distance = std::min(scene.step_distance, remaining);
      if (peak > 0.0) step_distance = std::min(step_distance, scene.max_depth_step / peak);
    }

    GroupRecord g;
    g.arrays.push_back(scalar("distance", distance, "m", "running distance at this step"));
    g.arrays.push_back(scalar("step_distance", step_distance, "m",
                              "distance of the wear increment taken from here (0: the end)"));
    g.arrays.push_back(scalar("failed_contacts", cw.failed_contacts, "1",
                              "wheel contacts without a usable patch (skipped)"));
    g.arrays.push_back(scalar("failed_weight", cw.failed_weight, "1",
                              "share of the running distance of the skipped contacts"));
    g.arrays.push_back(
        scalar("patches", static_cast<double>(cw.patches), "1", "contact patches solved"));
    g.arrays.push_back(scalar("table_patches", static_cast<double>(cw.table_patches), "1",
                              "of them, with totals from the book of tables "
                              "(tangential_method = best)"));
    g.arrays.push_back(scalar("unconverged_patches", static_cast<double>(cw.unconverged_patches),
                              "1",
                              "exact solves (tangential_method = exact) stopped at their "
                              "iteration cap; their last iterate is used"));
    std::vector<profiles::WearDepth> increments;
    for (std::size_t p = 0; p < worn.size(); ++p) {
      const std::string& n = worn[p].name;
      std::vector<double> y, z;
      for (const auto& point : worn[p].points) {
        y.push_back(point.x());
        z.push_back(point.y());
      }
      g.arrays.push_back(vector(n + "/y", y, "m", "profile points, lateral (+ field side)"));
      g.arrays.push_back(vector(n + "/z", z, "m", "profile points, vertical (+ down)"));
      profiles::WheelParameters params;
      double sh = kNaN, sd = kNaN, qr = kNaN;
      try {
        params = profiles::wheel_parameters(wheels[p]);
        sh = params.Sh;
        sd = params.Sd;
        qr = params.qR;
      } catch (const InputError&) {
        // A profile worn past EN 15313's reference points has no parameters: NaN records it.
      }
      g.arrays.push_back(scalar(n + "/Sh", sh, "m", "flange height (EN 15313)"));
      g.arrays.push_back(scalar(n + "/Sd", sd, "m", "flange thickness (EN 15313)"));
      g.arrays.push_back(scalar(n + "/qR", qr, "m", "flange slope measure qR (EN 15313)"));
      const wear::WearDistribution& rate = cw.rate[p];
      std::vector<double> s(rate.depth.size()), ys(rate.depth.size());
      for (std::size_t k = 0; k < s.size(); ++k) {
        s[k] = rate.s(k);
        ys[k] = wheels[p].position(s[k]).x();
      }
      g.arrays.push_back(
          vector(n + "/wear_rate/s", s, "m", "bin centre, arc length on the profile"));
      g.arrays.push_back(vector(n + "/wear_rate/y", ys, "m", "bin centre, lateral position"));
      g.arrays.push_back(
          vector(n + "/wear_rate/depth", rate.depth, "m/m",
                 "worn depth per metre running, weighted over the collective (unsmoothed)"));
      increments.push_back(depth_on_y(wheels[p], smooth_rate[p], step_distance));
      g.arrays.push_back(vector(n + "/wear_step/y", increments.back().y, "m",
                                "lateral positions of the step's wear depth"));
      g.arrays.push_back(
          vector(n + "/wear_step/depth", increments.back().depth, "m",
                 "wear depth of the step (smoothed wear rate times the step distance)"));
    }
    const contactgeom::WheelRailPair left = evaluator.pair(wheels.front());
    const contactgeom::WheelRailPair right = evaluator.pair(wheels.back());
    const contactgeom::RollingRadiusDifference dr =
        contactgeom::rolling_radius_difference(left, right, kDeltaRRange, kDeltaRSamples);
    g.arrays.push_back(scalar("equivalent_conicity", contactgeom::equivalent_conicity(dr, kConicityAmplitude),
                              "1", "tan(gamma_e) at 3 mm amplitude (EN 15302, Annex C)"));
    g.arrays.push_back(vector("delta_r/dy", dr.dy, "m", "wheelset shift, + to the left"));
    g.arrays.push_back(vector("delta_r/value", dr.delta_r, "m", "r_left - r_right"));
    if (scene.state_summaries) add_summaries(g, cw.summaries);
    if (cw.maps) add_maps(g, *cw.maps, scene.states.size());
    file.append_step(g);

    summary.steps = step;
    summary.distance = distance;
    summary.patches += cw.patches;
    summary.table_patches += cw.table_patches;
    if (options.progress) {
      RunProgress p;
      p.step = step;
      p.distance = distance;
      p.total_distance = scene.distance;
      p.states = scene.states.size();
      p.elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
      p.evaluations_per_second = static_cast<double>(summary.evaluations) / p.elapsed;
      p.failed_contacts = cw.failed_contacts;
      options.progress(p);
    }
    if (step_distance == 0.0) break;
    for (std::size_t p = 0; p < worn.size(); ++p) {
      summary.worn_area += p == 0 ? smooth_rate[p].area() * step_distance : 0.0;
      worn[p].points = profiles::apply_wear(wheels[p], increments[p], update).knot_points();
    }
    distance += step_distance;
    ++step;
  }
  summary.elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  file.write_run_info(run_info(scene_directory, builtin, summary.elapsed, summary.evaluations,
                               start.step == 0 ? -1 : start.step - 1));
  return summary;
}

}  // namespace

RunSummary run_scene(const Scene& scene, std::string_view scene_text,
                     const fs::path& scene_directory, bool builtin_scene, const fs::path& output,
                     const RunOptions& options) {
  // Everything that can fail on input fails before the file is created.
  const CollectiveEvaluator evaluator(scene);
  LoopStart start{0, 0.0, new_profiles(scene)};
  for (const WornProfile& w : start.worn) evaluator.pair(w.build());
  ResultsFile file =
      ResultsFile::create(output, scene_text, options.overwrite, collective_record(scene));
  file.write_run_info(run_info(scene_directory, builtin_scene, 0.0, 0, -1));
  return loop(scene, evaluator, file, std::move(start), scene_directory, builtin_scene, options);
}

RunSummary resume_run(const fs::path& output, const RunOptions& options) {
  ResultsFile file = ResultsFile::open(output);
  const auto directory = file.read_text("/run_info/scene_directory");
  if (!directory) {
    throw InputError("results file " + output.string() +
                     ": no /run_info/scene_directory; it was not written by wheelwear run");
  }
  const bool builtin = file.read_array("/run_info/builtin_scene").at(0) != 0.0;
  const Scene scene = builtin ? default_scene() : parse_scene(file.scene_text(), *directory);
  const int last = file.completed_steps() - 1;
  if (last < 0) throw InputError("results file " + output.string() + ": no step to resume from");
  const double step_distance = file.read_step_array(last, "step_distance").at(0);
  if (step_distance == 0.0) {
    throw InputError("results file " + output.string() +
                     ": the run is complete; nothing to resume (start a new run with -o)");
  }
  const CollectiveEvaluator evaluator(scene);
  LoopStart start{last + 1, file.read_step_array(last, "distance").at(0) + step_distance,
                  new_profiles(scene)};
  const profiles::WearUpdateOptions update{0.0};  // as in loop()
  for (WornProfile& w : start.worn) {
    const auto y = file.read_step_array(last, w.name + "/y");
    const auto z = file.read_step_array(last, w.name + "/z");
    if (y.size() != z.size() || y.size() < 4)
      throw InputError("results file " + output.string() + ": step " + std::to_string(last) +
                       " holds no valid " + w.name + " profile");
    w.points.clear();
    for (std::size_t i = 0; i < y.size(); ++i) w.points.emplace_back(y[i], z[i]);
    profiles::WearDepth depth;
    depth.y = file.read_step_array(last, w.name + "/wear_step/y");
    depth.depth = file.read_step_array(last, w.name + "/wear_step/depth");
    w.points = profiles::apply_wear(w.build(), depth, update).knot_points();
  }
  return loop(scene, evaluator, file, std::move(start), *directory, builtin, options);
}

}  // namespace wheelwear::pipeline
