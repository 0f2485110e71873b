// Reading and validating a case file. Every problem is a CaseError naming file and line.
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace bb {

/// Longest case name and body name, in characters: a name goes into file names, table
/// cells and headings.
inline constexpr std::size_t kMaxNameLength = 64;
/// Largest case file accepted, in bytes.
inline constexpr std::size_t kMaxCaseFileBytes = 1 << 20;
/// Most particles a [grid] may generate, and most bodies in a case: a 300 x 300 sheet fits;
/// what a run holds grows with bodies times samples, which kMaxBodySamples bounds.
inline constexpr long kMaxGridParticles = 100000;
inline constexpr long kMaxBodies = 100000;
/// Most steps one run may take (duration / dt).
inline constexpr double kMaxStepsPerRun = 1e7;
/// Most samples a run keeps (duration / sample), and most body-samples (samples x bodies):
/// what is held in memory and drawn.
inline constexpr double kMaxSamples = 1e5;
inline constexpr double kMaxBodySamples = 2e6;
/// Most body-steps of one backend's whole dt sweep (steps x (bodies + springs), summed).
inline constexpr double kMaxSweepWork = 1e9;

/// Load the case at `path`; throws CaseError.
Scene load_case(const std::string& path);

/// Parse case text; `file` names it in messages. Throws CaseError.
Scene parse_case(std::string_view text, const std::string& file);

}  // namespace bb
