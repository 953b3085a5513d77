// Uses the installed wheelwear library from outside the project: generates the S1002 wheel
// profile, solves FASTSIM-SDEC and looks up the installed exact-theory table on a patch at small
// creepage, comparing both with the linear theory they tend to there, and reads the built-in
// default scene. Exits non-zero when an answer is wrong.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/linear_theory.hpp"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

bool near(double value, double expected, double tolerance) {
  return std::abs(value - expected) <= tolerance;
}

void profile_checks() {
  namespace profiles = wheelwear::profiles;
  const profiles::Profile wheel = profiles::s1002();
  // EN 13715: the taping line is the origin, and the nominal flange (h28) reaches 28 mm below
  // it (z points down, so the tip is the largest z).
  const auto z0 = wheel.z_at(0.0);
  check(z0 && near(*z0, 0.0, 1e-6), "S1002 passes through the taping line");
  double tip = -1.0;
  for (const auto& point : profiles::s1002_points()) tip = std::max(tip, point[1]);
  check(near(tip, 0.028, 1e-5),
        "S1002 flange height 28 mm (tip z = " + std::to_string(tip) + " m)");
}

void creep_checks() {
  namespace tangential = wheelwear::tangential;
  // Far below saturation FASTSIM-SDEC gives the SDEC linear theory's forces: its flexibilities
  // are chosen for that (only cells at the trailing edge, where the bound vanishes, slip).
  const wheelwear::contactgeom::Sdec patch{.a = 5e-3, .b = 4e-3, .psi = 0.3};
  const tangential::Creepages creepages{.vx = 1e-6, .vy = 2e-6, .phi = 0.0};
  const tangential::Material material{.G = 80e9, .nu = 0.25};
  const tangential::ContactLoad load{.N = 50e3, .mu = 0.3};
  // The second-order marching: Kalker's first-order scheme is 2 % low on this grid.
  const tangential::FastsimOptions options{
      .nx = 50, .ny = 50, .scheme = tangential::FastsimScheme::second_order};
  const auto fastsim = tangential::fastsim(tangential::FastsimMethod::sdec, patch, creepages, load,
                                           material, options);
  const auto linear = tangential::linear_sdec_forces(patch, creepages, material);
  std::printf(
      "      FASTSIM-SDEC Fx = %.2f N, Fy = %.2f N; linear theory Fx = %.2f N, Fy = %.2f N\n",
      fastsim.forces.Fx, fastsim.forces.Fy, linear.Fx, linear.Fy);
  check(linear.Fx < 0.0 && linear.Fy < 0.0, "forces oppose the creepages");
  check(near(fastsim.forces.Fx, linear.Fx, 0.005 * std::abs(linear.Fx)),
        "FASTSIM-SDEC Fx within 0.5 % of the linear theory");
  check(near(fastsim.forces.Fy, linear.Fy, 0.005 * std::abs(linear.Fy)),
        "FASTSIM-SDEC Fy within 0.5 % of the linear theory");
}

void table_checks() {
  namespace tangential = wheelwear::tangential;
  // The book of exact-theory tables is read at run time: from the installed share/wheelwear
  // when install_and_run.cmake points WHEELWEAR_DATA_DIR there.
  const auto path = tangential::creep_table_path();
  if (const char* dir = std::getenv("WHEELWEAR_DATA_DIR")) {
    check(std::filesystem::equivalent(path.parent_path(), dir),
          "creep table read from WHEELWEAR_DATA_DIR (" + path.string() + ")");
  }
  // Kalker's exact theory tends to the linear theory as the creepage vanishes (here the
  // normalised creepage is about 0.01: saturation takes 0.3 % off). The table's solutions, from
  // a finite grid, lie about 2 % above that limit, hence 5 %.
  const wheelwear::contactgeom::Sdec patch{.a = 5e-3, .b = 4e-3, .psi = 0.3};
  const tangential::Creepages creepages{.vx = 2e-5, .vy = 0.0, .phi = 0.0};
  const tangential::Material material{.G = 80e9, .nu = 0.25};
  const tangential::ContactLoad load{.N = 50e3, .mu = 0.3};
  const auto table = tangential::creep_table_forces(patch, creepages, load, material);
  const auto linear = tangential::linear_sdec_forces(patch, creepages, material);
  std::printf("      exact theory (table) Fx = %.3f N; linear theory Fx = %.3f N\n", table.Fx,
              linear.Fx);
  check(near(table.Fx, linear.Fx, 0.05 * std::abs(linear.Fx)),
        "exact theory Fx within 5 % of the linear theory");
}

void scene_checks() {
  // The built-in scenes are compiled into the pipeline library; parsing them goes through
  // toml++.
  const auto scene = wheelwear::pipeline::default_scene();
  check(scene.wheel_profile == "S1002" && scene.rail_profile == "60E1",
        "default scene: S1002 on 60E1");
  check(scene.vehicle_run.has_value(), "default scene: the vehicle on its route");
  const auto frozen = wheelwear::pipeline::frozen_collective_scene();
  check(frozen.states.size() == 1000, "frozen-collective scene: 1000 wheelset states (" +
                                          std::to_string(frozen.states.size()) + ")");
}

}  // namespace

int main() {
  try {
    profile_checks();
    creep_checks();
    table_checks();
    scene_checks();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "wheelwear_consumer: %s\n", error.what());
    return 1;
  }
  if (failures > 0) {
    std::fprintf(stderr, "wheelwear_consumer: %d check(s) failed\n", failures);
    return 1;
  }
  return 0;
}
