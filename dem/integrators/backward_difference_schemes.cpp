// SPDX-License-Identifier: MIT
// Semi-implicit back-differenced schemes of thesis appendix D: BD1 (D.10) and BD2 (D.11).
// Each step is a fixed-point iteration in which the forces are evaluated explicitly at the
// latest iterate (no Jacobian), exactly as listed in the thesis; it ends when successive
// iterates differ by less than the tolerance.
#include <cmath>
#include <functional>

#include "dem/integrators/multistep_history.hpp"
#include "dem/integrators/scheme_factories.hpp"

namespace dem::detail {
namespace {

/// Runs the fixed-point iteration S^{h+1} = update(S^h, a(S^h)) from the forward-Euler
/// predictor until converged, then commits at the result. Returns the iteration count.
struct ImplicitIteration {
  const SchemeSettings& settings;
  SchemeDiagnostics& diagnostics;

  void run(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
           const std::function<Derivative(const Derivative& iterate)>& rate) const {
    const double tol_x = settings.implicit_tolerance * settings.length_scale;
    const double tol_u = tol_x / dt;
    const double tol_w = settings.implicit_tolerance / dt;
    KinematicState iterate;
    advance(state, dt, derivative_of(state, acc), settings.rotation, iterate);
    KinematicState next;
    Accelerations a;
    bool converged = false;
    for (int h = 0; h < settings.implicit_max_iterations && !converged; ++h) {
      f.trial(iterate, dt, a);
      ++diagnostics.force_evaluations;
      ++diagnostics.implicit_iterations;
      advance(state, dt, rate(derivative_of(iterate, a)), settings.rotation, next);
      converged = max_abs_difference(next.position, iterate.position) <= tol_x &&
                  max_abs_difference(next.velocity, iterate.velocity) <= tol_u &&
                  max_abs_difference(next.angular_velocity, iterate.angular_velocity) <= tol_w;
      std::swap(iterate, next);
    }
    if (!converged) ++diagnostics.unconverged_steps;
    state = std::move(iterate);
    f.commit(state, dt, acc);
    ++diagnostics.force_evaluations;
  }
};

/// First-order back-differenced (backward Euler), eq D.10:
/// x_{n+1} = x_n + Δt u_{n+1}, u_{n+1} = u_n + Δt F(x_{n+1}, u_{n+1})/m.
class BackwardDifference1 final : public Scheme {
 public:
  explicit BackwardDifference1(const SchemeSettings& s) : settings_(s) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    ImplicitIteration{settings_, diagnostics_}.run(state, acc, dt, f,
                                                   [](const Derivative& d) { return d; });
  }

 private:
  SchemeSettings settings_;
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
    const Derivative backward{(state.position - prev.position) / dt,
                              (state.velocity - prev.velocity) / dt,
                              orientation_rate(prev.orientation, state.orientation, dt),
                              (state.angular_velocity - prev.angular_velocity) / dt};
    ImplicitIteration{settings_, diagnostics_}.run(
        state, acc, dt, f, [&backward](const Derivative& d) {
          Derivative r = scaled(1.0 / 3.0, backward);
          add_scaled(r, 2.0 / 3.0, d);
          return r;
        });
  }
};

}  // namespace

std::unique_ptr<Scheme> make_backward_difference_1(const SchemeSettings& s) {
  return std::make_unique<BackwardDifference1>(s);
}
std::unique_ptr<Scheme> make_backward_difference_2(const SchemeSettings& s) {
  return std::make_unique<BackwardDifference2>(s);
}

}  // namespace dem::detail
