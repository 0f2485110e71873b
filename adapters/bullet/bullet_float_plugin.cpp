// The plugin of Bullet's single-precision libraries: `bullet-float`, the rigid bodies with the
// springs as Bullet's constraints. Its own file, apart from bullet_plugin.cpp: the two link
// libraries whose symbols have the same names (adapters/bullet/CMakeLists.txt).
#include <vector>

#include "bullet_engine.hpp"
#include "bullet_starts.hpp"
#include "bullet_vectors.hpp"
#include "seam/plugin_api.hpp"

namespace {

bb::Backend* bullet_float_backend(int index) {
  static const std::vector<bb::VariantStart> starts = {
      {"bullet-float", bb::bullet_rigid_start(bb::SpringsAs::Joints)}};
  return bb::engine_backend(bb::bullet_description(), bb::bullet_version(), starts, index);
}

}  // namespace

BEACHBALL_PLUGIN_BACKENDS(bullet_float_backend)
