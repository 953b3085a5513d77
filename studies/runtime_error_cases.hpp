#pragma once
// The reference cases of the run-time-versus-error study (runtime_error_study.cpp): CONTACT's
// pure-spin forces and its linear coefficients turned back into forces, and the error measures
// against them.

#include <string>
#include <vector>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::bench::runtime_error {

/// One solver call with CONTACT's answer.
struct Case {
  contactgeom::Sdec patch;
  tangential::Creepages creepages;
  tangential::ContactLoad load;
  double fx_ref = 0, fy_ref = 0;  ///< CONTACT's forces [N]
};

enum class Measure {
  max_component_over_mu_n,  ///< max(|dFx|, |dFy|)/(mu N)
  vector_relative,          ///< |dF|/|F_ref|
};

struct CaseSet {
  std::string name;
  Measure measure;
  std::vector<Case> cases;
};

/// A solver's forces on one case [N].
struct Forces {
  double fx = 0, fy = 0;
};

/// The 17 pure-spin cases with spin (b_pure_spin_mx80.csv), measured against mu N. The
/// catalogue's loaders throw when a file is missing or holds fewer or more cases than the
/// README lists, so every set is complete.
CaseSet pure_spin_cases();

/// CONTACT's linear coefficients (a_linear_coeffs_mx80.csv) turned back into the forces of its
/// unit creepages with the shear modulus of `material`: 270 calls, measured relative to |F|.
CaseSet linear_cases(const tangential::Material& material);

/// The set's normaliser: mu N, or the size of CONTACT's force.
double scale(Measure measure, const Case& c);

/// The error of (fx, fy) against (fx_ref, fy_ref) in the set's measure.
double case_error(Measure measure, const Case& c, double fx, double fy, double fx_ref,
                  double fy_ref);

struct Errors {
  double contact = 0, converged = 0;
  double contact_fx = 0, contact_fy = 0;  // each component alone, same normaliser
};

/// The largest errors of `f` over the set against CONTACT and, when given, against `conv`.
Errors errors(const CaseSet& set, const std::vector<Forces>& f, const std::vector<Forces>* conv);

/// The cases of `set` the creep table covers; `skipped` receives how many it does not. The
/// reasons are printed on stderr, each once.
CaseSet table_cases(const CaseSet& set, const tangential::Material& material, int& skipped);

}  // namespace wheelwear::bench::runtime_error
