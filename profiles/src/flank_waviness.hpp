#pragma once
// Whether a wheel record's flank is wavy on the scale of a millimetre, as a loading warning.

#include <optional>
#include <string>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles::detail {

/// A warning where the fitted wheel's active flank (from the flange tip to the taping line) has
/// three or more slope peaks in a row, each within 3 mm of the next laterally, each standing 4
/// degrees above the dips beside it: a record wavy on the scale of a millimetre, whose contact
/// point then jumps from wave to wave (a flange contact past the steepest wave counts as climbing),
/// so that a vehicle on it finds no balance. It names the peaks and the longer smoothing that fits
/// one flank. `source` names the file, `smoothing_length` the fit's [m].
std::optional<std::string> wavy_flank_warning(const Profile& wheel, const std::string& source,
                                              double smoothing_length);

}  // namespace wheelwear::profiles::detail
