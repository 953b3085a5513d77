// `wheelwear contact`: the contact patches of one wheel on its rail for a wheelset position.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "contact_inputs.hpp"
#include "contact_wear.hpp"
#include "creep_request.hpp"
#include "json_writer.hpp"
#include "wheelwear/contactgeom/nadal.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::cli {

namespace {

struct ContactArgs {
  ContactInputs in;
  bool creep = false;
  bool json = false;
  std::string tangential = "fastsim-sdec";  // or "exact": also Kalker's exact theory
  ExactPatchOptions exact;                  // --tangential exact: its grid
  // To refuse them without --tangential exact.
  const CLI::Option* exact_grid_option = nullptr;
  const CLI::Option* exact_margin_option = nullptr;
  const CLI::Option* exact_radius_option = nullptr;
};

// One patch's creepages at O and its FASTSIM-SDEC creep forces (--creep).
struct PatchCreep {
  tangential::Creepages creepages;
  tangential::CreepForces forces;
};

// Every patch's creep forces, solved once for the report and Nadal's criterion; empty without
// --creep.
std::vector<PatchCreep> creep_of(const SolvedContact& solved, const ContactArgs& args) {
  std::vector<PatchCreep> out;
  if (!args.creep) return out;
  for (const auto& p : solved.contact.patches) {
    PatchCreep c;
    c.creepages = args.in.creepages_at(solved.pair, p);
    // A patch of a blend: its description's problem, weighted by its share.
    c.forces = tangential::weighted(
        tangential::fastsim(tangential::FastsimMethod::sdec, p.sdec, c.creepages,
                            {contactgeom::description_load(p), args.in.mu}, args.in.material())
            .forces,
        p.share);
    out.push_back(c);
  }
  return out;
}

std::string patch_json(const contactgeom::WheelRailPair& pair, const contactgeom::WheelRailPatch& p,
                       const PatchCreep* creep, const ContactArgs& args) {
  JsonObject o;
  o.add("area", p.measures.area)
      .add("length", p.measures.length)
      .add("width", p.measures.width)
      .add("W1", p.measures.W1)
      .add("W2", p.measures.W2)
      .add("a", p.sdec.a)
      .add("b", p.sdec.b)
      .add("psi", p.sdec.psi)
      // Positions on the profiles in each profile's own frame (+ towards the field side).
      .add("y_wheel", -p.y_wheel)
      .add("y_rail", -p.y_rail)
      .add("contact_angle", p.contact_angle)
      .add("contact_angle_centre", p.contact_angle_centre)
      .add("plane_angle", p.plane_angle)
      .add("N", p.normal_force)
      .add("pmax", p.pmax)
      .add("rolling_radius", p.rolling_radius)
      .add("share", p.share);
  if (p.hertz) {
    o.add("hertz_a", p.hertz->a).add("hertz_b", p.hertz->b).add("hertz_p0", p.hertz->p0);
  }
  if (creep) {
    const tangential::Creepages& c = creep->creepages;
    const tangential::CreepForces& f = creep->forces;
    o.add("vx", c.vx).add("vy", c.vy).add("phi", c.phi);
    o.add("Fx", f.Fx).add("Fy", f.Fy).add("Mz", f.Mz.value_or(0.0));
    if (args.tangential == "exact") {
      const tangential::WheelRailExactSolution e =
          exact_patch(args.in, pair, p, args.in.creepages_at(pair, p), args.exact);
      const tangential::ExactSolution& r = e.rolling;
      o.add("exact_status", tangential::status_name(r.status))
          .add("exact_N", r.normal_force)
          .add("exact_Fx", r.forces.Fx)
          .add("exact_Fy", r.forces.Fy)
          .add("exact_Mz", r.forces.Mz.value_or(0.0))
          .add("exact_approach", e.approach)
          .add("exact_area", e.contact_area)
          .add("exact_adhesion_fraction", e.adhesion_fraction)
          .add("exact_iterations", r.iterations)
          .add("exact_nx", r.grid.nx)
          .add("exact_ny", r.grid.ny);
      if (!r.message.empty()) o.add("exact_message", r.message);
    }
  }
  return o.str();
}

// Nadal's criterion for the contact, with each patch's lateral creep force where --creep gives
// them (the forces the report shows), else with the normal forces only.
contactgeom::NadalCheck nadal_of(const SolvedContact& solved, const std::vector<PatchCreep>& creep,
                                 const ContactArgs& args) {
  contactgeom::PatchLateralCreep creep_Fy;
  if (args.creep) {
    creep_Fy.emplace();
    for (const PatchCreep& c : creep) creep_Fy->push_back(c.forces.Fy);
  }
  return contactgeom::nadal_check(solved.contact, args.in.mu, creep_Fy);
}

void run_contact(const ContactArgs& args) {
  if (args.tangential == "exact") {
    check_exact_patch_options(args.exact);
  } else {
    for (const CLI::Option* given :
         {args.exact_grid_option, args.exact_margin_option, args.exact_radius_option})
      if (given && given->count() > 0)
        throw InputError(given->get_name() + ": applies only with --tangential exact");
  }
  const SolvedContact solved = solve_contact(args.in);
  const contactgeom::WheelRailContact& contact = solved.contact;
  for (const std::string& w : solved.warnings) std::cerr << "wheelwear: warning: " << w << '\n';

  const std::vector<PatchCreep> creep = creep_of(solved, args);
  const contactgeom::NadalCheck nadal = nadal_of(solved, creep, args);
  if (args.json) {
    std::vector<std::string> patches;
    for (std::size_t k = 0; k < contact.patches.size(); ++k)
      patches.push_back(
          patch_json(solved.pair, contact.patches[k], args.creep ? &creep[k] : nullptr, args));
    JsonObject out;
    out.add("status", contactgeom::status_name(contact.status))
        .add("message", contact.message)
        .add("vertical_force", contact.vertical_force)
        .add("lateral_force", contact.lateral_force)
        .add("approach", contact.approach)
        .add("nadal_exceeded", nadal.exceeded)
        .add("Y_over_Q", nadal.Y_over_Q)
        .add("nadal_limit", nadal.limit)
        .add("nadal_delta", nadal.delta)
        .add("nadal_applies", nadal.applies)
        .add_raw("warnings", json_strings(solved.warnings))
        .add_raw("patches", json_array(patches));
    std::cout << out.str() << '\n';
  } else {
    std::printf("status %s%s%s\n", contactgeom::status_name(contact.status),
                contact.message.empty() ? "" : ": ", contact.message.c_str());
    std::printf("vertical force %.6g N, lateral force %.6g N, approach %.4g mm\n",
                contact.vertical_force, contact.lateral_force, contact.approach * 1e3);
    if (!contact.patches.empty())
      std::printf(
          "Nadal      Y/Q %.4g%s against (tan d - mu)/(1 + mu tan d) = %.4g at d = %.4f rad: "
          "%s\n",
          nadal.Y_over_Q, args.creep ? " (creep forces included)" : " (normal forces only)",
          nadal.limit, nadal.delta,
          !nadal.applies   ? "not flank contact, the criterion does not apply"
          : nadal.exceeded ? "EXCEEDED: the flange may climb"
                           : "within the limit");
    int k = 0;
    for (const auto& p : contact.patches) {
      std::printf(
          "patch %d: N %.6g N, angle %.4f rad, O at y = %.3f mm on the rail, %.3f mm on the "
          "wheel (profile frames, + towards the field side)\n"
          "  area %.4g mm2, length %.3f mm, width %.3f mm, W1 %.3f mm, W2 %.3f mm, pmax %.1f MPa\n"
          "  SDEC a %.3f mm, b %.3f mm, psi %+.3f\n",
          ++k, p.normal_force, p.contact_angle, -p.y_rail * 1e3, -p.y_wheel * 1e3,
          p.measures.area * 1e6, p.measures.length * 1e3, p.measures.width * 1e3,
          p.measures.W1 * 1e3, p.measures.W2 * 1e3, p.pmax * 1e-6, p.sdec.a * 1e3, p.sdec.b * 1e3,
          p.sdec.psi);
      if (p.share < 1.0)
        std::printf(
            "  share %.3f of a blend of the one- and two-contact descriptions (forces "
            "above scaled by it)\n",
            p.share);
      if (args.creep) {
        const tangential::Creepages& c = creep[static_cast<std::size_t>(k - 1)].creepages;
        const tangential::CreepForces& f = creep[static_cast<std::size_t>(k - 1)].forces;
        std::printf("  creepages vx %.4g, vy %.4g, phi %.4g 1/m: Fx %.6g N, Fy %.6g N\n", c.vx,
                    c.vy, c.phi, f.Fx, f.Fy);
        if (args.tangential == "exact") {
          const tangential::WheelRailExactSolution e = exact_patch(
              args.in, solved.pair, p, args.in.creepages_at(solved.pair, p), args.exact);
          const tangential::ExactSolution& r = e.rolling;
          std::printf(
              "  exact theory (%d x %d elements, %s after %d iterations): N %.6g N, Fx %.6g N, "
              "Fy %.6g N, Mz %.6g N m\n"
              "    area %.4g mm2, %.1f %% adhesion, approach %.4g um\n",
              r.grid.nx, r.grid.ny, tangential::status_name(r.status), r.iterations, r.normal_force,
              r.forces.Fx, r.forces.Fy, r.forces.Mz.value_or(0.0), e.contact_area * 1e6,
              100.0 * e.adhesion_fraction, e.approach * 1e6);
        }
      }
    }
  }
  // A status other than ok is no usable answer: what was computed is printed, and the command
  // fails with exit status 3 (docs/cli.md).
  if (contact.status != contactgeom::WheelRailStatus::ok) {
    throw std::runtime_error(std::string("contact ") + contactgeom::status_name(contact.status) +
                             (contact.message.empty() ? "" : ": " + contact.message));
  }
}

}  // namespace

void add_contact_command(CLI::App& app) {
  auto args = std::make_shared<ContactArgs>();
  CLI::App* cmd = app.add_subcommand(
      "contact",
      "Contact patches of one wheel (the left one) of a wheelset on its rail.\n"
      "Geometry as in CONTACT's wheel/rail module: the wheel's flange back sits back-to-back/2\n"
      "from the track centre, the rail's gauge point gauge/2 (14 mm below the top of rail).\n"
      "The normal problem is Kik-Piotrowski's with virtual penetration; each patch is\n"
      "regularised into an SDEC (Liu, Fu & Bruni 2022, Eq. 13-14). Lateral positions are\n"
      "positive towards the gauge side. SI units.\n"
      "Example: wheelwear contact --wheel S1002 --rail 60E1 --dy 0.004 --load 55000 --json");
  add_contact_options(cmd, args->in);
  CLI::Option* creep = cmd->add_flag(
      "--creep", args->creep,
      "also solve the tangential problem with FASTSIM-SDEC (creepages --vx --vy --phi)");
  // The creepages enter only the tangential problem: given without it they would be ignored.
  for (const char* name : {"--vx", "--vy", "--phi", "--kinematic"})
    cmd->get_option(name)->needs(creep);
  cmd->add_option("--tangential", args->tangential,
                  "with --creep: fastsim-sdec (default) or exact, which adds per patch Kalker's\n"
                  "exact theory (Kalker 1990, as in Vollebregt's CONTACT): the undeformed\n"
                  "distance of wheel and rail, yaw included, sampled on --exact-grid N x N\n"
                  "elements over --exact-margin times the patch in its contact plane, the normal\n"
                  "problem at the patch's N, then steady rolling. JSON keys exact_status,\n"
                  "exact_N (the check: equals N), exact_Fx, exact_Fy, exact_Mz, exact_approach,\n"
                  "exact_area, exact_adhesion_fraction, exact_iterations, exact_nx, exact_ny;\n"
                  "Fx, Fy, Mz stay FASTSIM-SDEC's. About 20 ms per tread patch at 40 x 40, 0.15 s "
                  "at 80 x 80")
      ->check(CLI::IsMember({"fastsim-sdec", "exact"}))
      ->needs(creep)
      ->capture_default_str();
  args->exact_grid_option = cmd->add_option("--exact-grid", args->exact.grid,
                                            "--tangential exact: elements per side, 8 ... 400")
                                ->capture_default_str();
  args->exact_margin_option =
      cmd->add_option("--exact-margin", args->exact.margin,
                      "--tangential exact: the grid covers the Kik-Piotrowski patch times this,\n"
                      "1 ... 5; raise it when the exact contact area reaches the grid's border")
          ->capture_default_str();
  args->exact_radius_option =
      cmd->add_flag("--exact-radius-variation", args->exact.radius_variation, kRadiusVariationHelp);
  cmd->add_flag("--json", args->json, "print one JSON object with a list of patches");
  cmd->callback([args] { run_contact(*args); });
}

}  // namespace wheelwear::cli
