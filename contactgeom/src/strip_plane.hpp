#pragma once
// The strips of one run of the wheel/rail gap for the Kik-Piotrowski solver, in the planar
// contact they are solved in (internal to the wheel/rail contact).

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "gap_run.hpp"
#include "wheel_rail_gap.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom::detail {

// The contact direction and height of the rail at the gap's samples, each looked up once per
// sampling: the load iterations project mostly the same strips at every approach they try.
class SampleDirections {
 public:
  // Forgets every direction: the samples are those of a new sampling, `samples` of them.
  void reset(std::size_t samples) {
    known_.assign(samples, 0);
    direction_.resize(samples);
    height_.resize(samples);
    angle_.resize(samples);
  }
  // The rail's contact direction at sample j (rail-frame y = g.y[j]), from its arc length there.
  ContactDirection at(const WheelRailGap& geometry, const GapSamples& g, std::size_t j) {
    look_up(geometry, g, j);
    return direction_[j];
  }
  // The rail's height z at sample j (the profile's z, + down) [m].
  double rail_z(const WheelRailGap& geometry, const GapSamples& g, std::size_t j) {
    look_up(geometry, g, j);
    return height_[j];
  }
  // The rail's contact angle at sample j [rad].
  double angle(const WheelRailGap& geometry, const GapSamples& g, std::size_t j) {
    look_up(geometry, g, j);
    return angle_[j];
  }

 private:
  void look_up(const WheelRailGap& geometry, const GapSamples& g, std::size_t j) {
    if (known_[j]) return;
    direction_[j] = geometry.rail_direction(g.s_rail[j]);
    height_[j] = geometry.pair().rail.position(g.s_rail[j])[1];
    angle_[j] = std::atan2(direction_[j].sin, direction_[j].cos);
    known_[j] = 1;
  }
  std::vector<unsigned char> known_;
  std::vector<ContactDirection> direction_;
  std::vector<double> height_, angle_;
};

// The planar contact a run's strips are solved in, and where each strip lies on the rail.
struct StripPlane {
  double angle = 0.0;  // inclination of the plane to the track plane [rad], as contact angles
  double cos = 1.0;    // its cosine
  // CONTACT's contact angle over the run: the rail's, weighted by the rigid penetration to the
  // power 5/2 (the plane's angle where `weighted`) [rad].
  double weighted_angle = 0.0;
  // Per strip (in increasing s): its centre's position in samples, fractional where the plane
  // is weighted (strips_of() resamples the run there).
  std::span<const double> sample;
  double s_first = 0.0, ds = 0.0;  // the strips' s (as GapStrips)
  bool weighted = false;           // CONTACT's weighted plane (strips_of()), else O's
  double y_O = 0.0;                // the run's gap minimum, s = 0 [m]

  // The fractional sample at plane coordinate s (clamped to the strips).
  double sample_at(double s) const;
  // The rail-frame y at plane coordinate s.
  double y_at(const GapSamples& g, double s) const;
};

// Buffers strips_of() fills (the strips it returns view them).
struct StripBuffers {
  std::vector<double> h, ax, sample;
  std::vector<double> t, hs, axs, tw, nw;  // per sample of the run: rail's t, h, A; wheel's t, n
};

// The strips of one run and their plane.
struct RunStrips {
  GapStrips strips;
  StripPlane plane;
};

// CONTACT's contact angle of `run` at the rigid approach `approach`: the rail's, weighted by the
// rigid penetration to the power 5/2 (StripPlane::weighted_angle); `fallback` where nothing
// interpenetrates.
double weighted_plane_angle(const WheelRailGap& geometry, const GapSamples& g,
                            SampleDirections& directions, const Run& run, double approach,
                            double fallback);

// The strips of `run` for the Kik-Piotrowski solver at the rigid approach `approach` (vertical,
// the datum of g.h), in increasing s (towards the gauge side, -y in the profile frame), s
// measured from run.y_O along the plane.
//
// The plane: with `weighted`, as CONTACT's planar contact takes it (Vollebregt's wheel/rail
// module, option D = 2): inclined by the mean of the rail's contact angle over the run's
// interpenetration, weighted by the rigid penetration to the power 5/2 (the penetration's
// square integrated along x under the parabola of the wheel's sag). The rail's and the wheel's
// points are turned into that plane, the wheel moved down by the approach, and each sample's
// gap is the distance between them along the plane's normal at the rail point's place along the
// plane; the strips lie every g.dy / cos from O, their gap and A linear between the samples
// about them (the strips reach a few samples beyond the run, within its window). Where the
// rail's slope varies across the patch (from the flange root onto the flank) each stretch of
// rail keeps its own slope in the plane; the plane at O alone stretched the root's shelf 2.5
// times across a flank-inclined plane and flattened its gap as much. Without `weighted` (Kik &
// Piotrowski's own reduction): the plane at the run's gap minimum, every sample's gap times its
// cosine, s = -(y - y_O) / cos.
// Pass approach * plane.cos to the solver.
RunStrips strips_of(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    const Run& run, double approach, bool weighted, StripBuffers& buffers);

}  // namespace wheelwear::contactgeom::detail
