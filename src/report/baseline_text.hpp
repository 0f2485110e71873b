// `check --baseline` in words: one line per value that changed or could not be compared,
// and the summary of them all (cli's text and the JUnit file say the same).
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// "<backend> dt <dt> <metric>: <baseline> -> <now> (x<ratio>)", or for a status or a
/// value not compared, "<backend> dt <dt> <metric>: <note>" (no dt for the reference).
std::string baseline_change_text(const BaselineComparison& c);

/// The word a line starts with: "worse", "better", "unchanged", "not compared".
std::string change_word(Change change);

/// Whether a comparison is said on a line of its own: worse, better, or named as not compared.
bool said_alone(const BaselineComparison& c);

/// "baseline DIR: N compared: W worse, B better, U unchanged; not compared: K (why: n, ...)"
/// over every comparison of `all`, with the cases that had no baseline.
std::string baseline_summary(const std::string& folder, const std::vector<CaseResults>& all,
                             int cases_without_baseline);

}  // namespace bb
