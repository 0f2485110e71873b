// `check --baseline DIR`: each case's kept results in DIR (<case>.json, as `run` and
// `report` write them), what they make a check run, and the comparison with them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "report/results_reader.hpp"
#include "run/case_runner.hpp"

namespace bb::cli {

/// Each case's kept results in `folder`, by case name; a case without <case>.json has
/// none. Throws CaseError (exit 2) when `folder` is not a folder, or a file there cannot be
/// read or is not the case's results; so before any work.
std::map<std::string, KeptResults> read_baselines(const std::string& folder,
                                                  const std::vector<Scene>& scenes);

/// What a check must run to compare with `kept`: each backend of it that the case names
/// and `shard` holds, at each of its steps that is one of the case's.
RunSelection baseline_selection(const Scene& scene, const KeptResults& kept,
                                const std::optional<Shard>& shard);

/// `results` compared with `kept`, row by row, for the backends `shard` holds: into
/// results.baseline.
void compare_case(CaseResults& results, const KeptResults& kept, const std::optional<Shard>& shard);

}  // namespace bb::cli
