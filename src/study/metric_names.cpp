#include "study/metric_names.hpp"

namespace bb {

const std::vector<std::string>& error_metric_names() {
  static const std::vector<std::string> v = {"position_max", "position_rms", "position_final",
                                             "velocity_max", "energy_max"};
  return v;
}

}  // namespace bb
