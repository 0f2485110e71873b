// Loading a case with every word this build knows: the loader of the model
// (study/load_case.hpp) is handed the observable kinds of the registry and the engines of
// the catalogue.
#pragma once

#include <string>
#include <string_view>

#include "study/load_case.hpp"

namespace bb {

/// Every observable kind of the registry and every engine of the catalogue.
const CaseVocabulary& every_word();

/// Load the case at `path`; throws CaseError (also for a map's claim on a backend the
/// course theory gives no stable step for, region_claims.hpp).
Scene load_case(const std::string& path);

/// Parse case text; `file` names it in messages. Throws CaseError.
Scene parse_case(std::string_view text, const std::string& file);

}  // namespace bb
