// SPDX-License-Identifier: MIT
// Semi-implicit back-differenced schemes of thesis appendix D: BD1 (D.10) and BD2 (D.11).
// Each step is a fixed-point iteration in which the forces are evaluated explicitly at the
// latest iterate (no Jacobian), exactly as listed in the thesis; it ends when successive
// iterates differ by less than the tolerance.
#include "dem/integrators/multistep_history.hpp"
#include "dem/integrators/scheme_factories.hpp"

namespace dem::detail {
namespace {

/// The iterates of one implicit step, kept between steps so that a step allocates nothing.
struct ImplicitWorkspace {
  KinematicState iterate;
  KinematicState next;
  Accelerations acc;
  Derivative d;
  Derivative rate;
};

/// Runs the fixed-point iteration S^{h+1} = update(S^h, a(S^h)) from the forward-Euler
/// predictor until converged, then commits at the result. `rate(d, out)` turns the derivative
/// at an iterate into the rate the step applies.
template <class Rate>
void implicit_step(const SchemeSettings& settings, SchemeDiagnostics& diagnostics,
                   ImplicitWorkspace& w, KinematicState& state, Accelerations& acc, double dt,
                   ForceEvaluator& f, const Rate& rate) {
  const double tol_x = settings.implicit_tolerance * settings.length_scale;
  const double tol_u = tol_x / dt;
  const double tol_w = settings.implicit_tolerance / dt;
  derivative_of(state, acc, w.d);
  advance(state, dt, w.d, settings.rotation, w.iterate, settings.orientation);
  bool converged = false;
  for (int h = 0; h < settings.implicit_max_iterations && !converged; ++h) {
    f.trial(w.iterate, dt, w.acc);
    ++diagnostics.force_evaluations;
    ++diagnostics.implicit_iterations;
    derivative_of(w.iterate, w.acc, w.d);
    rate(w.d, w.rate);
    advance(state, dt, w.rate, settings.rotation, w.next, settings.orientation);
    converged = max_abs_difference(w.next.position, w.iterate.position) <= tol_x &&
                max_abs_difference(w.next.velocity, w.iterate.velocity) <= tol_u &&
                max_abs_difference(w.next.angular_velocity, w.iterate.angular_velocity) <= tol_w;
    std::swap(w.iterate, w.next);
  }
  if (!converged) ++diagnostics.unconverged_steps;
  std::swap(state, w.iterate);
  f.commit(state, dt, acc);
  ++diagnostics.force_evaluations;
}

/// First-order back-differenced (backward Euler), eq D.10:
/// x_{n+1} = x_n + Δt u_{n+1}, u_{n+1} = u_n + Δt F(x_{n+1}, u_{n+1})/m.
class BackwardDifference1 final : public Scheme {
 public:
  explicit BackwardDifference1(const SchemeSettings& s) : settings_(s) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    implicit_step(settings_, diagnostics_, work_, state, acc, dt, f,
                  [](const Derivative& d, Derivative& out) { scale(1.0, d, out); });
  }

 private:
  SchemeSettings settings_;
  ImplicitWorkspace work_;
};

/// Second-order back-differenced, eq D.11 (fixed Δt):
/// x_{n+1} = (4x_n − x_{n−1} + 2Δt u_{n+1})/3, u_{n+1} = (4u_n − u_{n−1} + 2Δt a_{n+1})/3,
/// written as x_{n+1} = x_n + Δt [(x_n − x_{n−1})/Δt + 2u_{n+1}]/3 so the orientation can turn
/// by the same rule.
class BackwardDifference2 final : public MultiStepScheme {
 public:
  explicit BackwardDifference2(const SchemeSettings& s) : MultiStepScheme(s, 1) {}

 protected:
  void multistep(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                 const Derivative&) override {
    const KinematicState& prev = previous_state();
    backward_.velocity = (state.position - prev.position) / dt;
    backward_.acceleration = (state.velocity - prev.velocity) / dt;
    orientation_rate(prev.orientation, state.orientation, dt, backward_.angular_velocity);
    backward_.angular_acceleration = (state.angular_velocity - prev.angular_velocity) / dt;
    implicit_step(settings_, diagnostics_, implicit_, state, acc, dt, f,
                  [this](const Derivative& d, Derivative& out) {
                    scale(1.0 / 3.0, backward_, out);
                    add_scaled(out, 2.0 / 3.0, d);
                  });
  }

 private:
  Derivative backward_;
  ImplicitWorkspace implicit_;
};

}  // namespace

std::unique_ptr<Scheme> make_backward_difference_1(const SchemeSettings& s) {
  return std::make_unique<BackwardDifference1>(s);
}
std::unique_ptr<Scheme> make_backward_difference_2(const SchemeSettings& s) {
  return std::make_unique<BackwardDifference2>(s);
}

}  // namespace dem::detail
