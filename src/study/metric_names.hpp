// Names of the error metrics results may carry.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// position_max, position_rms, position_final, velocity_max, energy_max.
const std::vector<std::string>& error_metric_names();

}  // namespace bb
