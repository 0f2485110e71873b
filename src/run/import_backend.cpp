#include "run/import_backend.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "files/result_cache.hpp"
#include "files/whole_file.hpp"
#include "model/text.hpp"
#include "observe/observable_registry.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

/// Replays a file's states: step() moves to the next step, read() gives the state of the
/// file's last time at or before it (its own at every step, or the last sample's).
class ReplaySimulation : public Simulation {
 public:
  explicit ReplaySimulation(const ImportedTrajectory& run) : run_(run) {}
  void step() override {
    // The file ends before the case: the program stopped (crashed, or was stopped) there.
    if (step_ + 1 > run_.last_step())
      throw std::runtime_error(
          "the trajectory ends at t = " +
          short_number(static_cast<double>(run_.last_step()) * run_.dt) + " s of " +
          short_number(static_cast<double>(run_.run_steps) * run_.dt) + " s (" + run_.file + ")");
    ++step_;
  }
  void read(State& out) const override {
    const State& s = run_.states[static_cast<std::size_t>(step_ / run_.stride)];
    std::copy(s.begin(), s.end(), out.begin());
  }

 private:
  const ImportedTrajectory& run_;
  long step_ = 0;
};

/// The bytes of `file` (read and checked already).
std::string file_bytes(const std::string& file) {
  return read_whole_file(file).value_or("");
}

}  // namespace

ImportBackend::ImportBackend(std::string name, std::vector<ImportedTrajectory> runs)
    : name_(std::move(name)) {
  std::string all;
  for (ImportedTrajectory& run : runs) {
    all += exact_number(run.dt) + " " + digest(file_bytes(run.file)) + "\n";
    runs_.emplace(run.dt, std::move(run));
  }
  digest_ = "files " + digest(all);
}

FeatureSet ImportBackend::supports() const {
  FeatureSet all;
  for (std::size_t f = 0; f < static_cast<std::size_t>(Feature::Count); ++f)
    all.add(static_cast<Feature>(f));
  return all;
}

std::pair<std::string, std::string> ImportBackend::library_version() const {
  return {name(), digest_};
}

std::unique_ptr<Simulation> ImportBackend::start_run(const World&, const BackendSettings&,
                                                     double dt) const {
  return std::make_unique<ReplaySimulation>(run_at(dt));
}

std::vector<double> ImportBackend::dts() const {
  std::vector<double> out;
  for (auto it = runs_.rbegin(); it != runs_.rend(); ++it) out.push_back(it->first);
  return out;
}

const ImportedTrajectory& ImportBackend::run_at(double dt) const {
  const auto found = runs_.find(dt);
  if (found == runs_.end())
    throw std::logic_error(name() + " has no trajectory at dt " + format_dt(dt));
  return found->second;
}

std::optional<Cost> ImportBackend::cost(double dt) const {
  const ImportedTrajectory& run = run_at(dt);
  if (run.cost_ns.empty()) return std::nullopt;
  Cost c;
  double sum = 0.0;
  for (double ns : run.cost_ns) sum += ns;
  c.ns_per_step = sum / static_cast<double>(run.cost_ns.size());
  c.ns_per_step_min = *std::min_element(run.cost_ns.begin(), run.cost_ns.end());
  c.ns_per_step_max = *std::max_element(run.cost_ns.begin(), run.cost_ns.end());
  c.seconds_per_simulated_second = c.ns_per_step * 1e-9 / dt;
  c.repeats = 1;
  return c;
}

void ImportBackend::complete(const Scene& scene, RunRecord& run) const {
  if (!run.dt) return;
  if (ran_to_end(run.status) || run.status == RunStatus::Diverged) run.cost = cost(*run.dt);
  // What the steps between the samples would have shown is not in the file: the replay's
  // steps hold the last sample still, so whatever was measured from them is void, a value
  // or a note alike (a run that did not finish says so already).
  if (!run_at(*run.dt).samples_only() || !ran_to_end(run.status)) return;
  for (std::size_t i = 0; i < run.observables.size() && i < scene.observes.size(); ++i)
    if (observable_needs(scene.observes[i].kind, kReadsSteps))
      run.observables[i].measured = {std::nullopt, kSamplesOnlyNote};
}

std::vector<std::shared_ptr<const ImportBackend>> load_imports(
    const Scene& scene, const std::vector<TrajectoryImport>& imports) {
  std::map<std::string, std::vector<ImportedTrajectory>> by_name;
  for (const TrajectoryImport& given : imports) {
    const std::string option = "--trajectory " + given.name + "@" + format_dt(given.dt);
    const auto match = std::find_if(scene.dt.begin(), scene.dt.end(),
                                    [&](double d) { return std::abs(d - given.dt) <= 1e-9 * d; });
    if (match == scene.dt.end())
      throw CaseError(
          option, 0,
          "the step " + format_dt(given.dt) + " s is not one of case " + scene.name + "'s dt (" +
              [&] {
                std::vector<std::string> steps;
                for (double d : scene.dt) steps.push_back(format_dt(d));
                return joined(steps);
              }() +
              ")");
    std::vector<ImportedTrajectory>& runs = by_name[given.name];
    for (const ImportedTrajectory& run : runs)
      if (run.dt == *match)
        throw CaseError(option, 0, "is given twice (" + run.file + " and " + given.file + ")");
    runs.push_back(read_trajectory(scene, *match, given.file));
  }
  std::vector<std::shared_ptr<const ImportBackend>> out;
  for (auto& [name, runs] : by_name)
    out.push_back(std::make_shared<const ImportBackend>(name, std::move(runs)));
  return out;
}

}  // namespace bb
