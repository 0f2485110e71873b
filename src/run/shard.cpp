#include "run/shard.hpp"

#include "files/result_cache.hpp"

namespace bb {

bool in_shard(const std::optional<Shard>& shard, const Scene& scene, const std::string& unit) {
  if (!shard || shard->count <= 1) return true;
  // The first 64 bits of a digest of the case's text and the unit: the same on any machine.
  const std::string d = digest(scene.source + "\n" + scene.variant + "\n" + unit);
  const unsigned long long h = std::stoull(d.substr(0, 16), nullptr, 16);
  return static_cast<int>(h % static_cast<unsigned long long>(shard->count)) == shard->index - 1;
}

}  // namespace bb
