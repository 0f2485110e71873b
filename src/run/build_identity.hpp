// Which build made a result: the bytes of every piece of code that can change it. The
// program; every shared library the process has loaded, found from the process itself (its
// loaded objects), not from a list of names, so that beachball's own (libbb_model.so, the
// model and the seam; libbb_study.so, the loader; libbb_physics.so, every force term), the
// engines' and the system's are covered, and
// a new library is covered with no edit; and the engine plugins, each on its own, so that a
// rebuilt plugin reruns only its backend's runs.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// Every file of code mapped into this process: the program (/proc/self/exe) and every
/// shared object loaded so far, each once, as a path that can be read.
std::vector<std::string> loaded_code_files();

/// A digest of the code every backend shares: the program and every loaded shared library
/// that is not an engine plugin (nor one from outside the tree), by content (paths play no part: a
/// copy of the build elsewhere is the same build). Read at the first call, after the plugins are
/// loaded (then their engines' libraries are loaded too); "" when the program cannot be read.
const std::string& shared_code_digest();

/// A digest of the plugin file of `backend`, built-in or from outside the tree ("" for a
/// backend that is not a plugin).
std::string plugin_digest(const std::string& backend);

/// A digest of the whole build: the shared code, every file in the plugin folder and every
/// plugin from outside the tree. What a
/// shard's manifest records and a merge compares with its own.
std::string build_digest();

}  // namespace bb
