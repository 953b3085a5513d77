#pragma once
// The Kik-Piotrowski patches of one wheel on its rail at one rigid approach: the contact
// regions of the sampled gap, their strips and the description of each patch (internal to the
// wheel/rail contact).

#include <cstddef>
#include <limits>
#include <vector>

#include "gap_run.hpp"
#include "strip_plane.hpp"
#include "wheel_rail_gap.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom::detail {

// Rises of the gap smaller than this between two minima [m] are ripples of a sampled or
// measured profile within one contact, never a cut.
constexpr double kBasinRipple = 0.5e-6;
// Where the gap rises between two minima, r is the rise above the shallower minimum over that
// minimum's depth below the reference approach (r = 1 at the approach where two regions join).
// Below kMergedBelow the basins are one contact; above kSeparateAbove two; in between the contact
// is blended from both descriptions with shares that follow r smoothly. On S1002/60E1, a shallow
// dip within CONTACT's single tread patch has r = 0.05; two-point tread and flange-root contacts
// have r = 0.6 or more.
constexpr double kMergedBelow = 0.3;
constexpr double kSeparateAbove = 0.6;

// Runs of samples where the surfaces interpenetrate, each cut into one contact per basin of the
// gap where the rise between basins is deep enough (see r above): it is cut at the rise's top
// (between samples: Run::cut_before, cut_after), and each piece is a contact of its own with its
// own initial contact point and contact angle (two-point contact of tread and flange). Each
// run's share is 1 unless it belongs to a blend.
//
// r is taken at the rigid approach `reference`, the runs are those at max(approach, reference):
// for a fixed reference the description is fixed below it, and above it changes only where
// regions join, which they do as two contacts (r > 1), so every contact's load rises
// continuously with the approach and the load solve has one root. A basin not reached at
// `reference` is a contact of its own; reference = kEveryRise cuts at every rise (two contacts
// wherever there are two basins). The load solve takes the reference from that all-cut solution
// (solve_blend in wheel_rail_load.cpp), so that the shares follow the profiles' positions
// continuously too: taking r at the approach being tried made the load non-monotone in it where the
// merged and the split description carry unlike loads (the Hertz-calibrated method), and the root
// found switched.
std::vector<Run> interpenetration_runs(const GapSamples& g, double approach, double reference);

// The regions of the sampled gap below the rigid approach, uncut, each with its gap minimum.
std::vector<Run> interpenetration_regions(const GapSamples& g, double approach);

// The least reference approach at which every rise of the gap within the runs at `approach` is
// no cut at all (r <= kMergedBelow); -inf where there is no rise.
double merged_from(const GapSamples& g, double approach);

// The reference that cuts at every rise.
constexpr double kEveryRise = -std::numeric_limits<double>::infinity();

// True when the runs at `approach` with their shares taken there are those of kEveryRise: every
// rise is as firm a cut at this approach as it can be (r >= kSeparateAbove).
bool splits_at_every_rise(const GapSamples& g, double approach);

// The vertical and lateral force of one patch [N].
struct PatchForces {
  double vertical = 0.0;
  double lateral = 0.0;
};

// The forces of a Kik-Piotrowski patch solved on strips_of() `strips`: each strip's line load
// projected with the contact direction at its centre (between the samples about it), sum q(s)
// ds (cos gamma(s), sin gamma(s)). One angle for
// the whole patch would project a patch spread over a curved rail wrongly (a patch over the
// flange root and the flank misses the load by half with the flank's angle).
PatchForces strip_forces(const WheelRailGap& geometry, const GapSamples& g,
                         SampleDirections& directions, const RunStrips& strips,
                         const KpPatch& patch);

// The details of one Kik-Piotrowski patch solved on `strips` at the rigid approach `approach`
// (vertical, the datum of g.h), with forces `forces` (strip_forces); `share` its weight in a
// blend (Run::share).
WheelRailPatch describe_patch(const WheelRailGap& geometry, const GapSamples& g,
                              const KpPatch& patch, const RunStrips& strips, double approach,
                              PatchForces forces, double E_star, double share = 1.0);

// The contact angle at the patch's O: the rail's there, or with Kik & Piotrowski's reduction
// the plane's (O lies within a strip of the run's gap minimum).
double patch_contact_angle(const WheelRailGap& geometry, const GapSamples& g,
                           const RunStrips& strips, const KpPatch& patch);

// Scales the patch's pressures and load by its share of a blend.
void scale_loads(KpPatch& patch, double share);

// Patches and their total forces at one rigid approach.
struct PatchSet {
  std::vector<WheelRailPatch> patches;  // empty unless described
  double vertical = 0.0;                // sum of the patches' strip_forces [N]
  double lateral = 0.0;                 // sum of the patches' strip_forces [N]
  double steepest = 0.0;                // largest |contact angle| at O [rad]
};

// Every patch at the rigid approach `approach` (same datum as g.h) of interpenetration_runs(g,
// approach, reference); `describe`: with the patches' details, else the forces only.
// `directions` holds g's contact directions looked up so far.
PatchSet patches_at(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    double approach, double reference, double E_star,
                    const WheelRailOptions& options, bool describe);

}  // namespace wheelwear::contactgeom::detail
