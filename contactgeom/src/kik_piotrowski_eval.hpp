#pragma once
// The Kik-Piotrowski solution at one rigid approach, the step that the load iteration repeats
// (internal to kik_piotrowski.cpp and kik_piotrowski_load.cpp).

#include <array>
#include <cstddef>
#include <limits>
#include <string>

#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom::detail {

// The expensive part of one run's KP solution at one approach: the integrals I1, I2.
struct RunIntegrals {
  double i1 = 0.0;      // int int sqrt(x_l^2 - x^2)/r dx ds [m^2]
  double i2 = 0.0;      // int pi/2 x_l^2 ds [m^3]
  double max_xl = 0.0;  // largest leading edge at a strip centre [m]
  std::size_t first_contact = 0;
  std::size_t last_contact = 0;
};

// The integrals of every run at the last approach evaluated, so that writing the result after
// the load iteration does not repeat its most expensive pass. Fixed size: no allocation.
struct EvaluationCache {
  double delta = std::numeric_limits<double>::quiet_NaN();
  std::size_t count = 0;
  bool complete = false;  // false when there were more runs than slots
  std::array<RunIntegrals, 8> runs;
};

// Total KP load [N] at the rigid approach delta; records the run integrals in `cache`.
double total_load(const GapStrips& g, double delta, const KpOptions& options, double E_star,
                  EvaluationCache& cache);

// Writes every patch with load at delta into `result`, reusing its storage, and the run
// integrals from `cache` when it holds this delta. Sets approach, normal_force, pmax, patches.
void fill_result(const GapStrips& g, double delta, const KpOptions& options, double E_star,
                 const EvaluationCache& cache, KpResult& result);

// Smallest finite gap and its strip; index = size() when no gap is finite.
struct LowestStrip {
  std::size_t index;
  double h;
};
LowestStrip lowest_strip(const GapStrips& g);

// Throws InputError unless E_star is finite and positive.
void check_modulus(double E_star);

// Sets `result` to no contact at the approach delta, for the reason given.
void set_no_contact(KpResult& result, double delta, std::string message);

}  // namespace wheelwear::contactgeom::detail
