// Names of the error metrics and observable kinds results may carry.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// position_max, position_rms, position_final, velocity_max, energy_max.
const std::vector<std::string>& error_metric_names();

/// Every observable kind of DESIGN.md ("final_speed", "terminal_velocity", ...).
const std::vector<std::string>& observable_kinds();

/// Kinds that count events and take an `n` (the n-th bounce, contact, ...).
/// Whether observables of this kind describe the whole scene and take no `body` (they are
/// named by their kind alone): max_stretch, sag, final_shear.
bool observable_is_scene_wide(const std::string& kind);

bool observable_is_counted(const std::string& kind);

}  // namespace bb
