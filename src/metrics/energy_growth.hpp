// Whether a run's energy grows without bound: growth that compounds (each stretch of the run
// multiplies the rise), a runaway capped only by the motion folding over, drift that adds
// (the rise grows no faster than a power of the elapsed time), or a bounded rise.
#pragma once

#include <string>
#include <vector>

namespace bb {

/// The energy's largest rise above its start so far (J), read at the ends of equal windows
/// of the run: `level[k]` after `steps[k]` steps, both increasing.
struct EnergyHistory {
  std::vector<double> level;
  std::vector<long> steps;
  double scale = 0.0;  ///< J the scene can put into motion (physics/energy_scale.hpp)
};

enum class Growth {
  Bounded,    ///< the rise stays within noise, or stops growing
  Drift,      ///< the rise keeps growing, but no faster than steady drift: it adds
  Compounds,  ///< the rise outgrows steady drift by a steady factor to the end
  Runaway,    ///< far above the scene's energy scale, capped by something other than the step
};

struct GrowthVerdict {
  Growth growth = Growth::Bounded;
  bool stable = true;  ///< Bounded and Drift are stable
  std::string reason;  ///< what the energy did, in numbers (empty when it stayed within noise)
};

/// Windows an energy history is read over (fewer when a run has fewer steps).
constexpr int kGrowthWindows = 16;

/// A rise below this fraction of the scene's energy scale is noise, not judged. The fraction
/// sits just above what rounding adds up to: a thousandth hid an explicit Euler chain's swing
/// compounding from 0.4 J to 3.6 J.
constexpr double kGrowthNoise = 1e-9;

/// A bounded energy stays near the scene's own scale: a rise that grows to more than this
/// many times what the scene can put into motion and stays there is not bounded by the step
/// but held by something else (a spring folding through itself, an engine's cap).
constexpr double kNearScale = 3.0;

/// The verdict on a history. A rise that ends above kNearScale times the scene's energy scale, more
/// than twice what it was at the end of the first window (a swing that large from the start
/// and no larger is a bound), and that levelled off on the way (in some quarter after the
/// first it grew by less than the square root of the elapsed time's factor) is a runaway:
/// something caps it (a spring folding through itself), not the step. A history of fewer
/// than kGrowthWindows windows (a run of fewer steps) cannot show how the energy grows: a
/// runaway is a rise above kNearScale times the scale and twice its first step's, anything less
/// is stable. Otherwise the rise
/// compounds when, in two quarters in a row, it grows by more than `growth_factor` times
/// what steady drift would give (a rise proportional to the elapsed time; in the run's first
/// quarter, which also holds how the motion starts, at least twice that) and the second
/// quarter's excess is not smaller than 0.85 of the first's: any power of time, t^p, slows
/// down (its excess falls to 0.5, 0.58 and 0.71 of the quarter before's), compounding does
/// not, even when it stops later (a fold that caps the energy within the scale). A rise
/// that levels off in the last quarter is bounded when it stays within kNearScale scales or
/// swung there within the first window (semi-implicit Euler near 2 / omega), a runaway when
/// it grew there. A rise that still grows in the last quarter (by over 5 percent) and does
/// not compound is drift while it stays within kNearScale scales, and unbounded (a runaway)
/// past them.
/// Rises below kGrowthNoise of the scale are noise.
GrowthVerdict judge_growth(const EnergyHistory& history, double growth_factor);

std::string growth_name(Growth growth);

}  // namespace bb
