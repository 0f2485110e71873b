#include "study/study.hpp"

#include <cmath>

namespace bb {

int Study::sample_count() const {
  return static_cast<int>(std::llround(duration / sample));
}

int Study::steps_per_sample(double step) const {
  return static_cast<int>(std::llround(sample / step));
}

}  // namespace bb
