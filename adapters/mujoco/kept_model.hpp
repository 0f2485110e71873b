// The last MuJoCo model a process compiled and the data of its last run, kept for the next
// run of the same XML: the cost pass builds one scene for every repeat.
#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <utility>

namespace bb {

/// A copy of the model and the data reset (mj_resetData) are what compiling the XML and
/// mj_makeData give, without parsing it again and clearing MuJoCo's stack of megabytes.
class KeptModel {
 public:
  KeptModel() = default;
  KeptModel(const KeptModel&) = delete;
  KeptModel& operator=(const KeptModel&) = delete;
  /// A model of `xml` and data for it, the caller's to give back or delete; throws
  /// std::runtime_error when MuJoCo refuses the model.
  std::pair<mjModel*, mjData*> take(const std::string& xml);
  /// Keeps `data`, of a run of `xml` that is over, for the next run of it.
  void give_back(const std::string& xml, mjData* data);

 private:
  void forget();
  std::string xml_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

/// This process's one KeptModel.
KeptModel& kept_model();

}  // namespace bb
