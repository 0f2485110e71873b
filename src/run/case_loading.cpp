#include "run/case_loading.hpp"

#include "observe/observable_registry.hpp"
#include "run/engine_catalogue.hpp"

namespace bb {

const CaseVocabulary& every_word() {
  static CaseVocabulary vocabulary = case_vocabulary();
  // The engines again when plugins from outside joined the catalogue since.
  if (vocabulary.engines.size() != engine_catalogue().size())
    vocabulary.engines = engine_catalogue();
  return vocabulary;
}

Scene load_case(const std::string& path) {
  return load_case(path, every_word());
}

Scene parse_case(std::string_view text, const std::string& file) {
  return parse_case(text, file, every_word());
}

}  // namespace bb
