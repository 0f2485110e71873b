// The entry points every backend plugin exports: the built-in engines (adapters/<engine>/)
// and a plugin built outside the tree against the installed SDK (docs/own-physics.md).
#pragma once

#include "seam/backend.hpp"
#include "seam/declared_backend.hpp"

/// The version of the plugin interface: the classes a plugin and the program share
/// (seam/backend.hpp and what it includes) and the entry points below. Raised whenever one of
/// them changes; the program refuses a plugin built against another version before creating
/// anything of it. (2: a plugin gives any number of backends, by index.)
#define BEACHBALL_PLUGIN_INTERFACE_VERSION 2

/// Symbol looked up in each plugin: backend number `index` (0, 1, ...) of the plugin, a new
/// Backend the caller owns, or nullptr past its last.
#define BEACHBALL_PLUGIN_ENTRY "beachball_create_backend"
/// Symbol looked up before the entry: returns the interface version the plugin was built with.
#define BEACHBALL_PLUGIN_VERSION_ENTRY "beachball_plugin_interface_version"

/// Returns the plugin's backend number `index`, a new object the caller owns, or nullptr past
/// the last.
extern "C" bb::Backend* beachball_create_backend(int index);
/// The BEACHBALL_PLUGIN_INTERFACE_VERSION the plugin was compiled with.
extern "C" int beachball_plugin_interface_version();

/// The version entry point every plugin exports.
#define BEACHBALL_PLUGIN_EXPORT_VERSION                 \
  extern "C" int beachball_plugin_interface_version() { \
    return BEACHBALL_PLUGIN_INTERFACE_VERSION;          \
  }

/// Exports the entry points of a plugin of one backend, which `make` (an expression of type
/// bb::Backend*, a new object) creates:
///   BEACHBALL_PLUGIN(bb::DeclaredBackend::of<MySimulation>({"mine/euler", features}))
#define BEACHBALL_PLUGIN(make)                                  \
  BEACHBALL_PLUGIN_EXPORT_VERSION                               \
  extern "C" bb::Backend* beachball_create_backend(int index) { \
    return index == 0 ? (make) : nullptr;                       \
  }

/// Exports the entry points of a plugin of several backends: `make_backend` is a function
/// `bb::Backend* (int index)` giving backend number `index` (a new object) or nullptr past
/// the last (a built-in engine's variants: adapters/described_backend.hpp).
#define BEACHBALL_PLUGIN_BACKENDS(make_backend)                 \
  BEACHBALL_PLUGIN_EXPORT_VERSION                               \
  extern "C" bb::Backend* beachball_create_backend(int index) { \
    return make_backend(index);                                 \
  }
