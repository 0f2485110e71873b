// Reading and validating a case file. Every problem is a CaseError naming file and line.
#pragma once

#include <string>
#include <string_view>

#include "study/case_limits.hpp"
#include "study/case_vocabulary.hpp"
#include "study/scene.hpp"

namespace bb {

/// Longest case name and body name, in characters: a name goes into file names, table
/// cells and headings.
inline constexpr std::size_t kMaxNameLength = 64;
/// Largest case file accepted, in bytes.
inline constexpr std::size_t kMaxCaseFileBytes = 1 << 20;

/// Load the case at `path`, in the words of `vocabulary`; throws CaseError. (The program
/// loads with every word it knows: run/case_loading.hpp.)
Scene load_case(const std::string& path, const CaseVocabulary& vocabulary);

/// Parse case text; `file` names it in messages. Throws CaseError.
Scene parse_case(std::string_view text, const std::string& file, const CaseVocabulary& vocabulary);

}  // namespace bb
