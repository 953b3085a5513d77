#pragma once
// A wheelset of conical wheels (profiles::conical_wheel) on 60E1 rails without inclination,
// with Kalker's linear creep theory on the equivalent ellipse: the textbook wheelset of linear
// curving theory.

#include "wheelwear/profiles/conical_wheel.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/vehicle/wheelset_forces.hpp"

namespace wheelwear::vehicle::testing {

inline constexpr double kNominalRadius = 0.46;  // [m]

inline WheelsetModel conical_wheelset(double conicity) {
  profiles::ConicalWheelOptions cone;
  cone.conicity = conicity;
  cone.nominal_radius = kNominalRadius;
  const profiles::Profile wheel = profiles::conical_wheel(cone);
  profiles::Rail60E1Options rail_options;
  rail_options.inclination = 0.0;
  const profiles::Profile rail = profiles::rail_60e1(rail_options);
  WheelsetModel model{
      {contactgeom::WheelRailPair(wheel, rail), contactgeom::WheelRailPair(wheel, rail)}};
  model.method = tangential::Method::linear_sdec;  // Kalker's linear creep on the ellipse
  model.ellipse_at_O = true;
  model.material = {80e9, 0.25};
  return model;
}

// The wheelset's own geometry, from solve_wheelset: the rolling radius r_c of the centred
// wheelset and the effective conicity lambda_e = (r_left - r_right) / (2 dy) at shift dy. On a
// real rail head lambda_e exceeds the cone's slope: the wheelset rolls by about lambda dy / e0
// and the roll moves each contact further along its wheel (by 3.8 % of dy for lambda 0.05,
// 7.8 % for 0.1, 17 % for 0.2 on 60E1); it is constant in dy to 1e-5 within 7 mm.
struct ConeGeometry {
  double centred_radius = 0.0;
  double conicity = 0.0;
};

inline ConeGeometry cone_geometry(const WheelsetModel& model, double dy) {
  ConeGeometry g;
  for (double shift : {0.0, dy}) {
    contactgeom::WheelsetState s;
    s.dy = shift;
    s.vertical_force_left = s.vertical_force_right = 55e3;
    const contactgeom::WheelsetContact c = contactgeom::solve_wheelset(model.track, s);
    const double r_left = c.left.patches.at(0).rolling_radius;
    const double r_right = c.right.patches.at(0).rolling_radius;
    if (shift == 0.0)
      g.centred_radius = r_left;
    else
      g.conicity = (r_left - r_right) / (2.0 * shift);
  }
  return g;
}

// The creep coefficients f11, f22 [N] of a wheel of the centred wheelset at wheel load `load`:
// the model's creep law on its patch's ellipse, read off as force over a small creepage (with
// conical_wheelset's linear theory, Kalker's G a b C11 and G a b C22).
struct CreepCoefficients {
  double f11 = 0.0, f22 = 0.0;
};

inline CreepCoefficients creep_coefficients(const WheelsetModel& model, double load) {
  contactgeom::WheelsetState s;
  s.vertical_force_left = s.vertical_force_right = load;
  const contactgeom::WheelsetContact c = contactgeom::solve_wheelset(model.track, s);
  const contactgeom::WheelRailPatch& patch = c.left.patches.at(0);
  const contactgeom::Sdec ellipse{patch.sdec.a, patch.sdec.b, 0.0};
  const double creepage = 1e-6;
  const tangential::ContactLoad contact_load{patch.normal_force, 0.3};
  const auto fx = tangential::solve_patch(model.method, ellipse, {creepage, 0.0, 0.0}, contact_load,
                                          model.material, model.solve);
  const auto fy = tangential::solve_patch(model.method, ellipse, {0.0, creepage, 0.0}, contact_load,
                                          model.material, model.solve);
  return {-fx.forces.Fx / creepage, -fy.forces.Fy / creepage};
}

}  // namespace wheelwear::vehicle::testing
