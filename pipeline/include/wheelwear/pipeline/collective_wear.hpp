#pragma once
/// One evaluation of a load collective on the current wheel profiles: every state through the
/// per-state kernel (state_kernel.hpp), then an ordered reduction to a wear rate across each
/// worn profile.

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "wheelwear/contactgeom/wheelset_table.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace wheelwear::pipeline {

/// The states an evaluation did not wear (StateOutcome::dropped), by the reason of each wheel
/// (WheelOutcome::drop_reason). `*_contacts` count wheel contacts with the reason; their
/// `*_weight` is the share of the running distance of the states that have at least one such
/// contact, each state counted once per reason. dropped_patches counts the contact patches of
/// both wheels of every dropped state, dropped_patches_weight the dropped states' share.
struct DroppedStates {
  int failed_contacts = 0;
  double failed_contacts_weight = 0.0;
  int climbing_contacts = 0;
  double climbing_contacts_weight = 0.0;
  int nadal_contacts = 0;
  double nadal_contacts_weight = 0.0;
  int load_jump_contacts = 0;
  double load_jump_contacts_weight = 0.0;
  int dropped_patches = 0;
  double dropped_patches_weight = 0.0;

  /// The counters with their names, in a fixed order (the results' and the JSON's names).
  std::vector<std::pair<std::string, double>> named() const;
};

/// The result of one evaluation.
struct CollectiveWear {
  /// Wear rate of each worn profile (ProfileLayout: one when the wheels share a profile, else
  /// left, right, or per wheelset left, right):
  /// the distance-weighted mean over the collective of the depth per metre running [m/m], on a
  /// kWearBin grid of the profile's arc length.
  std::vector<wear::WearDistribution> rate;
  /// Every state's outcome, in the collective's order; kept when the scene records state
  /// summaries or T gamma maps (the patches keep their cells for maps).
  std::vector<StateOutcome> states;
  DroppedStates dropped;            ///< states not worn, by reason
  std::size_t geometry_solves = 0;  ///< distinct wheel/rail contacts solved (after reuse)
  std::size_t table_contacts = 0;   ///< of them, interpolated in a contact table
  std::size_t patches = 0;          ///< patches solved and worn
  std::size_t table_patches = 0;    ///< of them, with totals from the book of tables ("best")
  /// Frictional work of the solved patches, each weighted by its state's share of the distance
  /// [J/m], and of it the work of the patches with totals from the book of tables.
  double frictional_work = 0.0, table_work = 0.0;
  /// Exact solves ("exact") that stopped at their iteration cap; their last iterate is used.
  std::size_t unconverged_patches = 0;
  /// Patches not solved because the contact model is hertz and they have no Hertz ellipse.
  std::size_t hertz_dropped = 0;
};

/// Which wheel profiles a run wears, and so which of them each state's wheels wear.
enum class ProfileLayout {
  shared,      ///< one profile, worn by both wheels of every state ("wheel")
  left_right,  ///< the left and the right wheel's ("wheel_left", "wheel_right")
  /// Each physical wheel of the vehicle's four wheelsets its own
  /// ("wheelsets/K/wheel_left|right", K = 1..4 in the forward order of travel): a vehicle run
  /// with wheels = "separate".
  per_wheelset,
};

/// The layout of `scene`'s run.
ProfileLayout profile_layout(const Scene& scene);
/// The number of profiles of `layout`: 1, 2 or 8.
std::size_t profile_count(ProfileLayout layout);
/// The profiles' names in the results file, in the order of their indices.
std::vector<std::string> profile_names(ProfileLayout layout);
/// The layout of `count` profiles (profile_count's inverse); InputError for another count.
ProfileLayout layout_of(std::size_t count);

/// The indices of the profiles the left and the right wheel (in travel) of `state` wear: a
/// reversed state's left wheel is the physical right one. Throws InputError for a state without
/// a wheelset (0..3) in the per_wheelset layout.
std::array<std::size_t, 2> worn_profiles(const WheelsetStateSpec& state, ProfileLayout layout);

/// The share of the running distance each state stands for (its weight over the total).
std::vector<double> state_shares(const std::vector<WheelsetStateSpec>& states);
/// state_shares of the scene's collective.
std::vector<double> state_shares(const Scene& scene);

/// The weight of each wheel case, state i's left (2i) and right (2i + 1) wheel, in the rate of
/// the profile it wears: its state's share over the summed shares of all wheel cases on that
/// profile, so that every profile's rate is the mean over the distance its wheel runs (half a
/// state each when both wheels share one profile; the state's share times four when each of
/// the four wheelsets wears its own).
std::vector<double> wheel_weights(const std::vector<WheelsetStateSpec>& states,
                                  ProfileLayout layout);
/// wheel_weights of the scene's collective.
std::vector<double> wheel_weights(const Scene& scene);

/// Adds the outcomes of `states` (in order, whatever order they were computed in) into `out`:
/// the rates of the worn profiles and the counts. The order of the sums is fixed, so results
/// are bit-identical for any number of threads or executors.
void reduce_states(const Scene& scene, const std::vector<WheelsetStateSpec>& specs,
                   const std::vector<StateOutcome>& states, CollectiveWear& out);
/// reduce_states of the scene's collective.
void reduce_states(const Scene& scene, const std::vector<StateOutcome>& states,
                   CollectiveWear& out);

/// Contact tables of the evaluated wheels, per pair of profiles: the key is the indices (left,
/// right) into the wheels of the evaluation (worn_profiles' numbering). A table must have been
/// built on exactly those profiles, in the kernel's track and with its contact options.
using ContactTables =
    std::map<std::array<std::size_t, 2>, std::shared_ptr<const contactgeom::WheelsetContactTable>>;

/// Outcomes of some of a collective's states, in the order they were asked for.
struct StateOutcomes {
  std::vector<StateOutcome> states;
  std::size_t geometry_solves = 0;  ///< distinct wheel/rail contacts solved for them
  /// Of them, interpolated in a contact table instead of solved (`tables` of outcomes()).
  std::size_t table_contacts = 0;
};

/// The fixed part of a run: the kernel (rail, track, models, law) and the collective.
/// Evaluations are deterministic: the same profiles give bit-identical results for any number
/// of threads.
class CollectiveEvaluator {
 public:
  /// Throws InputError on a bad scene. `reuse_geometry` solves the contact of states with the
  /// same position and loads once (the results are identical either way; off only to measure
  /// what the reuse saves).
  explicit CollectiveEvaluator(const Scene& scene, bool reuse_geometry = true);

  /// Evaluates the collective on `wheels` (profile_count(profile_layout(scene)) profiles, in
  /// profile_names' order).
  /// Every worn profile must have the taping line at y = 0 (as profiles from
  /// profiles::wheel_profile do). TBB-parallel over contacts and states.
  CollectiveWear evaluate(const std::vector<const profiles::Profile*>& wheels) const;
  /// Evaluates `specs` instead of the scene's collective (a vehicle run's states of the step).
  /// With `tables`, each state's contact is interpolated in its pair of profiles' table where
  /// StateKernel::contact answers from it, and solved elsewhere.
  CollectiveWear evaluate(const std::vector<const profiles::Profile*>& wheels,
                          const std::vector<WheelsetStateSpec>& specs,
                          const ContactTables* tables = nullptr) const;

  /// Which of `ranks` processes evaluates each state of `specs` when a step is spread over
  /// processes (distributed_run.hpp): whole contact geometries dealt out in turn, so that states
  /// sharing a geometry stay together (none is solved twice) and the dearer curve states are
  /// spread evenly. One rank (0 ... ranks - 1) per state.
  std::vector<int> owners(const std::vector<WheelsetStateSpec>& specs, int ranks) const;
  /// The outcomes of states `which` (indices into `specs`) on `wheels`, TBB-parallel; each is
  /// bit-identical to its outcome in evaluate(), whatever else is asked with it.
  /// `tables` as for evaluate().
  StateOutcomes outcomes(const std::vector<const profiles::Profile*>& wheels,
                         const std::vector<WheelsetStateSpec>& specs,
                         const std::vector<std::size_t>& which,
                         const ContactTables* tables = nullptr) const;
  /// The evaluation from the outcomes of every state of `specs`, in order (reduce_states).
  CollectiveWear reduce(const std::vector<const profiles::Profile*>& wheels,
                        const std::vector<WheelsetStateSpec>& specs, StateOutcomes all) const;

  const Scene& scene() const { return kernel_.scene(); }
  const StateKernel& kernel() const { return kernel_; }
  const profiles::Profile& rail() const { return kernel_.rail(); }
  /// The pair of `wheel` on the scene's rail in the scene's track.
  contactgeom::WheelRailPair pair(const profiles::Profile& wheel) const {
    return kernel_.pair(wheel);
  }

 private:
  void check_wheels(const std::vector<const profiles::Profile*>& wheels) const;

  StateKernel kernel_;
  bool reuse_geometry_ = true;
};

}  // namespace wheelwear::pipeline
