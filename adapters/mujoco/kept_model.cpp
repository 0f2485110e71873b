#include "kept_model.hpp"

#include <cstring>
#include <memory>
#include <stdexcept>

namespace bb {

namespace {

/// The model compiled from `xml`, through a virtual file (mjVFS is large: on the heap, and
/// left for mj_defaultVFS to clear).
mjModel* compile_model(const std::string& xml) {
  const std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* name = "beachball.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: no room for the model in its virtual file system");
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML(name, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (model == nullptr) throw std::runtime_error(std::string("MuJoCo refused the model: ") + error);
  return model;
}

}  // namespace

std::pair<mjModel*, mjData*> KeptModel::take(const std::string& xml) {
  if (model_ == nullptr || xml != xml_) {
    mjModel* compiled = compile_model(xml);
    forget();
    model_ = compiled, xml_ = xml;
  }
  mjModel* model = mj_copyModel(nullptr, model_);
  // mj_makeData resets what it makes; only data kept from an earlier run needs a reset.
  mjData* data = data_;
  data_ = nullptr;
  if (data != nullptr)
    mj_resetData(model, data);
  else
    data = mj_makeData(model);
  return {model, data};
}

void KeptModel::give_back(const std::string& xml, mjData* data) {
  if (data_ == nullptr && model_ != nullptr && xml == xml_)
    data_ = data;
  else
    mj_deleteData(data);
}

void KeptModel::forget() {
  if (data_ != nullptr) mj_deleteData(data_);
  if (model_ != nullptr) mj_deleteModel(model_);
  data_ = nullptr, model_ = nullptr;
}

KeptModel& kept_model() {
  static KeptModel kept;
  return kept;
}

}  // namespace bb
