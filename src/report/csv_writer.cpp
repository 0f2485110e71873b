#include "report/csv_writer.hpp"

#include <fmt/format.h>

namespace bb {

namespace {

std::string number(std::optional<double> v) {
  return v ? fmt::format("{:.17g}", *v) : "";
}

/// Quotes a field when it holds a comma, a quote or a line break.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string row(const Scene& scene, const RunRecord& run) {
  const auto error = [&](const std::string& name) -> std::optional<double> {
    return run.errors ? std::optional<double>(run.errors->get(name)) : std::nullopt;
  };
  std::string out = fmt::format(
      "{},{},{},{},{},{},{},{},{},{},{},{},{},{}", scene.name, field(run.backend), number(run.dt),
      status_name(run.status), run.steps, number(run.diverged_at), number(error("position_max")),
      number(error("position_rms")), number(error("position_final")), number(error("velocity_max")),
      number(error("energy_max")),
      number(run.cost ? std::optional<double>(run.cost->ns_per_step) : std::nullopt),
      number(run.cost ? std::optional<double>(run.cost->seconds_per_simulated_second)
                      : std::nullopt),
      run.cost ? std::to_string(run.cost->repeats) : "");
  for (const ObservableResult& o : run.observables) out += "," + number(o.measured.value);
  return out + "," + field(run.reason) + "\n";
}

}  // namespace

std::string results_csv(const CaseResults& results) {
  const Scene& scene = *results.scene;
  std::string out =
      "case,backend,dt,status,steps,diverged_at,position_max,position_rms,position_final,"
      "velocity_max,energy_max,ns_per_step,seconds_per_simulated_second,cost_repeats";
  for (const Observe& o : scene.observes) out += "," + field(o.name);
  out += ",reason\n";
  out += row(scene, results.reference_run);
  for (const RunRecord& run : results.runs) out += row(scene, run);
  return out;
}

}  // namespace bb
