// The results JSON (schema "beachball-results/1", json_writer.hpp) read back: the rows a
// baseline is compared with, each as the RunRecord it was written from (backend, dt,
// status, reason, errors, observables; not its cost, settings or series).
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

struct KeptResults {
  std::string case_name;
  std::vector<RunRecord> runs;  ///< the reference's row first, as written
};

/// Reads `text`, the contents of `file`. Throws CaseError naming `file` (and the line, for
/// JSON that does not parse) when it is not such results, or a row's field is of the wrong
/// type.
KeptResults read_results_json(const std::string& text, const std::string& file);

/// Reads the file at `path` (at most 256 MiB); CaseError when it cannot be read or parsed.
KeptResults read_results_file(const std::string& path);

}  // namespace bb
