// SPDX-License-Identifier: MIT
// Adams-family multi-step schemes of thesis appendix D: AB2 (D.6), AB4 (D.7), ABM (D.8).
#include "dem/integrators/multistep_history.hpp"
#include "dem/integrators/scheme_factories.hpp"

namespace dem::detail {
namespace {

/// Derivative Σ c_k D_{n−k} with D_n = current and D_{n−1}, … from `past`.
Derivative weighted(const Derivative& current, const std::deque<Derivative>& past,
                    std::initializer_list<double> weights) {
  auto w = weights.begin();
  Derivative sum = scaled(*w, current);
  for (std::size_t k = 0; ++w != weights.end(); ++k) add_scaled(sum, *w, past[k]);
  return sum;
}

/// Second-order Adams–Bashforth, eq D.6: x_{n+1} = x_n + Δt/2 (3u_n − u_{n−1}), same for u.
class AdamsBashforth2 final : public MultiStepScheme {
 public:
  explicit AdamsBashforth2(const SchemeSettings& s) : MultiStepScheme(s, 1) {}

 protected:
  void multistep(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                 const Derivative& current) override {
    KinematicState next;
    advance(state, dt, weighted(current, past(), {1.5, -0.5}), settings_.rotation, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }
};

/// Fourth-order Adams–Bashforth, eq D.7: weights (55, −59, 37, −9)/24.
class AdamsBashforth4 final : public MultiStepScheme {
 public:
  explicit AdamsBashforth4(const SchemeSettings& s) : MultiStepScheme(s, 3) {}

 protected:
  void multistep(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                 const Derivative& current) override {
    KinematicState next;
    advance(state, dt,
            weighted(current, past(), {55.0 / 24.0, -59.0 / 24.0, 37.0 / 24.0, -9.0 / 24.0}),
            settings_.rotation, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }
};

/// Adams–Bashforth–Moulton predictor–corrector, eq D.8: third-order AB predictor
/// (23, −16, 5)/12, fourth-order Adams–Moulton corrector (9, 19, −5, 1)/24.
class AdamsBashforthMoulton final : public MultiStepScheme {
 public:
  explicit AdamsBashforthMoulton(const SchemeSettings& s) : MultiStepScheme(s, 2) {}

 protected:
  void multistep(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                 const Derivative& current) override {
    KinematicState predicted;
    advance(state, dt, weighted(current, past(), {23.0 / 12.0, -16.0 / 12.0, 5.0 / 12.0}),
            settings_.rotation, predicted);
    Accelerations acc_predicted;
    f.trial(predicted, dt, acc_predicted);
    Derivative corrector = scaled(9.0 / 24.0, derivative_of(predicted, acc_predicted));
    add_scaled(corrector, 19.0 / 24.0, current);
    add_scaled(corrector, -5.0 / 24.0, past()[0]);
    add_scaled(corrector, 1.0 / 24.0, past()[1]);
    KinematicState next;
    advance(state, dt, corrector, settings_.rotation, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    diagnostics_.force_evaluations += 2;
  }
};

}  // namespace

std::unique_ptr<Scheme> make_adams_bashforth_2(const SchemeSettings& s) {
  return std::make_unique<AdamsBashforth2>(s);
}
std::unique_ptr<Scheme> make_adams_bashforth_4(const SchemeSettings& s) {
  return std::make_unique<AdamsBashforth4>(s);
}
std::unique_ptr<Scheme> make_adams_bashforth_moulton(const SchemeSettings& s) {
  return std::make_unique<AdamsBashforthMoulton>(s);
}

}  // namespace dem::detail
