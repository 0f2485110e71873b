#include "run/stability_chains.hpp"

#include <algorithm>
#include <numeric>

#include "run/case_runner.hpp"
#include "run/stability_watch.hpp"
#include "run/wire.hpp"

namespace bb {

namespace {

/// Seconds a trial of `scene` at `dt` may take in its child: as a run's limit, for every
/// step it may take (the usual trial and, past the theory's limit, the longer one).
double trial_time_limit(const Scene& scene, double dt, double timeout, bool longer) {
  if (timeout > 0.0) return timeout;
  const double steps = static_cast<double>(StabilityWatch::trial_steps(scene, dt)) *
                       (longer ? 1.0 + static_cast<double>(kTheoryProbeFactor) : 1.0);
  return steps_time_limit(scene, steps);
}

}  // namespace

StabilityChains::StabilityChains(const Scene& scene, std::vector<const Backend*> backends,
                                 Options options)
    : scene_(scene),
      options_(std::move(options)),
      out_(backends.size()),
      pool_(options_.jobs, options_.isolation) {
  for (const Backend* b : backends)
    chains_.emplace_back(b, theory_for(scene, b->name()),
                         StabilitySearch(scene.stability.dt_min, scene.stability.dt_max));
}

std::vector<StabilityResult> StabilityChains::run() {
  for (std::size_t i = 0; i < chains_.size(); ++i) advance(i);
  look_ahead();
  pool_.run();
  return std::move(out_);
}

std::optional<StabilityTrial> StabilityChains::at_hand(Chain& c, double dt) {
  if (const auto f = c.finished.find(dt); f != c.finished.end()) {
    const StabilityTrial trial = f->second;
    c.finished.erase(f);
    // A trial run ahead was not looked for in the kept results when it started: it counts
    // as run now that the search asks for it (a trial it asked for counted when looked for).
    if (c.ahead.erase(dt) > 0 && options_.cache) options_.cache->count_run();
    out_[&c - chains_.data()].step_seconds += trial.step_seconds;
    return trial;
  }
  if (const StabilityTrial* judged = judged_by_accuracy(c, dt)) return *judged;
  return std::nullopt;
}

const StabilityTrial* StabilityChains::judged_by_accuracy(const Chain& c, double dt) const {
  if (!options_.known) return nullptr;
  const auto found = options_.known->find({c.backend->name(), dt});
  if (found == options_.known->end()) return nullptr;
  // Not one stable past the theory's limit: judge_step() then runs a longer trial.
  const bool needs_longer = found->second.stable && c.theory && dt > *c.theory;
  return needs_longer ? nullptr : &found->second;
}

void StabilityChains::advance(std::size_t i) {
  Chain& c = chains_[i];
  if (c.over) return;
  while (const auto dt = c.search.next()) {
    if (const auto trial = at_hand(c, *dt)) {
      c.search.record(*dt, *trial);
      continue;
    }
    if (c.running.contains(*dt)) return;
    RunCache* cache = options_.cache;
    const std::string key = cache ? cache->key(scene_, "stability trial", *c.backend, *dt) : "";
    if (const auto kept = cache ? cache->find(key) : std::nullopt) {
      c.search.record(*dt, wire::decode_trial(*kept));
      continue;
    }
    submit(i, *dt, key);
    return;
  }
  c.over = true;
  // Trials run ahead that the search did not ask for are stopped: the cores go to others.
  for (const auto& [dt, piece] : c.running) pool_.cancel(piece);
  c.running.clear();
  out_[i].backend = c.backend->name();
  c.search.fill(out_[i]);
  if (options_.on_done) options_.on_done(c.backend->name());
}

void StabilityChains::submit(std::size_t i, double dt, const std::string& key) {
  Chain& c = chains_[i];
  const Backend& b = *c.backend;
  const Scene& scene = scene_;
  const std::optional<double> theory = c.theory;
  c.running[dt] = pool_.submit(
      b.name() + " stability at dt " + std::to_string(dt),
      [&b, &scene, dt, theory] { return wire::encode(judge_step(b, scene, dt, theory)); },
      trial_time_limit(scene_, dt, options_.timeout, theory && dt > *theory),
      [this, i, dt, key](const ChildOutcome& o) { finished(i, dt, key, o); }, priority(c));
}

void StabilityChains::finished(std::size_t i, double dt, const std::string& key,
                               const ChildOutcome& o) {
  const bool done = o.kind == ChildOutcome::Kind::Done;
  const StabilityTrial trial =
      done ? wire::decode_trial(o.payload) : StabilityTrial{false, o.reason, "failed"};
  // A trial that did not finish (a crash, a timeout) is tried again next time.
  if (!key.empty())
    options_.cache->keep(key, done ? o.payload : wire::encode(trial), trial.growth != "failed");
  Chain& c = chains_[i];
  c.running.erase(dt);
  c.child_seconds += o.seconds;
  ++c.children;
  if (!c.over) c.finished[dt] = trial;
  advance(i);
  look_ahead();
}

double StabilityChains::priority(const Chain& c) {
  return c.children == 0 ? 0.0 : c.child_seconds / c.children;
}

StabilitySearch::Known StabilityChains::known(Chain& c, double dt) {
  using Known = StabilitySearch::Known;
  const auto verdict = [](const StabilityTrial& t) {
    return t.stable ? Known::Stable : Known::Unstable;
  };
  if (c.running.contains(dt)) return Known::Running;
  if (const auto f = c.finished.find(dt); f != c.finished.end()) return verdict(f->second);
  if (const StabilityTrial* judged = judged_by_accuracy(c, dt)) return verdict(*judged);
  if (const auto k = c.kept.find(dt); k != c.kept.end()) return verdict(k->second);
  // A trial kept from an earlier report is looked at without counting it as reused.
  if (options_.cache)
    if (const auto bytes =
            options_.cache->peek(options_.cache->key(scene_, "stability trial", *c.backend, dt))) {
      const StabilityTrial trial = wire::decode_trial(*bytes);
      c.kept[dt] = trial;
      return verdict(trial);
    }
  return Known::Nothing;
}

void StabilityChains::look_ahead() {
  int free = pool_.free_slots();
  if (free <= 0) return;
  // The waiting searches, slowest trials first.
  std::vector<std::size_t> waiting;
  for (std::size_t i = 0; i < chains_.size(); ++i)
    if (!chains_[i].over && !chains_[i].running.empty()) waiting.push_back(i);
  std::stable_sort(waiting.begin(), waiting.end(), [&](std::size_t a, std::size_t b) {
    return priority(chains_[a]) > priority(chains_[b]);
  });
  for (std::size_t i : waiting) {
    Chain& c = chains_[i];
    const auto known_here = [&](double dt) { return known(c, dt); };
    for (double dt : c.search.likely_next(free, known_here)) {
      RunCache* cache = options_.cache;
      submit(i, dt, cache ? cache->key(scene_, "stability trial", *c.backend, dt) : "");
      c.ahead.insert(dt);
      if (--free == 0) return;
    }
  }
}

}  // namespace bb
