#include "reference/hybrid_integrator.hpp"

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace bb {

namespace {

int call_derivatives(double t, const double y[], double dydt[], void* model) {
  static_cast<HybridModel*>(model)->derivatives(t, y, dydt);
  return GSL_SUCCESS;
}

int call_jacobian(double t, const double y[], double* dfdy, double dfdt[], void* model) {
  static_cast<HybridModel*>(model)->jacobian(t, y, dfdy, dfdt);
  return GSL_SUCCESS;
}

void check(int status, const char* what, double t) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("GSL ") + what + " failed at t = " + std::to_string(t) +
                             " s: " + gsl_strerror(status));
}

}  // namespace

void HybridModel::jacobian(double t, const double* y, double* dfdy, double* dfdt) {
  // Central differences, each value perturbed by a step scaled to its size.
  const std::size_t n = dimension();
  std::vector<double> probe(y, y + n), up(n), down(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double h = 1e-7 * std::max(1.0, std::abs(y[j]));
    probe[j] = y[j] + h;
    derivatives(t, probe.data(), up.data());
    probe[j] = y[j] - h;
    derivatives(t, probe.data(), down.data());
    probe[j] = y[j];
    for (std::size_t i = 0; i < n; ++i) dfdy[i * n + j] = (up[i] - down[i]) / (2.0 * h);
  }
  const double h = 1e-7 * std::max(1.0, std::abs(t));
  derivatives(t + h, y, up.data());
  derivatives(t - h, y, down.data());
  for (std::size_t i = 0; i < n; ++i) dfdt[i] = (up[i] - down[i]) / (2.0 * h);
}

double HybridModel::max_step(double, const double*) {
  return std::numeric_limits<double>::infinity();
}

HybridIntegrator::HybridIntegrator(HybridModel& model, const HybridOptions& options,
                                   std::vector<double> y0, double t0)
    : model_(model), options_(options), y_(std::move(y0)), t_(t0) {
  gsl_set_error_handler_off();
  const std::size_t n = model.dimension();
  if (y_.size() != n) throw std::invalid_argument("hybrid integrator: state size mismatch");
  system_ = {call_derivatives, call_jacobian, n, &model_};
  stepper_ = gsl_odeiv2_step_alloc(options.method, n);
  control_ = gsl_odeiv2_control_standard_new(options.absolute_tolerance, options.relative_tolerance,
                                             1.0, options.derivative_weight);
  evolve_ = gsl_odeiv2_evolve_alloc(n);
  refine_ = gsl_odeiv2_driver_alloc_standard_new(
      &system_, options.method, 1e-6, options.absolute_tolerance, options.relative_tolerance, 1.0,
      options.derivative_weight);
  if (!stepper_ || !control_ || !evolve_ || !refine_)
    throw std::runtime_error("GSL could not allocate the hybrid integrator");
  // Multistep methods (msbdf) read their tolerances through a driver; the others ignore it.
  gsl_odeiv2_step_set_driver(stepper_, refine_);
  y0_.resize(n);
  probe_.resize(n);
  g0_.resize(model.event_count());
  g1_.resize(model.event_count());
  g_probe_.resize(model.event_count());
  located_.resize(model.event_count());
  h_ = 1e-6;
}

HybridIntegrator::~HybridIntegrator() {
  gsl_odeiv2_driver_free(refine_);
  gsl_odeiv2_evolve_free(evolve_);
  gsl_odeiv2_control_free(control_);
  gsl_odeiv2_step_free(stepper_);
}

void HybridIntegrator::restart() {
  gsl_odeiv2_evolve_reset(evolve_);
  gsl_odeiv2_step_reset(stepper_);
}

void HybridIntegrator::state_at(double t, std::vector<double>& out) {
  out = y0_;
  if (t == t0_) return;
  double at = t0_;
  gsl_odeiv2_driver_reset(refine_);
  gsl_odeiv2_driver_reset_hstart(refine_, std::min(h_, t - t0_));
  check(gsl_odeiv2_driver_apply(refine_, &at, t, out.data()), "event refinement", t0_);
}

double HybridIntegrator::locate(std::size_t k, double from, double g_from, double to, double g_to) {
  // Illinois regula falsi on g_k(t): keeps the bracket [from, to] with g(from) > 0 >= g(to).
  int side = 0;
  while (to - from > options_.event_tolerance) {
    double t = (from * g_to - to * g_from) / (g_to - g_from);
    // Bisect when the secant lands on or outside the bracket's ends.
    if (!(t > from && t < to)) t = 0.5 * (from + to);
    state_at(t, probe_);
    model_.events(t, probe_.data(), g_probe_.data());
    const double g = g_probe_[k];
    if (g > 0.0) {
      from = t, g_from = g;
      if (side == -1) g_to *= 0.5;
      side = -1;
    } else {
      to = t, g_to = g;
      if (side == +1) g_from *= 0.5;
      side = +1;
    }
  }
  return to;
}

void HybridIntegrator::advance_to(double target) {
  long events_here = 0;
  while (t_ < target) {
    // One adaptive step from (t0_, y0_), never past the target.
    t0_ = t_;
    y0_ = y_;
    model_.events(t_, y_.data(), g0_.data());
    const double h_limit = std::min(options_.max_step > 0.0 ? options_.max_step : target - t_,
                                    model_.max_step(t_, y_.data()));
    h_ = std::min({h_, h_limit, target - t_});
    check(
        gsl_odeiv2_evolve_apply(evolve_, control_, stepper_, &system_, &t_, target, &h_, y_.data()),
        "step", t_);
    ++steps_;
    // The earliest event whose function crossed from above zero to zero or below; events
    // located at the same instant (within the tolerance) all happen there, in order.
    model_.events(t_, y_.data(), g1_.data());
    double first = t_;
    bool any = false;
    for (std::size_t k = 0; k < g1_.size(); ++k) {
      located_[k] = -1.0;
      if (!(g0_[k] > 0.0 && g1_[k] <= 0.0)) continue;
      located_[k] = locate(k, t0_, g0_[k], t_, g1_[k]);
      if (!any || located_[k] < first) first = located_[k];
      any = true;
    }
    if (!any) {
      if (options_.watcher) options_.watcher->span(*this, t0_, y0_.data(), t_, y_.data());
      continue;
    }
    // Move to the event, apply its reset map, and restart the solver from there.
    state_at(first, y_);
    t_ = first;
    if (options_.watcher) options_.watcher->span(*this, t0_, y0_.data(), t_, y_.data());
    for (std::size_t k = 0; k < g1_.size(); ++k) {
      if (located_[k] < 0.0 || located_[k] > first + options_.event_tolerance) continue;
      model_.apply(k, t_, y_.data());
      events_.push_back({t_, k});
    }
    restart();
    if (++events_here > options_.max_events_per_advance)
      throw std::runtime_error("more than " + std::to_string(options_.max_events_per_advance) +
                               " events before t = " + std::to_string(target) + " s");
  }
  t_ = target;
}

}  // namespace bb
