#include "run/case_loading.hpp"

#include "observe/observable_registry.hpp"
#include "run/engine_catalogue.hpp"
#include "run/region_claims.hpp"

namespace bb {

const CaseVocabulary& every_word() {
  static CaseVocabulary vocabulary = case_vocabulary();
  // The engines again when plugins from outside joined the catalogue since.
  if (vocabulary.engines.size() != engine_catalogue().size())
    vocabulary.engines = engine_catalogue();
  return vocabulary;
}

Scene load_case(const std::string& path) {
  Scene scene = load_case(path, every_word());
  require_region_theory(scene);
  return scene;
}

Scene parse_case(std::string_view text, const std::string& file) {
  Scene scene = parse_case(text, file, every_word());
  require_region_theory(scene);
  return scene;
}

}  // namespace bb
