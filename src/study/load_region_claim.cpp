// A map's [[claim]] (`region`): the backend whose outcomes it states, the region, the outcome
// inside and outside it, and the margin about its boundary where a point is not judged.
#include <algorithm>

#include "model/text.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "study/load_parts.hpp"

namespace bb::load {

namespace {

/// The outcomes a side of the region may be claimed to have.
const std::vector<std::string>& claimable_outcomes() {
  static const std::vector<std::string> words = {"ok", "exploded", "any"};
  return words;
}

std::string read_outcome(TomlReader& r, const std::string& key, const std::string& fallback) {
  const std::string word = r.string_or(key, fallback);
  const auto& words = claimable_outcomes();
  if (std::find(words.begin(), words.end(), word) == words.end())
    r.fail(r.line_of(key), "[[claim]] '" + key + "' is '" + word +
                               "'; known: ok, exploded (past the first [[sweep]]'s onset, or "
                               "diverged), any (not judged on that side)");
  return word;
}

}  // namespace

void read_region_claim(TomlReader& r, const Scene& scene, Claim& c,
                       const EngineCatalogue& catalogue) {
  // The keys of a claim that compares two quantities have no meaning over a map's outcomes.
  for (const char* key : {"left", "op", "right", "tolerance", "diverged", "compare"})
    if (r.has(key))
      r.fail(r.line_of(key), std::string("[[claim]] with 'region' states a backend's outcomes "
                                         "over the map; '") +
                                 key + "' belongs to a claim that compares two quantities");
  RegionClaim g;
  g.region = r.string("region");
  if (g.region != "theory")
    r.fail(r.line_of("region"),
           "[[claim]] 'region' is '" + g.region +
               "'; known: theory (the points of the map below the bound of the theory drawn on "
               "the backend's map: the course's largest stable step, Coulomb's steepest holding "
               "tilt, ...)");
  g.backend = r.string("backend");
  require_runnable(r, scene, "backend", "[[claim]] 'backend'", g.backend,
                   runnable_backend_names(scene, catalogue), catalogue);
  g.boundary_factor = r.number_or("boundary_factor", 1.0);
  require_range(r, "boundary_factor", g.boundary_factor, 0.0, 0.0);
  g.inside = read_outcome(r, "inside", "ok");
  g.outside = read_outcome(r, "outside", "exploded");
  if (g.inside == "any" && g.outside == "any")
    r.fail(r.line_of("inside"),
           "[[claim]] says 'any' outcome inside the region and outside it: it states nothing");
  g.margin = r.number_or("margin", 0.0);
  require_range(r, "margin", g.margin, 0.0, 1.0, true);
  c.region = g;
}

// Whether a theory bounds one of the map's axes for the backend is the program's to say
// (run/region_claims.hpp, which knows the theories); here, that there is a map.
void check_region_claims(const Scene& scene) {
  for (const Claim& c : scene.claims)
    if (c.region && !scene.second_sweep)
      throw CaseError(scene.file, c.line,
                      "[[claim]] with region = \"" + c.region->region +
                          "\" is judged over a map: the case needs two [[sweep]]s, one of them "
                          "a parameter a theory bounds");
}

}  // namespace bb::load
