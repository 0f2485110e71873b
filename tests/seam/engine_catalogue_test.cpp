// The engines' own descriptions: every engine names its backends, its keys belong to its
// table, each key's default is a value the loader would accept, and a case may set every
// key of every engine.
#include "seam/engine_catalogue.hpp"

#include <gtest/gtest.h>

#include <set>

#include "run/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "study/backend_names.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(EngineCatalogue, EveryEngineDescribesItsBackendsAndKeys) {
  std::set<std::string> backends;
  ASSERT_GE(engine_catalogue().size(), 3u);
  for (const EngineDescription& e : engine_catalogue()) {
    EXPECT_FALSE(e.variants.empty()) << e.engine;
    for (const EngineVariant& v : e.variants) {
      EXPECT_TRUE(backends.insert(v.name).second) << v.name;
      // Its colour, "#rrggbb": every built-in backend has one of its own.
      EXPECT_EQ(v.colour.size(), 7u) << v.name;
      EXPECT_EQ(v.colour.find_first_not_of("#0123456789abcdef"), std::string::npos) << v.name;
    }
    std::set<std::string> keys;
    for (const EngineKey& k : e.keys) {
      EXPECT_EQ(k.engine, e.engine);
      EXPECT_TRUE(keys.insert(k.key).second) << e.engine << "." << k.key;
      EXPECT_FALSE(k.meaning.empty()) << e.engine << "." << k.key;
      // The loader takes integers from 1, booleans as 0 or 1, numbers from 0.
      const double least = k.kind == KeyKind::Integer ? 1.0 : 0.0;
      EXPECT_GE(k.fallback, least) << k.key;
      EXPECT_TRUE(k.kind != KeyKind::Boolean || k.fallback == 1.0 || k.fallback == 0.0) << k.key;
    }
  }
  const std::vector<std::string> names = engine_backend_names(engine_catalogue());
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()), backends);
}

TEST(EngineCatalogue, ACaseMaySetEveryKeyOfEveryEngine) {
  std::string text = test::kMinimalCase;
  for (const EngineDescription& e : engine_catalogue()) {
    if (e.keys.empty()) continue;
    text += "\n[engines." + e.engine + "]\n";
    for (const EngineKey& k : e.keys)
      text += k.key + " = " +
              (k.kind == KeyKind::Boolean   ? std::string("true")
               : k.kind == KeyKind::Integer ? std::string("7")
                                            : std::string("0.125")) +
              "\n";
  }
  const Scene scene = test::scene_from(text);
  for (const EngineDescription& e : engine_catalogue())
    for (const EngineKey& k : e.keys)
      EXPECT_EQ(engine_setting(scene.engines, e, k.key), k.kind == KeyKind::Boolean   ? 1.0
                                                         : k.kind == KeyKind::Integer ? 7.0
                                                                                      : 0.125)
          << e.engine << "." << k.key;
}

}  // namespace
}  // namespace bb
