// The entry points every backend plugin exports: the built-in engines (adapters/<engine>/)
// and a plugin built outside the tree against the installed SDK (docs/own-physics.md).
#pragma once

#include "scene/backend.hpp"
#include "scene/declared_backend.hpp"

/// The version of the plugin interface: the classes a plugin and the program share
/// (scene/backend.hpp and what it includes). Raised whenever one of them changes; the program
/// refuses a plugin built against another version before creating anything of it.
#define BEACHBALL_PLUGIN_INTERFACE_VERSION 1

/// Symbol looked up in each plugin: returns a new Backend, the caller owns it.
#define BEACHBALL_PLUGIN_ENTRY "beachball_create_backend"
/// Symbol looked up before the entry: returns the interface version the plugin was built with.
#define BEACHBALL_PLUGIN_VERSION_ENTRY "beachball_plugin_interface_version"

/// Returns a new Backend; the caller owns it.
extern "C" bb::Backend* beachball_create_backend();
/// The BEACHBALL_PLUGIN_INTERFACE_VERSION the plugin was compiled with.
extern "C" int beachball_plugin_interface_version();

/// Exports both entry points of a plugin whose backend `make` (an expression of type
/// bb::Backend*, a new object) creates:
///   BEACHBALL_PLUGIN(bb::DeclaredBackend::of<MySimulation>({"mine/euler", features}))
#define BEACHBALL_PLUGIN(make)                          \
  extern "C" int beachball_plugin_interface_version() { \
    return BEACHBALL_PLUGIN_INTERFACE_VERSION;          \
  }                                                     \
  extern "C" bb::Backend* beachball_create_backend() {  \
    return make;                                        \
  }
