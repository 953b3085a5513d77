#pragma once
// The Kik-Piotrowski patches of one wheel on its rail at one rigid approach: the contact
// regions of the sampled gap, their strips and the description of each patch (internal to the
// wheel/rail contact).

#include <cstddef>
#include <vector>

#include "wheel_rail_gap.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom::detail {

// One run of samples where the surfaces interpenetrate at the rigid approach.
struct Run {
  std::size_t first = 0, last = 0;  // sample indices, inclusive
  double y_O = 0.0, h_O = 0.0;      // gap minimum (parabola through the lowest sample)
};

// The run of samples [first, last] with its refined gap minimum.
Run with_minimum(const GapSamples& g, std::size_t first, std::size_t last);

// Runs of samples where the surfaces interpenetrate at the rigid approach. A run whose virtual
// interpenetration (Kik-Piotrowski: the gap below h_O + eps (approach - h_O)) falls apart into
// separate pieces is cut at the highest gap between them: each piece is a contact of its own,
// with its own initial contact point and contact angle (two-point contact of tread and flange).
std::vector<Run> interpenetration_runs(const GapSamples& g, double approach, double epsilon);

// The strips of samples [first, last] for the Kik-Piotrowski solver, in increasing s (towards
// the gauge side, -y in the profile frame), s measured from y_O along the contact plane, whose
// cosine is c. h and ax hold the strips' values (the result views them).
GapStrips strips_of(const WheelRailGap& geometry, const GapSamples& g, std::size_t first,
                    std::size_t last, double y_O, double c, std::vector<double>& h,
                    std::vector<double>& ax);

// The vertical and lateral force of one patch [N].
struct PatchForces {
  double vertical = 0.0;
  double lateral = 0.0;
};

// The contact direction at the gap's samples, each looked up on the rail once per sampling:
// the load iterations project mostly the same strips at every approach they try.
class SampleDirections {
 public:
  // Forgets every direction: the samples are those of a new sampling, `samples` of them.
  void reset(std::size_t samples) {
    known_.assign(samples, 0);
    direction_.resize(samples);
  }
  // The rail's contact direction at sample j (rail-frame y = g.y[j]), from its arc length there.
  ContactDirection at(const WheelRailGap& geometry, const GapSamples& g, std::size_t j) {
    if (!known_[j]) {
      direction_[j] = geometry.rail_direction(g.s_rail[j]);
      known_[j] = 1;
    }
    return direction_[j];
  }

 private:
  std::vector<unsigned char> known_;
  std::vector<ContactDirection> direction_;
};

// The forces of a Kik-Piotrowski patch solved on `strips`, the strips_of() of samples
// [first, last]: each strip's line load projected with the contact angle gamma at its centre,
// the sample last - (s - s_first)/ds, sum q(s) ds (cos gamma(s), sin gamma(s)). One angle for
// the whole patch would project a patch spread over a curved rail wrongly (a patch over the
// flange root and the flank misses the load by half with the flank's angle).
PatchForces strip_forces(const WheelRailGap& geometry, const GapSamples& g,
                         SampleDirections& directions, const GapStrips& strips, std::size_t last,
                         const KpPatch& patch);

// The details of one Kik-Piotrowski patch of the region whose gap minimum lies at rail-frame
// y_O, with contact angle `angle` and forces `forces` (strip_forces); its strips' s is measured
// from y_O along the contact plane.
WheelRailPatch describe_patch(const WheelRailGap& geometry, const KpPatch& patch, double y_O_run,
                              double angle, PatchForces forces, double E_star);

// Patches and their total forces at one rigid approach.
struct PatchSet {
  std::vector<WheelRailPatch> patches;  // empty unless described
  double vertical = 0.0;                // sum of the patches' strip_forces [N]
  double lateral = 0.0;                 // sum of the patches' strip_forces [N]
  double steepest = 0.0;                // largest |contact angle| at O [rad]
};

// Every patch at the rigid approach `approach` (same datum as g.h); `describe`: with the patches'
// details, else the forces only. `directions` holds g's contact directions looked up so far.
PatchSet patches_at(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    double approach, double E_star, const WheelRailOptions& options, bool describe);

}  // namespace wheelwear::contactgeom::detail
