// The gates of a `check` as JUnit XML, for a CI system's test view: a test suite per case,
// a test case per gate, a failure with the measured value and the limit it exceeds; with
// `--baseline`, a test case per backend and metric compared, failed where a dt got worse.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The JUnit XML of every gate and baseline comparison of every case in `all`.
std::string junit_xml(const std::vector<CaseResults>& all);

}  // namespace bb
