#include "report/claims_page.hpp"

#include <fmt/format.h>

#include "model/text.hpp"
#include "report/format.hpp"
#include "report/map_claim_picture.hpp"
#include "run/claims.hpp"
#include "run/map_theory.hpp"

namespace bb {

namespace {

/// "holds (29.2 > 9.63)": the verdict and the two numbers at report_dt, and the known
/// cause of a verdict other than "holds".
std::string verdict_text(const Claim& claim, const ClaimVerdict& v) {
  std::string out = v.backend + ": **" + v.verdict + "**";
  if (v.left && v.right)
    out += " (" + format_value(v.left) + " " + claim.op + " " + format_value(v.right) + ")";
  if (!v.cause.empty()) out += ", cause: " + v.cause;
  return out;
}

/// What a map's claim's word for a side ("ok", "exploded", "any") is on `scene`'s map, in the
/// map's outcomes: "exploded" is past the first [[sweep]]'s onset (a block that slides, a ball
/// that flies through) or diverged.
std::string side_outcome(const Scene& scene, const std::string& word) {
  if (word == "any") return "any outcome";
  if (word == "ok") return "ok";
  const Sweep& first = *scene.sweep;
  if (first.onset.empty()) return "diverged";
  return "past the onset (" + first.onset + " > " + short_number(first.onset_above) +
         ") or diverged";
}

/// The claim's sentence, and how its sides are read when that is not their value: a map's
/// claim in its map's outcomes, on either side of its theory's bound.
std::string claim_cell(const Scene& scene, const Claim& claim) {
  if (claim.region && scene.second_sweep)
    if (const MapTheory* theory = map_theory(scene, claim.region->backend))
      return claim.text + " (judged on its map: " + side_outcome(scene, claim.region->inside) +
             " where " + theory->bounded + " is below the theory's bound, " +
             side_outcome(scene, claim.region->outside) + " where it is above)";
  if (!claim.against_reference) return claim.text;
  return claim.text + " (each side read as its distance from the reference's value)";
}

/// The course text's words with their section, or that the claim is the case's own.
std::string source_cell(const Claim& claim) {
  std::string quoted;
  if (!claim.quote.empty())
    quoted = (claim.seed.empty() ? "" : claim.seed + ": ") + "\"" + claim.quote + "\"";
  if (!claim.own) return quoted.empty() ? "-" : quoted;
  return "the case's own claim, not the text's" +
         (quoted.empty() ? std::string() : "; prompted by " + quoted);
}

/// The verdicts, and for a map's claim whose map ran, its picture.
std::string verdicts_cell(const CaseResults& results, const ClaimResult& c) {
  std::string cell;
  for (const ClaimVerdict& v : c.verdicts)
    cell += (cell.empty() ? "" : "; ") + verdict_text(*c.claim, v);
  if (c.claim->region && results.sweep)
    cell += fmt::format(
        " ([its map]({}))",
        map_claim_file(*results.scene,
                       static_cast<std::size_t>(c.claim - results.scene->claims.data())));
  return cell.empty() ? "-" : cell;
}

}  // namespace

Table case_claims_table(const CaseResults& results) {
  Table t;
  t.headers = {"claim", "course text", "verdicts (numbers at report_dt)"};
  t.right_aligned.assign(t.headers.size(), false);
  for (const ClaimResult& c : results.claims)
    t.rows.push_back(
        {claim_cell(*results.scene, *c.claim), source_cell(*c.claim), verdicts_cell(results, c)});
  return t;
}

std::string claims_page(const std::vector<CaseResults>& all) {
  Table t;
  t.headers = {"claim", "course text", "case", "verdicts (numbers at report_dt)"};
  t.right_aligned.assign(t.headers.size(), false);
  int count = 0, own = 0, failing = 0, neither = 0;
  for (const CaseResults& r : all)
    for (const ClaimResult& c : r.claims) {
      const ClaimStanding standing = claim_standing(c);
      failing += standing == ClaimStanding::Fails;
      neither += standing == ClaimStanding::Neither;
      own += c.claim->own;
      ++count;
      // render_markdown escapes every cell's text once.
      t.rows.push_back({claim_cell(*r.scene, *c.claim), source_cell(*c.claim),
                        fmt::format("[{0}]({0}.md)", r.scene->name), verdicts_cell(r, c)});
    }
  std::string page =
      "# Claims ledger\n\nSentences of the course text, each quoted beside the claim that "
      "checks it by numbers from the case it names ([[claim]] in the case file); a claim the "
      "text does not make is marked as the case's own. For each backend the verdict over its "
      "whole dt sweep: holds, fails, holds for dt <= X (only at the small steps), holds for "
      "dt >= X (only at the large ones, as a claim that a method goes wrong at a game's step "
      "should), holds at some dts only, or not measured (with why); a verdict names the dts it "
      "could not judge (not measured at dt ..., where a run has no value for the claim: the "
      "case page says why). Runs that diverged are named; "
      "where the claim says so, a divergence counts as evidence for it (a claim that "
      "something explodes) or against it. Runs that an engine held at a cap of its own (capped) "
      "are named and not judged: their numbers are the cap's. A map's claim (a backend's "
      "outcome inside the theory's region and outside it) is judged at each point of its map: "
      "it holds at N of M judged points, the points it does not judge counted apart (within its "
      "margin of the boundary, without an outcome), with a picture of where it fails. The two "
      "numbers are those compared at report_dt, "
      "and a known cause of a verdict other than holds is named. Computed by the program "
      "from the case files; nothing here is written by hand.\n\n";
  if (count == 0) return page + "No case of this suite has a claim yet.\n";
  page += fmt::format(
      "{} claims ({} from the course text, {} the cases' own); {} of them fail or hold only in "
      "part for some backend; of the others, {} have a backend that diverged at some dt "
      "without bearing on the claim, was capped, or could not be measured at some dt or at all "
      "(neither holds nor fails "
      "there: counted apart).\n\n",
      count, count - own, own, failing, neither);
  return page + render_markdown(t);
}

}  // namespace bb
