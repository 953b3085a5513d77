#include "contact_inputs.hpp"

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <utility>

#include "wheelwear/core/plausibility.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace wheelwear::cli {

void add_contact_options(CLI::App* cmd, ContactInputs& in) {
  cmd->add_option("--wheel", in.wheel, "S1002 or a wheel profile file")->capture_default_str();
  cmd->add_option("--rail", in.rail, "60E1 or a rail profile file")->capture_default_str();
  cmd->add_option("--dy", in.pose.dy,
                  "lateral shift of the wheelset [m], + towards this wheel's flange contact")
      ->required();
  cmd->add_option("--load", in.load, "vertical force on this wheel [N]")->required();
  cmd->add_option("--yaw", in.pose.yaw, "yaw angle [rad]")->capture_default_str();
  cmd->add_option("--roll", in.pose.roll, "roll of the wheel profile [rad], small")
      ->capture_default_str();
  cmd->add_option("--incl", in.inclination,
                  "rail inclination to apply: 1:N or a slope tan(theta) (1:40 = 0.025), none;\n"
                  "default 1:40 for 60E1, none for files (they usually carry theirs)");
  cmd->add_option("--gauge", in.gauge, "track gauge [m]")->capture_default_str();
  cmd->add_option("--back-to-back", in.back_to_back, "back-to-back distance [m]")
      ->capture_default_str();
  cmd->add_option("--wheel-radius", in.wheel_radius,
                  "nominal rolling radius at the taping line [m]; default half the diameter a\n"
                  "wheel file's header states, else 0.46");
  add_profile_file_options(cmd, in.files);
  cmd->add_option("--E", in.E, "Young's modulus of wheel and rail [Pa]")->capture_default_str();
  cmd->add_option("--nu", in.nu, "Poisson's ratio [-]")->capture_default_str();
  cmd->add_option("--strip-width", in.strip_width, "lateral sampling of the gap [m]")
      ->capture_default_str();
  cmd->add_option("--normal-method", in.normal_method,
                  "normal problem: hertz-calibrated (Kik-Piotrowski's strips with each patch's\n"
                  "virtual penetration from Hertz's ellipse for its curvature ratio) or\n"
                  "kik-piotrowski (one factor, --epsilon, for every patch)")
      ->check(CLI::IsMember(core::all_names(contactgeom::kNormalMethodNames)))
      ->capture_default_str();
  cmd->add_option("--contact-plane", in.contact_plane,
                  "the plane each patch's strips are solved in: initial-point (the tangent plane\n"
                  "at O, the gap the vertical one times its cosine) or weighted (CONTACT's planar\n"
                  "contact: inclined by the rail's contact angle averaged over the\n"
                  "interpenetration, both profiles turned into it; docs/normal-contact.md)")
      ->check(CLI::IsMember(core::all_names(contactgeom::kContactPlaneNames)))
      ->capture_default_str();
  cmd->add_option("--epsilon", in.epsilon,
                  "Kik-Piotrowski virtual penetration factor, with --normal-method kik-piotrowski")
      ->capture_default_str();
  cmd->add_option("--vx", in.creepages.vx, "longitudinal creepage at each patch's O [-]")
      ->capture_default_str();
  cmd->add_option("--vy", in.creepages.vy, "lateral creepage at each patch's O [-]")
      ->capture_default_str();
  cmd->add_option("--phi", in.creepages.phi, "spin creepage at each patch's O [1/m]")
      ->capture_default_str();
  cmd->add_option("--mu", in.mu, "friction coefficient [-]")->capture_default_str();
  cmd->add_option("--V", in.motion.speed, "forward speed of the wheelset [m/s]")
      ->capture_default_str();
  CLI::Option* kinematic =
      cmd->add_flag("--kinematic", in.kinematic,
                    "creepages at each O from the wheelset's motion (--V, --lateral-velocity,\n"
                    "--yaw-rate, --omega and --yaw) instead of --vx --vy --phi");
  // The motion enters only the kinematic creepages: given without them it would be ignored.
  cmd->add_option("--lateral-velocity", in.motion.lateral_velocity,
                  "lateral velocity [m/s], + towards this wheel's flange")
      ->needs(kinematic)
      ->capture_default_str();
  cmd->add_option("--yaw-rate", in.motion.yaw_rate, "yaw rate [rad/s], + when this wheel leads")
      ->needs(kinematic)
      ->capture_default_str();
  cmd->add_option("--omega", in.motion.angular_velocity,
                  "wheel spin about the axle [rad/s]; 0: free rolling on the nominal radius")
      ->needs(kinematic)
      ->capture_default_str();
  cmd->add_option("--slip-point", in.slip_point,
                  "with --kinematic: where the lateral creepage is the wheel's rigid slip:\n"
                  "axle-plane (projected onto the contact plane at O, the multibody codes'\n"
                  "convention) or contact-point (along the contact plane where a yawed wheel\n"
                  "touches, ahead of its axle: 1/cos^2 of the contact angle times the former)")
      ->check(CLI::IsMember(core::all_names(contactgeom::kSlipPointNames)))
      ->needs(kinematic)
      ->capture_default_str();
}

tangential::Creepages ContactInputs::creepages_at(const contactgeom::WheelRailPair& pair,
                                                  const contactgeom::WheelRailPatch& patch) const {
  if (!kinematic) return creepages;
  contactgeom::WheelsetMotion at = motion;
  at.slip_point = *core::value_named(contactgeom::kSlipPointNames, slip_point);
  return contactgeom::kinematic_creepages(patch, pose, at, pair.wheel_radius);
}

namespace {

// Refuses the impossible typed inputs (unit mistakes, mostly) before any profile is read and
// returns the warnings for the implausible ones.
std::vector<std::string> check_plausibility(const ContactInputs& in) {
  std::vector<std::string> warnings;
  core::check_plausible(core::kYawLimit, "--yaw", in.pose.yaw, warnings);
  core::check_plausible(core::kWheelLoadLimit, "--load", in.load, warnings);
  core::check_plausible(core::kSpeedLimit, "--V", in.motion.speed, warnings);
  core::check_plausible(core::kFrictionLimit, "--mu", in.mu, warnings);
  core::check_plausible(core::kCreepageLimit, "--vx", in.creepages.vx, warnings);
  core::check_plausible(core::kCreepageLimit, "--vy", in.creepages.vy, warnings);
  return warnings;
}

}  // namespace

SolvedContact solve_contact(const ContactInputs& in) {
  std::vector<std::string> warnings = check_plausibility(in);
  in.files.refuse_for_standard(in.wheel == "S1002", in.rail == "60E1" || in.rail == "UIC60");
  const profiles::ProfileFileOptions files = in.files.options();
  // The loaders' warnings (an origin the rule contradicts, a rail without a gauge point or
  // probably mirrored) belong to this contact: a user sees them here or not at all.
  profiles::Profile wheel = profiles::wheel_profile(in.wheel, in.wheel_radius, files, &warnings);
  const std::optional<double> inclination =
      in.inclination.empty() ? std::nullopt
                             : std::optional(core::parse_inclination(in.inclination, "--incl"));
  profiles::Profile rail = profiles::rail_profile(in.rail, inclination, files, &warnings);
  SolvedContact out{
      contactgeom::WheelRailPair(std::move(wheel), std::move(rail)), {}, std::move(warnings)};
  out.pair.gauge = in.gauge;
  out.pair.back_to_back = in.back_to_back;
  out.pair.wheel_radius = out.pair.wheel.info().nominal_radius;
  out.pair.youngs_modulus = in.E;
  out.pair.poisson = in.nu;
  contactgeom::WheelRailOptions options;
  options.strip_width = in.strip_width;
  options.kp.epsilon = in.epsilon;
  options.kp.penetration = *core::value_named(contactgeom::kNormalMethodNames, in.normal_method);
  options.contact_plane = *core::value_named(contactgeom::kContactPlaneNames, in.contact_plane);
  out.contact = contactgeom::solve_wheel_rail(out.pair, in.pose, in.load, options);
  if (auto warning =
          core::plausibility_warning(core::kApproachLimit, "approach", out.contact.approach))
    out.warnings.push_back(*warning);
  return out;
}

}  // namespace wheelwear::cli
