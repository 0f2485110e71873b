#include "report/results_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "study/case_error.hpp"

namespace bb {

namespace {

using Json = nlohmann::ordered_json;

/// What reads one results file: its name, for every message.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw CaseError(file_, 0, where + " " + problem);
  }

  const Json& member(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) fail(where, "has no '" + key + "'");
    return object.at(key);
  }

  std::string string(const Json& v, const std::string& where) const {
    if (!v.is_string()) fail(where, "is not a string");
    return v.get<std::string>();
  }

  /// A number, or null (nullopt).
  std::optional<double> number_or_null(const Json& v, const std::string& where) const {
    if (v.is_null()) return std::nullopt;
    if (!v.is_number()) fail(where, "is neither a number nor null");
    return v.get<double>();
  }

  RunStatus status(const Json& v, const std::string& where) const {
    const std::string name = string(v, where);
    for (RunStatus s :
         {RunStatus::Ok, RunStatus::Diverged, RunStatus::Unsupported, RunStatus::Crashed,
          RunStatus::Timeout, RunStatus::Error, RunStatus::Capped})
      if (status_name(s) == name) return s;
    fail(where, "is '" + name + "', not a status beachball writes");
  }

  std::optional<ErrorMetrics> errors(const Json& v, const std::string& where) const {
    if (v.is_null()) return std::nullopt;
    ErrorMetrics e;
    const std::pair<const char*, double ErrorMetrics::*> fields[] = {
        {"position_max", &ErrorMetrics::position_max},
        {"position_rms", &ErrorMetrics::position_rms},
        {"position_final", &ErrorMetrics::position_final},
        {"velocity_max", &ErrorMetrics::velocity_max},
        {"energy_max", &ErrorMetrics::energy_max}};
    for (const auto& [key, field] : fields) {
      const std::string at = where + "." + key;
      const std::optional<double> value = number_or_null(member(v, key, where), at);
      if (!value) fail(at, "is null");
      e.*field = *value;
    }
    return e;
  }

  std::vector<ObservableResult> observables(const Json& v, const std::string& where) const {
    if (!v.is_object()) fail(where, "is not an object");
    std::vector<ObservableResult> out;
    for (const auto& [name, o] : v.items()) {
      const std::string at = where + "." + name;
      ObservableResult r;
      r.name = name;
      r.measured.value = number_or_null(member(o, "value", at), at + ".value");
      r.reference = number_or_null(member(o, "reference", at), at + ".reference");
      if (o.contains("note")) r.measured.note = string(o.at("note"), at + ".note");
      out.push_back(r);
    }
    return out;
  }

  RunRecord run(const Json& v, const std::string& where) const {
    RunRecord r;
    r.backend = string(member(v, "backend", where), where + ".backend");
    r.dt = number_or_null(member(v, "dt", where), where + ".dt");
    r.status = status(member(v, "status", where), where + ".status");
    if (v.contains("reason")) r.reason = string(v.at("reason"), where + ".reason");
    r.errors = errors(member(v, "errors", where), where + ".errors");
    r.observables = observables(member(v, "observables", where), where + ".observables");
    return r;
  }

 private:
  std::string file_;
};

/// The 1-based line of byte `offset` of `text` (nlohmann counts bytes read, the bad one too).
int line_of(const std::string& text, std::size_t offset) {
  const std::size_t end = std::min(text.size(), offset > 0 ? offset - 1 : 0);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + end, '\n'));
}

}  // namespace

KeptResults read_results_json(const std::string& text, const std::string& file) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw CaseError(file, line_of(text, e.byte), "is not JSON: " + std::string(e.what()));
  }
  const Reader r(file);
  if (!j.is_object() || !j.contains("schema") || j["schema"] != "beachball-results/1")
    throw CaseError(file, 0,
                    "is not beachball's results (\"schema\": \"beachball-results/1\" missing)");
  KeptResults out;
  out.case_name = r.string(r.member(j, "case", "the results"), "\"case\"");
  const Json& runs = r.member(j, "runs", "the results");
  if (!runs.is_array()) r.fail("\"runs\"", "is not a list");
  for (std::size_t k = 0; k < runs.size(); ++k)
    out.runs.push_back(r.run(runs[k], "runs[" + std::to_string(k) + "]"));
  return out;
}

KeptResults read_results_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) throw CaseError(path, 0, "cannot be read: " + ec.message());
  if (size > (std::uintmax_t{256} << 20))
    throw CaseError(path, 0, "is larger than 256 MiB; results are a few hundred kilobytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(path, 0, "cannot be opened for reading");
  std::ostringstream text;
  if (size > 0 && !(text << in.rdbuf())) throw CaseError(path, 0, "cannot be read");
  return read_results_json(text.str(), path);
}

}  // namespace bb
