// What MuJoCo 2.2.2 does on its own that its state does not show, read from its warning
// counters (mjData::warning) after each step. mj_step's checks (engine_forward.c:
// mj_checkPos, mj_checkVel, mj_checkAcc) reset the data to the model's initial state when a
// position, velocity or acceleration is NaN or beyond mjMAXVAL (1e10), and step on; a full
// contact list or constraint buffer (mjWARN_CONTACTFULL, mjWARN_CNSTRFULL, at nconmax 100 and
// njmax 500 rows, MuJoCo 2.2.2's defaults) drops what does not fit.
#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

class MujocoWarnings {
 public:
  /// For `world`, whose body i is MuJoCo's body i + 1 (0 is the world).
  explicit MujocoWarnings(const World& world) : world_(world) {}
  /// Reads the counters of `data` (of `model`) after step number `steps` (1 for the first).
  void after_step(const mjModel* model, const mjData* data, long steps);
  /// The first reset and the first dropped contact or constraint, in the order they happened.
  const std::vector<EngineIntervention>& interventions() const { return seen_; }

 private:
  bool seen(EngineIntervention::Kind kind) const;
  /// "body 'mote'": the body owning degree of freedom `dof` (or qpos coordinate `qpos`).
  std::string body_of_dof(int dof) const;
  std::string body_of_qpos(int qpos) const;
  void latch_reset(const mjData* data, long steps);
  void latch_full(const mjData* data, long steps);

  const World& world_;
  const mjModel* model_ = nullptr;
  std::vector<EngineIntervention> seen_;
};

}  // namespace bb
