#include "mujoco_warnings.hpp"

#include <algorithm>

namespace bb {

namespace {

/// A warning MuJoCo counted in this data (a reset keeps its own warning's count at 1 at
/// least: mj_checkAcc counts again after mj_resetData clears the counters).
bool counted(const mjData* data, int warning) {
  return data->warning[warning].number > 0;
}

}  // namespace

bool MujocoWarnings::seen(EngineIntervention::Kind kind) const {
  return std::any_of(seen_.begin(), seen_.end(),
                     [kind](const EngineIntervention& i) { return i.kind == kind; });
}

std::string MujocoWarnings::body_of_dof(int dof) const {
  if (dof < 0 || dof >= model_->nv) return "a body";
  const int id = model_->dof_bodyid[dof];
  const auto i = static_cast<std::size_t>(id - 1);
  return id >= 1 && i < world_.bodies.size() ? "body '" + world_.bodies[i].name + "'" : "a body";
}

std::string MujocoWarnings::body_of_qpos(int qpos) const {
  // The joint whose coordinates hold it: the last one starting at or before it.
  int joint = -1;
  for (int j = 0; j < model_->njnt; ++j)
    if (model_->jnt_qposadr[j] <= qpos) joint = j;
  return joint < 0 ? "a body" : body_of_dof(model_->jnt_dofadr[joint]);
}

void MujocoWarnings::latch_reset(const mjData* data, long steps) {
  // Each check resets at the start of mj_step, from the state the step before left.
  struct Check {
    int warning;
    const char* name;
    const char* what;
  };
  for (const Check& c : {Check{mjWARN_BADQPOS, "mjWARN_BADQPOS", "a position"},
                         Check{mjWARN_BADQVEL, "mjWARN_BADQVEL", "a velocity"},
                         Check{mjWARN_BADQACC, "mjWARN_BADQACC", "an acceleration"}}) {
    if (!counted(data, c.warning)) continue;
    const int at = data->warning[c.warning].lastinfo;
    const std::string body = c.warning == mjWARN_BADQPOS ? body_of_qpos(at) : body_of_dof(at);
    seen_.push_back(
        {EngineIntervention::Kind::Reset, steps - 1,
         "MuJoCo reset its state to the model's initial one (qpos0: a free body at the origin, "
         "a hinged one where it started, all at rest)",
         std::string(c.name) + ", " + c.what + " of " + body + " NaN or beyond 1e10 (mjMAXVAL, " +
             "at degree of freedom " + std::to_string(at) +
             "): MuJoCo 2.2.2 then resets the data to the model's initial state and steps on"});
    return;
  }
}

void MujocoWarnings::latch_full(const mjData* data, long steps) {
  const bool contacts = counted(data, mjWARN_CONTACTFULL);
  if (!contacts && !counted(data, mjWARN_CNSTRFULL)) return;
  const std::string cap =
      contacts ? "contacts at its cap of " + std::to_string(model_->nconmax) + " (nconmax)"
               : "constraint rows at its cap of " + std::to_string(model_->njmax) + " (njmax)";
  seen_.push_back({EngineIntervention::Kind::Cap, steps - 1, "MuJoCo held the " + cap,
                   std::string(contacts ? "mjWARN_CONTACTFULL" : "mjWARN_CNSTRFULL") +
                       ": what did not fit was dropped from the step"});
}

void MujocoWarnings::after_step(const mjModel* model, const mjData* data, long steps) {
  model_ = model;
  if (!seen(EngineIntervention::Kind::Reset)) latch_reset(data, steps);
  if (!seen(EngineIntervention::Kind::Cap)) latch_full(data, steps);
}

}  // namespace bb
