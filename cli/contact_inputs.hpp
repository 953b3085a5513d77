#pragma once
// The inputs `wheelwear contact` and `wheelwear wear` share: profiles, track, wheelset
// position, load, material, and the creepages at each patch's initial contact point.

#include <optional>
#include <string>
#include <vector>

#include "profile_file_options.hpp"
#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace CLI {
class App;
}

namespace wheelwear::cli {

struct ContactInputs {
  std::string wheel = "S1002";
  std::string rail = "60E1";
  contactgeom::WheelsetPose pose;
  double load = 0.0;
  std::string inclination;  ///< --incl as given (core::parse_inclination); empty: the default
  double gauge = 1.435;
  double back_to_back = 1.360;
  /// Nominal rolling radius [m]; default the wheel file header's diameter / 2, else 0.46.
  std::optional<double> wheel_radius;
  ProfileFileArgs files;  // how profile files are read
  double E = 200e9;
  double nu = 0.25;
  double strip_width = 0.1e-3;
  std::string normal_method = "hertz-calibrated";  // a contactgeom::kNormalMethodNames name
  std::string contact_plane = "initial-point";     // a contactgeom::kContactPlaneNames name
  double epsilon = 0.55;
  tangential::Creepages creepages;
  bool kinematic = false;                 // creepages from the motion below instead
  std::string slip_point = "axle-plane";  // a contactgeom::kSlipPointNames name
  contactgeom::WheelsetMotion motion{20.0, 0.0, 0.0, 0.0, 0.75};
  double mu = 0.3;

  /// The creepages at O of `patch` of `pair`: given directly, or from the wheelset's motion
  /// (with the pair's nominal radius).
  tangential::Creepages creepages_at(const contactgeom::WheelRailPair& pair,
                                     const contactgeom::WheelRailPatch& patch) const;

  /// Combined shear modulus G = E / (2 (1 + nu)) [Pa] and nu.
  tangential::Material material() const { return {E / (2.0 * (1.0 + nu)), nu}; }
};

/// Adds the shared options to `cmd`, writing into `inputs`.
void add_contact_options(CLI::App* cmd, ContactInputs& inputs);

/// The wheel/rail pair the inputs describe, and its contact; throws on bad input and on an
/// impossible one (core/plausibility.hpp). `warnings` names the implausible inputs and approach.
struct SolvedContact {
  contactgeom::WheelRailPair pair;
  contactgeom::WheelRailContact contact;
  std::vector<std::string> warnings;
};
SolvedContact solve_contact(const ContactInputs& inputs);

}  // namespace wheelwear::cli
