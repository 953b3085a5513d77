#include "wheelwear/pipeline/run_headline.hpp"

#include <cmath>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::pipeline {

namespace {

// The states not worn over the whole run: counts summed, weights as the share of the run's
// distance (each step's share times the distance of the step it drove).
std::map<std::string, double> run_dropped(const ResultsFile& file, int last) {
  std::vector<double> step_distance;
  double distance = 0.0;
  for (int step = 0; step <= last; ++step) {
    step_distance.push_back(file.read_step_array(step, "step_distance").at(0));
    distance += step_distance.back();
  }
  std::map<std::string, double> totals;
  for (const auto& [name, unused] : DroppedStates{}.named()) {
    const bool weight = name.find("_weight") != std::string::npos;
    double& total = totals[name];
    for (int step = 0; step <= last; ++step) {
      const double value = file.read_step_array(step, name).at(0);
      const auto k = static_cast<std::size_t>(step);
      total += weight && distance > 0.0 ? value * step_distance[k] / distance : value;
    }
  }
  return totals;
}

// The first step at which a wheel profile reached an in-service limit, and what it reached.
void first_limit(const ResultsFile& file, int last, RunHeadline& out) {
  std::vector<std::string> wheels;
  for (auto layout :
       {ProfileLayout::shared, ProfileLayout::left_right, ProfileLayout::per_wheelset})
    for (const std::string& name : profile_names(layout)) wheels.push_back(name);
  auto recorded = [&](int step, const std::string& wheel) {
    return file.has(ResultsFile::step_group(step) + "/" + wheel + "/limits_reached");
  };
  // The run counts the limits each profile reached per step; the phrases are rebuilt from the
  // recorded parameters and limits at the first step that has any.
  for (int step = 0; step <= last && out.limit_step < 0; ++step)
    for (const std::string& wheel : wheels)
      if (recorded(step, wheel) && file.read_step_array(step, wheel + "/limits_reached").at(0) > 0)
        out.limit_step = step;
  if (out.limit_step < 0) return;
  auto at = [&](const std::string& name) {
    return file.read_step_array(out.limit_step, name).at(0);
  };
  const profiles::WheelLimits bounds{at("limits/Sd_min"), at("limits/Sh_max"), at("limits/qR_min")};
  for (const std::string& wheel : wheels) {
    if (!recorded(out.limit_step, wheel)) continue;
    profiles::WheelParameters p;
    p.Sd = at(wheel + "/Sd");
    p.Sh = at(wheel + "/Sh");
    p.qR = at(wheel + "/qR");
    for (const std::string& phrase : profiles::limits_reached(p, bounds))
      out.limit_reached += (out.limit_reached.empty() ? "" : ", ") + wheel + " " + phrase;
  }
}

// The area under the cumulative depth along the new profile's arc length (trapezoids; a NaN,
// where the normal misses the worn profile, ends a piece).
double worn_area(const std::vector<double>& s, const std::vector<double>& depth) {
  double area = 0.0;
  for (std::size_t i = 1; i < s.size() && i < depth.size(); ++i)
    if (std::isfinite(depth[i - 1]) && std::isfinite(depth[i]))
      area += 0.5 * (depth[i - 1] + depth[i]) * (s[i] - s[i - 1]);
  return area;
}

}  // namespace

RunHeadline read_headline(const ResultsFile& file) {
  RunHeadline h;
  const int last = file.completed_steps() - 1;
  if (last < 0) throw InputError("results file " + file.path().string() + ": no step written yet");
  h.steps = last;
  // The first profile of the run's layout: the shared one, the left, or wheelset 1's left.
  h.wheel = "wheel";
  for (const char* name : {"wheel", "wheel_left", "wheelsets/1/wheel_left"}) {
    if (!file.has(ResultsFile::step_group(last) + "/" + name)) continue;
    h.wheel = name;
    break;
  }
  auto at = [&](int step, const std::string& name) {
    return file.read_step_array(step, name).at(0);
  };
  h.distance = at(last, "distance");
  h.complete = at(last, "step_distance") == 0.0 || file.has("/final");
  h.Sh_start = at(0, h.wheel + "/Sh");
  h.Sh_end = at(last, h.wheel + "/Sh");
  h.Sd_start = at(0, h.wheel + "/Sd");
  h.Sd_end = at(last, h.wheel + "/Sd");
  h.qR_start = at(0, h.wheel + "/qR");
  h.qR_end = at(last, h.wheel + "/qR");
  h.conicity_start = at(0, "equivalent_conicity");
  h.conicity_end = at(last, "equivalent_conicity");
  h.worn_area = worn_area(file.read_step_array(last, h.wheel + "/cumulative_wear/s"),
                          file.read_step_array(last, h.wheel + "/cumulative_wear/depth"));
  h.dropped = run_dropped(file, last);
  first_limit(file, last, h);
  h.stopped_at_limit = file.has(ResultsFile::step_group(last) + "/limits/stopped") &&
                       at(last, "limits/stopped") > 0.0;
  return h;
}

}  // namespace wheelwear::pipeline
