// The entry point every engine plugin (adapters/<engine>/) exports.
#pragma once

#include "scene/backend.hpp"

/// Symbol looked up in each plugin.
#define BEACHBALL_PLUGIN_ENTRY "beachball_create_backend"

/// Returns a new Backend; the caller owns it.
extern "C" bb::Backend* beachball_create_backend();
