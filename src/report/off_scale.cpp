#include "report/off_scale.hpp"

namespace bb {

double off_scale_limit(std::vector<double> reach, double span, double floor) {
  double typical = 0.0;
  if (!reach.empty()) {
    std::nth_element(reach.begin(), reach.begin() + reach.size() / 2, reach.end());
    typical = reach[reach.size() / 2];
  }
  return kOffScale * std::max({span, typical, floor});
}

}  // namespace bb
