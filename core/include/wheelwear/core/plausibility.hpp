#pragma once
/// Plausibility limits of the inputs a user types: one table of what is refused as impossible
/// (most often a unit mistake: millimetres typed as metres, km/h as m/s, per cent as a fraction)
/// and what is warned about as implausible. docs/cli.md, "Plausibility limits", lists the same
/// rows with their reasons; tests/pipeline/plausibility_test.cpp checks that it does.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::core {

/// One row of the table. The limits bound |value|: above `warn` a value is implausible (a
/// warning), above `refuse` (or at it, when `refuse_at_limit`) impossible (an InputError).
struct PlausibilityLimit {
  std::string_view quantity{};  ///< plural noun for messages, e.g. "contact semi-axes"
  std::string_view unit{};      ///< SI unit of the value and the limits; "" for a pure number
  bool positive = false;        ///< the value must also be > 0 (else either sign is accepted)
  double warn = std::numeric_limits<double>::infinity();    ///< [unit]; infinity: never warned
  std::string_view warn_reason{};                           ///< why above `warn` is implausible
  double refuse = std::numeric_limits<double>::infinity();  ///< [unit]; infinity: never refused
  bool refuse_at_limit = false;      ///< `refuse` itself is refused (|value| >= refuse)
  std::string_view refuse_reason{};  ///< why beyond `refuse` is impossible
  std::string_view fix{};            ///< the likely mistake and how to fix it
};

/// The wheelset's yaw angle.
inline constexpr PlausibilityLimit kYawLimit{
    .quantity = "yaw angles",
    .unit = "rad",
    .refuse = 0.1,
    .refuse_at_limit = true,
    .refuse_reason =
        "a wheelset yawed 5.7 degrees has left its track (flanges keep it within "
        "about 0.01 rad even in the sharpest curves); the contact geometry assumes a "
        "small yaw",
    .fix = "did you give milliradians or degrees? the unit is radians (2 mrad = 0.002)"};

/// The semi-axes a, b of a contact patch the user gives (an SDEC or an ellipse).
inline constexpr PlausibilityLimit kSemiAxisLimit{
    .quantity = "contact semi-axes",
    .unit = "m",
    .positive = true,
    .warn = 0.03,
    .warn_reason =
        "tread patches have semi-axes of 3 ... 8 mm and conformal ones rarely reach "
        "20 mm",
    .refuse = 0.1,
    .refuse_reason = "a patch 0.2 m across is larger than the rail head (72 mm wide)",
    .fix = "did you give millimetres? the unit is metres (4.25 mm = 4.25e-3)"};

/// The vertical load on one wheel, or the normal force on one patch.
inline constexpr PlausibilityLimit kWheelLoadLimit{
    .quantity = "wheel loads",
    .unit = "N",
    .positive = true,
    .warn = 3e5,
    .warn_reason =
        "the heaviest heavy-haul wheels carry about 200 kN (40 t axles); only "
        "dynamic peaks reach 300 kN",
    .refuse = 1e6,
    .refuse_reason =
        "wheel and rail would yield far beyond the elastic contact the model "
        "assumes (five times the heaviest static wheel load)",
    .fix =
        "did you give another unit, or the axle's load? the unit is newtons on one wheel "
        "(55 kN = 55000)"};

/// The wheel/rail approach after the contact solve (computed, so only warned about).
inline constexpr PlausibilityLimit kApproachLimit{
    .quantity = "wheel/rail approaches",
    .unit = "m",
    .warn = 5e-3,
    .warn_reason =
        "S1002 on 60E1 approaches by 0.08 mm at 55 kN and 0.5 mm at 1 MN; millimetres "
        "mean an elastic modulus far too small or profiles in the wrong unit",
    .fix = "check Young's modulus (the unit is Pa: 200e9 for steel) and the profiles' unit"};

/// The forward (rolling) speed.
inline constexpr PlausibilityLimit kSpeedLimit{
    .quantity = "speeds",
    .unit = "m/s",
    .positive = true,
    .warn = 100.0,
    .warn_reason = "faster than any train in service (350 km/h = 97 m/s)",
    .refuse = 150.0,
    .refuse_reason = "no train but a record run (575 km/h, 2007) went faster than 540 km/h",
    .fix = "did you give km/h? the unit is m/s (72 km/h = 20)"};

/// The longitudinal and lateral creepages vx, vy.
inline constexpr PlausibilityLimit kCreepageLimit{
    .quantity = "creepages",
    .unit = "",
    .warn = 0.2,
    .warn_reason = "curving gives about 0.01 and traction and brake control keep slip below 0.2",
    .refuse = 1.0,
    .refuse_reason = "beyond full sliding (a locked wheel has |vx| = 1)",
    .fix = "did you give per cent? the creepage is a fraction (0.1 % = 1e-3)"};

/// The coefficient of friction.
inline constexpr PlausibilityLimit kFrictionLimit{
    .quantity = "friction coefficients",
    .unit = "",
    .positive = true,
    .warn = 0.6,
    .warn_reason = "dry, clean wheel and rail reach about 0.6",
    .refuse = 1.0,
    .refuse_reason = "steel on steel in air stays well below 1",
    .fix = "did you give per cent? the coefficient is a fraction (0.3)"};

/// Every row, in the order docs/cli.md lists them.
inline constexpr std::array<const PlausibilityLimit*, 7> kPlausibilityLimits = {
    &kYawLimit,   &kSemiAxisLimit, &kWheelLoadLimit, &kApproachLimit,
    &kSpeedLimit, &kCreepageLimit, &kFrictionLimit};

/// A limit or value as the messages and docs/cli.md write it: the shortest exact number, the
/// exponent as typed (1e6, 3e-3), then the unit if any ("1e6 N").
std::string limit_text(double value, std::string_view unit);

/// Throws InputError unless `value` is finite, positive where the row asks it, and within the
/// row's refuse limit. The message names `input` (a flag such as "--a", or a file's line and
/// key), the value, the limit, the reason and the likely fix, e.g. "--a = 4.25 m: contact
/// semi-axes above 0.1 m are impossible: ...; did you give millimetres? ...".
void require_plausible(const PlausibilityLimit& limit, std::string_view input, double value);

/// The warning for `value` of `input` when |value| is above the row's warn limit (naming the
/// input, the value, the limit and the reason); nullopt otherwise, also for NaN.
std::optional<std::string> plausibility_warning(const PlausibilityLimit& limit,
                                                std::string_view input, double value);

/// require_plausible, then plausibility_warning appended to `warnings` if there is one.
void check_plausible(const PlausibilityLimit& limit, std::string_view input, double value,
                     std::vector<std::string>& warnings);

}  // namespace wheelwear::core
