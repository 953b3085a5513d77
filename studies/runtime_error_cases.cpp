#include "runtime_error_cases.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

#include "support/contact_cases.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::bench::runtime_error {

namespace contact = wheelwear::testing::contact;

CaseSet pure_spin_cases() {
  CaseSet set{"pure_spin", Measure::max_component_over_mu_n, {}};
  for (const contact::PureSpinCase& c : contact::pure_spin_cases_with_spin())
    set.cases.push_back({c.patch, c.creepages, c.load, c.Fx, c.Fy});
  return set;
}

// CONTACT's linear coefficients turned back into the forces of its unit creepages (README of
// tests/data/contact, section 3: C11s = -Fx(dvx)/(G c^2 dvx), C13s = -Fx(dphi)/(G c^3 dphi), ...).
CaseSet linear_cases(const tangential::Material& material) {
  CaseSet set{"linear", Measure::vector_relative, {}};
  for (const contact::LinearCoefficientCase& k : contact::linear_coefficient_cases()) {
    const contactgeom::Sdec& patch = k.patch;
    const double c = std::sqrt(patch.a * patch.b), g = material.G;
    const double dv = k.dv, dphi = k.dphi;
    const double c2 = g * c * c, c3 = g * c * c * c;
    set.cases.push_back({patch, {dv, 0, 0}, k.load, -c2 * k.c11s * dv, -c2 * k.c21s * dv});
    set.cases.push_back({patch, {0, dv, 0}, k.load, -c2 * k.c12s * dv, -c2 * k.c22s * dv});
    set.cases.push_back({patch, {0, 0, dphi}, k.load, -c3 * k.c13s * dphi, -c3 * k.c23s * dphi});
  }
  return set;
}

double scale(Measure measure, const Case& c) {
  return measure == Measure::max_component_over_mu_n ? c.load.mu * c.load.N
                                                     : std::hypot(c.fx_ref, c.fy_ref);
}

double case_error(Measure measure, const Case& c, double fx, double fy, double fx_ref,
                  double fy_ref) {
  if (measure == Measure::max_component_over_mu_n)
    return std::max(std::abs(fx - fx_ref), std::abs(fy - fy_ref)) / scale(measure, c);
  return std::hypot(fx - fx_ref, fy - fy_ref) / scale(measure, c);
}

Errors errors(const CaseSet& set, const std::vector<Forces>& f, const std::vector<Forces>* conv) {
  Errors e;
  for (std::size_t k = 0; k < set.cases.size(); ++k) {
    const Case& c = set.cases[k];
    e.contact =
        std::max(e.contact, case_error(set.measure, c, f[k].fx, f[k].fy, c.fx_ref, c.fy_ref));
    e.contact_fx = std::max(e.contact_fx, std::abs(f[k].fx - c.fx_ref) / scale(set.measure, c));
    e.contact_fy = std::max(e.contact_fy, std::abs(f[k].fy - c.fy_ref) / scale(set.measure, c));
    if (conv)
      e.converged = std::max(
          e.converged, case_error(set.measure, c, f[k].fx, f[k].fy, (*conv)[k].fx, (*conv)[k].fy));
  }
  return e;
}

CaseSet table_cases(const CaseSet& set, const tangential::Material& material, int& skipped) {
  CaseSet covered{set.name, set.measure, {}};
  std::set<std::string> reasons;
  skipped = 0;
  for (const Case& c : set.cases) {
    const auto why = tangential::creep_table_outside(c.patch, c.creepages, c.load, material);
    if (!why) {
      covered.cases.push_back(c);
    } else {
      ++skipped;
      reasons.insert(*why);
    }
  }
  for (const std::string& why : reasons)
    std::cerr << "table " << set.name << ": skipped: " << why << "\n";
  return covered;
}

}  // namespace wheelwear::bench::runtime_error
