#include "run/case_loading.hpp"

#include "observe/observable_registry.hpp"

namespace bb {

Scene load_case(const std::string& path) {
  return load_case(path, case_vocabulary());
}

Scene parse_case(std::string_view text, const std::string& file) {
  return parse_case(text, file, case_vocabulary());
}

}  // namespace bb
