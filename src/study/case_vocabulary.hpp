// The words a case file may use that the layers above the model define: the observable
// kinds (observe/observable_registry.hpp declares them, one row each) and the engines with
// their settings and backends (the adapters' descriptions, run/engine_catalogue.hpp). The
// loader is handed them, so that a new kind is added where it is measured and a new engine
// in its adapter, nowhere in the model.
#pragma once

#include <string>
#include <vector>

#include "seam/engine_catalogue.hpp"

namespace bb {

/// One observable kind as the case format sees it.
struct ObservableWord {
  std::string name;
  bool scene_wide = false;  ///< describes the whole scene: takes no `body`
  bool counted = false;     ///< counts events: takes an `n` (the n-th bounce)
  bool rest_speed = false;  ///< takes a `rest_speed`: below it the body is at rest
  bool axis = false;        ///< signed about an `axis`: required in 3D, +z by default in 2D
  bool level = false;       ///< takes a `level` (m), required: the height it watches
};

struct CaseVocabulary {
  std::vector<ObservableWord> observables;
  EngineCatalogue engines;
};

}  // namespace bb
