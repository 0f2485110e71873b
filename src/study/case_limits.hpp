// Limits that protect the machine, checked from a case's numbers alone (how many bodies,
// springs, contact pairs, samples, steps and sweep points it asks for) before anything of
// the case's size is built: a short file that asks for hours of work or gigabytes is
// refused in microseconds, whatever it asks for.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace bb {

/// Most particles a [grid] may generate, and most bodies in a case: a 300 x 300 sheet fits;
/// what a run holds grows with bodies times samples, which kMaxBodySamples bounds.
inline constexpr long kMaxGridParticles = 100000;
inline constexpr long kMaxBodies = 100000;
/// Most steps one run may take (duration / dt): accuracy runs, sweep points and every trial
/// of a stability search alike.
inline constexpr double kMaxStepsPerRun = 1e7;
/// Most samples a run keeps (duration / sample), and most body-samples (samples x bodies):
/// what is held in memory and drawn.
inline constexpr double kMaxSamples = 1e5;
inline constexpr double kMaxBodySamples = 2e6;
/// Most body-steps of one backend's whole dt sweep (steps x (bodies + springs + contact
/// pairs), summed), and of one backend's [[sweep]] (points x steps at report_dt x the same).
inline constexpr double kMaxSweepWork = 1e9;
/// Most pairs of bodies [[contact]] entries may make touch: ["*"] among n bodies is
/// n (n - 1) / 2 of them, each checked at every step.
inline constexpr double kMaxContactPairs = 1e6;
/// Most values one [[sweep]] may take: each is a run of the whole case per backend.
inline constexpr int kMaxSweepValues = 1000;
/// Most runs a map (two [[sweep]]s: points x the runs of each point) takes on one machine,
/// in one report or in one shard of it: a larger map is refused with its run count and told
/// how many shards it needs (`report --shard I/N`, scripts/slurm/submit).
inline constexpr double kMaxMapRunsPerMachine = 20000;

/// True when `ratio` is within rounding of a whole number >= 1 (a step that divides a
/// sample, a sample that divides the duration).
inline bool is_whole_multiple(double ratio) {
  const double r = std::round(ratio);
  return r >= 1.0 && std::abs(ratio - r) <= 1e-9 * r;
}

/// What a case asks for, as numbers, with the lines to name when a limit is passed.
struct CaseSize {
  double duration = 0.0;
  double sample = 0.0;
  std::vector<double> dt;
  double report_dt = 0.0;
  double bodies = 0.0;          ///< [[body]] tables plus the [grid]'s particles
  double fixed_bodies = 0.0;    ///< of those, the fixed ones (two fixed bodies never touch)
  double springs = 0.0;         ///< [[spring]] tables plus the [grid]'s springs
  bool all_pairs = false;       ///< some [[contact]] says ["*"]
  double named_pairs = 0.0;     ///< [[contact]] entries that name one pair
  double sweep_points = 0.0;    ///< values of the [[sweep]] (of a map: their product); 0: none
  double sweep_least_dt = 0.0;  ///< the smallest value of a [[sweep]] of "dt"; 0: none
  int case_line = 1;
  int sample_line = 0;
  int dt_line = 0;
  int contact_line = 0;  ///< the ["*"] [[contact]]
  int sweep_line = 0;    ///< the [[sweep]]'s values or range
};

/// Pairs of bodies that can touch each other: with ["*"] every pair but those of two fixed
/// bodies, else one per [[contact]] that names a pair (an upper bound: the loader refuses a
/// pair named twice).
double contact_pair_count(const CaseSize& size);

/// Throws a CaseError naming `file` and the line of the first limit `size` passes.
void check_case_size(const std::string& file, const CaseSize& size);

/// What a [grid] generates, from its numbers.
struct GridCounts {
  double particles = 0.0;
  double springs = 0.0;
  double fixed = 0.0;  ///< anchored particles
};
/// Particles and springs of a [grid] of `size` ([cols, rows] or [x, y, z]) joined to
/// `neighbours` lattice neighbours, its top row fixed when `anchored` (the springs between
/// two fixed particles left out), as the generator builds them.
GridCounts grid_counts(int dims, const std::vector<int>& size, int neighbours, bool anchored);

/// Particles every [grid] has generated in this process so far: tests check with it that
/// a refusal comes before the work.
long grid_particles_made();

}  // namespace bb
