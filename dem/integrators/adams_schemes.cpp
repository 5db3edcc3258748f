// SPDX-License-Identifier: MIT
// Adams-family multi-step schemes of thesis appendix D: AB2 (D.6), AB4 (D.7), ABM (D.8).
#include "dem/integrators/multistep_history.hpp"
#include "dem/integrators/scheme_factories.hpp"

namespace dem::detail {
namespace {

/// Second-order Adams–Bashforth, eq D.6: x_{n+1} = x_n + Δt/2 (3u_n − u_{n−1}), same for u.
class AdamsBashforth2 final : public MultiStepScheme {
 public:
  explicit AdamsBashforth2(const SchemeSettings& s) : MultiStepScheme(s, 1) {}

 protected:
  void multistep(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                 const Derivative& current) override {
    weighted(current, {1.5, -0.5}, work_);
    advance(state, dt, work_, settings_.rotation, next_, settings_.orientation);
    std::swap(state, next_);
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
    weighted(current, {55.0 / 24.0, -59.0 / 24.0, 37.0 / 24.0, -9.0 / 24.0}, work_);
    advance(state, dt, work_, settings_.rotation, next_, settings_.orientation);
    std::swap(state, next_);
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
    weighted(current, {23.0 / 12.0, -16.0 / 12.0, 5.0 / 12.0}, work_);
    advance(state, dt, work_, settings_.rotation, next_, settings_.orientation);  // predictor
    f.trial(next_, dt, acc_work_);
    derivative_of(next_, acc_work_, work2_);
    scale(9.0 / 24.0, work2_, work_);
    add_scaled(work_, 19.0 / 24.0, current);
    add_scaled(work_, -5.0 / 24.0, past(0));
    add_scaled(work_, 1.0 / 24.0, past(1));
    advance(state, dt, work_, settings_.rotation, next_, settings_.orientation);
    std::swap(state, next_);
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
