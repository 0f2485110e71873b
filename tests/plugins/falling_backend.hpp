// The backend every test plugin gives (tests/CMakeLists.txt): bodies on gravity's parabola,
// compiled once; each plugin's entry points (test_plugin.cpp) are compiled per plugin and
// include nothing heavier than this header.
#pragma once

namespace bb {
class Backend;
}

namespace bb::test_plugin {

/// Where a plugin's backend crashes, if anywhere.
enum class Crash { Never, AtStart, AtFourthStep };

/// A new backend named `name`, the caller's: every body exactly on gravity's parabola at each
/// step, or a SIGSEGV where `crash` says.
Backend* falling_backend(const char* name, Crash crash);

/// BEACHBALL_PLUGIN_INTERFACE_VERSION as this build of the program has it.
int interface_version();

}  // namespace bb::test_plugin
