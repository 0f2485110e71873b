// The report's index (README.md of the output folder): what was run, the claims ledger, one
// table per course section, the rotation plots and where the time went.
#pragma once

#include <string>
#include <vector>

#include "run/results.hpp"

namespace bb {

/// The widest table the index prints, counting the backend column: a projector or a laptop
/// shows about this many columns of cells legibly.
inline constexpr int kMaxIndexColumns = 12;

/// What the index is an index of, in words for its first line ("The bundled suite", "The
/// cases of `mine/`"), and the command that makes it again.
struct IndexSource {
  std::string what;
  std::string regenerate;
};

/// One table per course section, in the text's order: a backend per row, a case per column
/// (at most kMaxIndexColumns - 1 per table; a larger section gets several), each case's title
/// and gates listed above its table.
std::string section_tables(const std::vector<CaseResults>& all);

/// The index page; with `timed` (the cost pass ran), where the time went: like the costs, a
/// report without them is the same bytes from one run to the next. `rotation_plots` holds each
/// case's rotation plot file, empty where none was drawn.
std::string index_page(const std::vector<CaseResults>& all,
                       const std::vector<std::string>& rotation_plots, bool timed, int jobs,
                       const IndexSource& source);

}  // namespace bb
