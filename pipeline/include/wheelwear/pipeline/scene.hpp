#pragma once
/// A wear-evolution scene: the wheel, the rail, the track, the contact and wear models, the load
/// collective and the run's step control, read from a TOML file with unit-suffixed keys.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/pipeline/cosimulation_hook.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/track_irregularities.hpp"
#include "wheelwear/vehicle/vehicle.hpp"

namespace wheelwear::pipeline {

/// One state of the wheelset in the load collective: where it runs, how it is loaded, how fast,
/// and which share of the running distance it stands for. Signs: `dy` and `yaw` as
/// contactgeom::WheelsetState (+ towards the left wheel's flange); a curve of positive radius
/// turns right, so that the left wheel runs on the outer rail.
struct WheelsetStateSpec {
  std::string label;        ///< free text (e.g. the track section)
  double dy = 0.0;          ///< lateral shift [m], + to the left
  double yaw = 0.0;         ///< yaw angle [rad], + counter-clockwise seen from above (heads left)
  double load_left = 0.0;   ///< vertical force on the left wheel [N], > 0
  double load_right = 0.0;  ///< vertical force on the right wheel [N], > 0
  /// Lateral force of the left rail on its wheel [N], + towards the track centre (the same
  /// number as the wheel's force on its rail, + outwards).
  std::optional<double> lateral_force_left;
  std::optional<double> lateral_force_right;  ///< same for the right wheel [N]
  double speed = 0.0;                         ///< forward speed [m/s], > 0
  double curve_radius = 0.0;      ///< [m]; 0 on tangent track, > 0 right-hand, < 0 left-hand
  double lateral_velocity = 0.0;  ///< dy/dt [m/s], + to the left
  /// Axle angular velocity [rad/s], > 0; unset: rolling on the nominal radius, V / r0. A
  /// vehicle model's states give the free-rolling spin it solved for.
  std::optional<double> angular_velocity;
  double yaw_rate = 0.0;  ///< d(yaw)/dt relative to the track [rad/s], + counter-clockwise
  /// Wheelset roll [rad], + when the left wheel goes down, as the state's source computed it.
  /// Recorded only: the contact is a constraint, so the kernel's roll follows from the
  /// geometry of both wheels (its value is in the state summaries).
  std::optional<double> roll;
  /// Coefficients of friction on the rail top and on the gauge face (contactgeom::RailFriction);
  /// unset: the scene's.
  std::optional<double> friction, friction_flange;
  /// Creepages given directly (each wheel in its own frame, + y towards the gauge side); when
  /// absent they follow from the kinematics at every patch's O.
  std::optional<tangential::Creepages> creepages_left, creepages_right;
  double weight = 1.0;  ///< share of the running distance (normalised over the collective)
  /// The physical wheelset whose wheels this state wears when a run wears each wheelset's own
  /// profiles (ProfileLayout::per_wheelset): 0..3, numbered in the order of travel of the route's
  /// forward direction; -1: not given (the run's shared or left/right profiles).
  int wheelset = -1;
  /// The vehicle runs the route backwards: the wheel on the left in travel is the physical
  /// right wheel, whose profile it wears where the wheels have profiles of their own.
  bool reversed = false;
  int line = 0;  ///< line in the scene or the collective file (for messages)
};

/// How the tangential problem of each patch is solved.
enum class TangentialMethod {
  fastsim,  ///< FASTSIM with the contact model's region and flexibilities
  /// Inside the book of tables each SDEC patch's forces, spin moment and frictional work are
  /// Kalker's exact theory's, spread over the patch as FASTSIM-SDEC spreads them
  /// (wheelwear/tangential/table_correction.hpp); FASTSIM-SDEC alone outside the table. Needs model
  /// sdec.
  best,
  /// Kalker's exact theory on the SDEC patch (exact_sdec on grid_nx x grid_ny elements,
  /// tangential/exact/exact_fields.hpp): the reference, at milliseconds per patch. Needs model
  /// sdec.
  exact,
};

/// Which wheelsets of the vehicle wear the profile(s).
enum class WheelsetSelection {
  all,      ///< all four
  leading,  ///< the leading wheelset of each bogie (the first and third in order of travel)
};

/// Which way the vehicle runs its route.
enum class RunningDirection {
  forward,  ///< from the route's start to its end
  reverse,  ///< from its end to its start (vehicle::reversed): the last wheelset leads
  both,     ///< half the distance each way
};

/// Where the track irregularities of the time-domain pieces come from.
enum class IrregularitySource {
  none,       ///< ideal track: the vehicle runs centred on tangents
  erri_low,   ///< generated from ERRI B176 low level, seeded per section
  erri_high,  ///< generated from ERRI B176 high level, seeded per section
  file,       ///< measured, one record along the whole route (TimeDomainKeys::measured)
};

/// How a vehicle run simulates its route's tangents and transitions in time ([time_domain];
/// docs/vehicle.md, "In the run"). Each tangent is represented by a stretch of
/// `tangent_length` at its middle, each transition whole; a stretch is run from the
/// quasi-static state `run_in` before it, and every wheelset is sampled every
/// `sample_distance` while it runs through the stretch.
struct TimeDomainKeys {
  bool enabled = true;  ///< false: tangents and transitions quasi-statically, as curves
  IrregularitySource irregularities = IrregularitySource::erri_low;
  vehicle::TrackIrregularities measured;  ///< the record when irregularities is file
  std::string irregularity_file;          ///< its resolved path, else empty
  std::uint64_t seed = 1;                 ///< base seed; each section draws its own from it
  /// Generated irregularities drawn anew at every solve of the vehicle (seeded per section and
  /// per wear step), so that over a run's solves the tangents' wear averages over many
  /// stretches of the random track; false: the same track at every solve.
  bool redraw = false;
  double tangent_length = 200.0;  ///< simulated stretch of each tangent [m]
  /// Transitions simulated in time, whole; false: each a quasi-static condition at its
  /// midpoint's curvature and cant, as with enabled = false.
  bool simulate_transitions = true;
  double run_in = 50.0;          ///< run before a stretch's first sample [m]
  double sample_distance = 0.5;  ///< longest distance between two samples [m]
};

/// A vehicle on a route, whose own steady states make each step's collective
/// (vehicle_run.hpp).
struct VehicleRun {
  vehicle::Vehicle vehicle;
  std::string vehicle_file;  ///< resolved path; empty: the built-in vehicle
  vehicle::Route route;
  std::string route_file;  ///< resolved path; empty: the built-in route
  WheelsetSelection wheelsets = WheelsetSelection::all;
  RunningDirection direction = RunningDirection::forward;
  /// The vehicle is solved again once the deepest wear since its last solve reaches this [m];
  /// 0: at every step.
  double resolve_depth = 0.05e-3;
  /// Interpolate the wheels' contacts from a look-up table built on each solve's profiles
  /// (contactgeom::WheelsetContactTable) rather than solve every one directly.
  bool contact_table = true;
  /// At a step where the vehicle was solved, its states' wear is evaluated on the same tables
  /// (with contact_table): each state's contact is the one its balance or motion was computed
  /// with where that was on the tables (not where a balance was finished on direct contacts or
  /// kept from earlier profiles), at a fraction of a direct solve's cost. Direct solves
  /// elsewhere, where a table does not answer, and with the hertz contact model.
  bool wear_from_table = true;
  /// Tangents and transitions simulated in time with the track's irregularities.
  TimeDomainKeys time_domain;
  /// The vehicle's linear critical speed on tangent track at each solve, on its profiles
  /// (vehicle::vehicle_critical_speed with the run's contact models).
  bool critical_speed = true;

  /// The wheelsets (0..3, in order of travel) that wear the profile(s); in the reversed
  /// direction, travel position k is the physical wheelset 3 - k.
  std::vector<int> worn_wheelsets() const;
};

/// The in-service limits the run watches ([limits]); unset values are EN 15313's for the wheel's
/// nominal diameter (profiles::in_service_limits).
struct LimitKeys {
  std::optional<double> Sd_min;  ///< [m]
  std::optional<double> Sh_max;  ///< [m]
  std::optional<double> qR_min;  ///< [m]
  bool stop = false;             ///< end the run at the first step that reaches a limit

  /// The limits for a wheel of nominal diameter `diameter` [m]; below the standard's 0.33 m the
  /// unset ones are NaN, which no profile reaches.
  profiles::WheelLimits resolve(double diameter) const;
};

/// Steps a scene may ask for (`[run] distance_m` over `step_distance_m`): more are refused,
/// more than kStepsWarning warned about. Each step re-evaluates the whole collective and writes
/// a group of the results file.
inline constexpr double kStepsLimit = 1e5;
inline constexpr double kStepsWarning = 1e4;

/// A file a scene names (a profile, the collective, a wear table, the vehicle, the route, a
/// measured irregularity record), as it was read.
struct SceneInput {
  std::string key;      ///< the scene key that names it, e.g. "wheel.profile"
  std::string path;     ///< resolved from the scene's folder
  std::string content;  ///< its bytes
};

/// Everything a run needs. Defaults are those of a scene file that leaves a key out
/// (docs/scenes.md), not the built-in scene's (data/scenes/default.toml).
struct Scene {
  std::string title;
  std::string wheel_profile = "S1002";  ///< standard name or resolved file path
  /// Nominal rolling radius at the taping line [m]; default half the diameter a wheel file's
  /// header states, else profiles::kDefaultWheelRadius.
  std::optional<double> wheel_radius;
  profiles::ProfileFileOptions wheel_file;  ///< how a wheel file is read (origin, ...)
  std::string rail_profile = "60E1";
  profiles::ProfileFileOptions rail_file;  ///< how a rail file is read
  std::optional<double> rail_inclination;  ///< [rad]; default per profile_source.hpp
  double gauge = 1.435;                    ///< [m]
  double back_to_back = 1.360;             ///< [m]
  double lateral_arm = 0.75;               ///< wheelset centre to contact [m]
  double youngs_modulus = 200e9;           ///< [Pa]
  double poisson = 0.25;                   ///< [-]
  tangential::ContactModel model = tangential::ContactModel::sdec;
  double friction = 0.3;  ///< on the rail top [-], > 0
  /// On the gauge face (patches at contact angles from contactgeom::kFlangeContactAngle) [-];
  /// unset: the rail top's.
  std::optional<double> friction_flange;
  int grid_nx = 30;
  int grid_ny = 30;
  tangential::FastsimScheme scheme = tangential::FastsimScheme::kalker;
  TangentialMethod tangential = TangentialMethod::fastsim;
  double strip_width = 0.2e-3;  ///< [m]
  /// How the normal problem chooses its virtual penetration: Kik-Piotrowski's fixed epsilon
  /// (virtual_penetration), or Hertz-calibrated per patch.
  contactgeom::KpPenetration normal_method = contactgeom::KpPenetration::hertz_calibrated;
  /// The plane each patch's strips are solved in: at O, or CONTACT's weighted plane.
  contactgeom::ContactPlane contact_plane = contactgeom::ContactPlane::initial_point;
  /// Where a patch's lateral creepage is the wheel's rigid slip: in the axle's vertical plane
  /// (projected) or at the contact point ahead of a yawed axle (contactgeom::SlipPoint).
  contactgeom::SlipPoint slip_point = contactgeom::SlipPoint::axle_plane;
  double virtual_penetration = 0.55;  ///< Kik-Piotrowski epsilon [-], with kik-piotrowski
  /// A contact steeper than this is flange climb, its state not worn [rad]
  /// (contactgeom::WheelRailOptions::max_contact_angle).
  double max_contact_angle = 1.35;
  std::string wear_law = "usfd";   ///< usfd or archard
  std::string wear_law_table;      ///< resolved path of the user's table, empty: built-in
  std::string wear_law_text;       ///< that table's content, read when the scene was parsed
  double distance = 100e3;         ///< running distance of the run [m]
  double step_distance = 5e3;      ///< longest step [m]
  double max_depth_step = 0.1e-3;  ///< deepest wear increment of one step [m]
  double smoothing_length = 2e-3;  ///< smoothing of a step's depth along the profile [m]
  bool separate_wheels = false;    ///< evolve left and right profiles separately
  LimitKeys limits;                ///< in-service limits, and whether reaching one stops
  bool state_summaries = true;     ///< write per-state summaries
  bool tgamma_maps = false;        ///< write per-cell T gamma maps of every contact
  /// The hand-written collective; empty when the vehicle makes it (vehicle_run).
  std::vector<WheelsetStateSpec> states;
  /// The vehicle and its route ([vehicle] and [route]), instead of a hand-written collective.
  std::optional<VehicleRun> vehicle_run;
  /// Every file the scene names, read once when it was parsed: what the run depends on beyond
  /// the scene's text, stored in its results file so that a resumed run uses the same inputs.
  std::vector<SceneInput> inputs;
  /// What the scene's reader noticed that does not stop a run (e.g. many steps); a run passes
  /// them to RunOptions::warning.
  std::vector<std::string> warnings;
  /// An outside program that makes every step's collective ([hook]), instead of the above.
  std::optional<CosimulationHook> hook;
};

/// Reads a file named in a scene (a profile, the collective, a wear table, ...): its bytes, or
/// none when there is no such file.
using SceneFileReader = std::function<std::optional<std::string>(const std::filesystem::path&)>;

/// The reader of files on disk (a regular file's bytes, else none).
std::optional<std::string> read_scene_file_from_disk(const std::filesystem::path& path);

/// What a scene is read for: a wear run needs its states' source ([load_collective], [vehicle]
/// or [hook]); a vehicle solve alone (`curving`, `route`) takes the profiles, track and contact
/// model of any scene and the built-in coach and route where it names none.
enum class SceneUse { wear_run, vehicle_solve };

/// Parses a scene. Relative file names are taken from `base_directory`; `read` reads every file
/// the scene names (default: from disk), each once, and the scene keeps them (Scene::inputs).
/// Every problem (TOML syntax, unknown key, wrong type,
/// a value out of range, a missing file) throws InputError naming the key and its line, before
/// any work starts.
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& base_directory,
                  const SceneFileReader& read = {}, SceneUse use = SceneUse::wear_run);

/// Reads and parses the scene file `path`.
Scene load_scene(const std::filesystem::path& path, SceneUse use = SceneUse::wear_run);

/// The built-in default scene's text (data/scenes/default.toml): the built-in vehicle on the
/// built-in route.
std::string_view default_scene_text();
/// The built-in default scene.
Scene default_scene();

/// The frozen-collective scene's text (data/scenes/frozen_collective.toml): 1000 hand-set
/// wheelset states, the built-in scene before the vehicle's own states replaced it.
std::string_view frozen_collective_text();
/// Its load collective (data/scenes/frozen_collective.csv).
std::string_view frozen_collective_states_text();
/// The frozen-collective scene, with its collective.
Scene frozen_collective_scene();

}  // namespace wheelwear::pipeline
