// A hybrid integrator: smooth motion by an adaptive GSL method, discontinuities as events.
// Each event function is watched for a crossing from positive to zero or below; the
// crossing is located to a set time tolerance by re-integrating from the step's start,
// the model's reset map is applied there (an impulse, a change of mode), and integration
// restarts. Nothing steps across a discontinuity and patches it up afterwards.
#pragma once

#include <gsl/gsl_odeiv2.h>

#include <cstddef>
#include <vector>

namespace bb {

/// The system a HybridIntegrator advances: an ODE in its current mode, event functions,
/// and what happens at each event.
class HybridModel {
 public:
  virtual ~HybridModel() = default;
  /// Number of state values y.
  virtual std::size_t dimension() const = 0;
  /// dy/dt at (t, y) in the current mode.
  virtual void derivatives(double t, const double* y, double* dydt) = 0;
  /// The Jacobian d(dy/dt)/dy (row-major, dimension^2) and d(dy/dt)/dt at (t, y), for the
  /// implicit methods (msbdf). The default differentiates derivatives() numerically.
  virtual void jacobian(double t, const double* y, double* dfdy, double* dfdt);
  /// The longest step (seconds) that cannot carry the state across an event and back
  /// (a ball through a thin panel, where the gap is positive on both sides); the default
  /// sets no limit.
  virtual double max_step(double t, const double* y);
  /// Number of event functions.
  virtual std::size_t event_count() const = 0;
  /// Event function values g_k(t, y); event k happens where g_k falls to zero from above.
  virtual void events(double t, const double* y, double* g) = 0;
  /// The reset map of event k at time t: changes y and the mode in place.
  virtual void apply(std::size_t k, double t, double* y) = 0;
};

class HybridIntegrator;

/// Told of each stretch of the solution the integrator crosses with no event inside, to
/// find what happens between its steps (the peaks of a smooth quantity).
class SpanWatcher {
 public:
  virtual ~SpanWatcher() = default;
  /// The solution went smoothly from (t0, y0) to (t1, y1), just before any event at t1;
  /// while this runs, `integrator.dense_state(t, out)` gives y at any t in [t0, t1].
  virtual void span(HybridIntegrator& integrator, double t0, const double* y0, double t1,
                    const double* y1) = 0;
};

/// How the smooth parts are solved and how precisely events are placed.
struct HybridOptions {
  const gsl_odeiv2_step_type* method = gsl_odeiv2_step_rk8pd;
  double absolute_tolerance = 1e-10;
  double relative_tolerance = 1e-10;
  /// The weight of h |y'| in each value's error allowance, abs + rel (|y| + weight h |y'|)
  /// (GSL's a_dydt); 0 keeps the error within abs + rel |y| (GSL's y control).
  double derivative_weight = 0.0;
  /// Largest internal step, seconds; 0: no limit.
  double max_step = 0.0;
  /// Events are placed to within this many seconds.
  double event_tolerance = 1e-12;
  /// Safety bound on events in one advance_to call; exceeding it throws.
  long max_events_per_advance = 1000000;
  /// Told of every smooth span (not owned); null: none.
  SpanWatcher* watcher = nullptr;
};

/// One located event.
struct EventRecord {
  double time = 0.0;  ///< seconds
  std::size_t index = 0;
};

class HybridIntegrator {
 public:
  HybridIntegrator(HybridModel& model, const HybridOptions& options, std::vector<double> y0,
                   double t0 = 0.0);
  ~HybridIntegrator();
  HybridIntegrator(const HybridIntegrator&) = delete;
  HybridIntegrator& operator=(const HybridIntegrator&) = delete;

  /// Integrates to exactly `target` (>= time()), handling every event on the way; throws
  /// std::runtime_error when the solver fails.
  void advance_to(double target);
  const std::vector<double>& state() const { return y_; }
  /// Lets `edit` change the state at the current time (an impulse), then restarts the solver.
  template <class Edit>
  void change_state(Edit&& edit) {
    edit(y_.data());
    restart();
  }
  double time() const { return t_; }
  /// Accepted internal steps so far, events' re-integrations not counted.
  long steps() const { return steps_; }
  /// Every event so far, in time order.
  const std::vector<EventRecord>& events() const { return events_; }
  /// y at time t within the span a SpanWatcher is being told of, integrated afresh from the
  /// span's start to the solver's tolerance.
  void dense_state(double t, std::vector<double>& out) { state_at(t, out); }

 private:
  /// y at time `t` (t0_ <= t <= the step's end), integrated afresh from (t0_, y0_).
  void state_at(double t, std::vector<double>& out);
  /// The time, within (from, to], where event k crosses, to the event tolerance.
  double locate(std::size_t k, double from, double g_from, double to, double g_to);
  /// Forget the solver's history after a reset map changed the state.
  void restart();

  HybridModel& model_;
  HybridOptions options_;
  gsl_odeiv2_system system_{};
  gsl_odeiv2_step* stepper_ = nullptr;
  gsl_odeiv2_control* control_ = nullptr;
  gsl_odeiv2_evolve* evolve_ = nullptr;
  gsl_odeiv2_driver* refine_ = nullptr;  ///< re-integrates sub-intervals to place events
  std::vector<double> y_, y0_, probe_, g0_, g1_, g_probe_;
  std::vector<double> located_;  ///< per event: where it was located in this step, or -1
  double t_ = 0.0;
  double t0_ = 0.0;  ///< start of the step being examined
  double h_ = 0.0;   ///< the next step size the controller proposes
  long steps_ = 0;
  std::vector<EventRecord> events_;
};

}  // namespace bb
