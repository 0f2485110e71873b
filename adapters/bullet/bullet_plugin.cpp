// The plugin of Bullet's double-precision libraries: `bullet` (the springs as Bullet's
// constraints), `bullet/force` (the springs as forces) and `bullet-softbody`. `bullet-float`
// links the single-precision libraries, whose symbols have the same names: it is a plugin of
// its own (bullet_float_plugin.cpp), loaded apart with RTLD_LOCAL.
#include <vector>

#include "bullet_engine.hpp"
#include "bullet_starts.hpp"
#include "bullet_vectors.hpp"
#include "seam/plugin_api.hpp"

namespace {

bb::Backend* bullet_backend(int index) {
  using bb::SpringsAs;
  static const std::vector<bb::VariantStart> starts = {
      {"bullet", bb::bullet_rigid_start(SpringsAs::Joints)},
      {"bullet/force", bb::bullet_rigid_start(SpringsAs::Forces)},
      {"bullet-softbody", bb::bullet_softbody_start()}};
  return bb::engine_backend(bb::bullet_description(), bb::bullet_version(), starts, index);
}

}  // namespace

BEACHBALL_PLUGIN_BACKENDS(bullet_backend)
