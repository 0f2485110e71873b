#include "report/claims_page.hpp"

#include <fmt/format.h>

#include "report/format.hpp"
#include "report/table.hpp"
#include "run/claims.hpp"

namespace bb {

namespace {

/// "holds (29.2 > 9.63)": the verdict and the two numbers at report_dt.
std::string verdict_text(const Claim& claim, const ClaimVerdict& v) {
  std::string out = v.backend + ": **" + v.verdict + "**";
  if (v.left && v.right)
    out += " (" + format_value(v.left) + " " + claim.op + " " + format_value(v.right) + ")";
  return out;
}

}  // namespace

std::string claims_page(const std::vector<CaseResults>& all) {
  Table t;
  t.headers = {"claim", "course section", "case", "verdicts (numbers at report_dt)"};
  t.right_aligned.assign(t.headers.size(), false);
  int count = 0, failing = 0;
  for (const CaseResults& r : all)
    for (const ClaimResult& c : judge_claims(r)) {
      std::string cell;
      bool fails = false;
      for (const ClaimVerdict& v : c.verdicts) {
        cell += (cell.empty() ? "" : "; ") + verdict_text(*c.claim, v);
        fails = fails || v.verdict != "holds";
      }
      failing += fails;
      ++count;
      // render_markdown escapes every cell's text once.
      t.rows.push_back({c.claim->text, c.claim->seed.empty() ? "-" : c.claim->seed,
                        fmt::format("[{0}]({0}.md)", r.scene->name), cell});
    }
  std::string page =
      "# Claims ledger\n\nSentences of the course text, each checked by numbers from the case "
      "it names ([[claim]] in the case file): for each backend the verdict over its whole dt "
      "sweep (holds, fails, or holds only below some dt), and the two numbers compared at "
      "report_dt. Computed by the program from the case files; nothing here is written by "
      "hand.\n\n";
  if (count == 0) return page + "No case of this suite has a claim yet.\n";
  page += fmt::format("{} claims; {} of them fail or hold only in part for some backend.\n\n",
                      count, failing);
  return page + render_markdown(t);
}

}  // namespace bb
