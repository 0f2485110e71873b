#include "run/results.hpp"

namespace bb {

std::string status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Ok:
      return "ok";
    case RunStatus::Diverged:
      return "diverged";
    case RunStatus::Unsupported:
      return "unsupported";
    case RunStatus::Crashed:
      return "crashed";
    case RunStatus::Timeout:
      return "timeout";
    case RunStatus::Error:
      return "error";
  }
  return "?";
}

}  // namespace bb
