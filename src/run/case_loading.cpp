#include "run/case_loading.hpp"

#include "observe/observable_registry.hpp"
#include "run/engine_catalogue.hpp"

namespace bb {

const CaseVocabulary& every_word() {
  static const CaseVocabulary vocabulary = [] {
    CaseVocabulary v = case_vocabulary();
    v.engines = engine_catalogue();
    return v;
  }();
  return vocabulary;
}

Scene load_case(const std::string& path) {
  return load_case(path, every_word());
}

Scene parse_case(std::string_view text, const std::string& file) {
  return parse_case(text, file, every_word());
}

}  // namespace bb
