// SPDX-License-Identifier: MIT
// Self-starting explicit schemes of thesis appendix D: FE (D.2), SE (D.3), RK2 (D.4), RK4 (D.5).
// Each keeps its stages in members, so a step allocates nothing once the sizes are known.
#include "dem/integrators/scheme_factories.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {
namespace {

/// Forward Euler, eq D.2: x and u both advance with the derivative at t_n.
class ForwardEuler final : public Scheme {
 public:
  explicit ForwardEuler(const SchemeSettings& s) : rotation_(s.rotation), orientation_(s.orientation) {}
  [[nodiscard]] double start_weight() const noexcept override { return 1.0; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    derivative_of(state, acc, d_);
    advance(state, dt, d_, rotation_, next_, orientation_);
    std::swap(state, next_);
    f.weigh(0.0, 1.0);  // u_{n+1} − u_n = Δt a_n: these forces drive the next step
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
  bool orientation_;
  Derivative d_;
  KinematicState next_;
};

/// Symplectic Euler, eq D.3: u advances first and the new u moves x.
class SymplecticEuler final : public Scheme {
 public:
  explicit SymplecticEuler(const SchemeSettings& s) : rotation_(s.rotation), orientation_(s.orientation) {}
  [[nodiscard]] double start_weight() const noexcept override { return 1.0; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    derivative_of(state, acc, d_);
    d_.velocity += dt * acc.linear;
    if (rotation_) d_.angular_velocity += dt * acc.angular;
    advance(state, dt, d_, rotation_, next_, orientation_);
    std::swap(state, next_);
    f.weigh(0.0, 1.0);  // u_{n+1} − u_n = Δt a_n: these forces drive the next step
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
  bool orientation_;
  Derivative d_;
  KinematicState next_;
};

/// Second-order Runge–Kutta (midpoint), eq D.4.
class RungeKutta2 final : public Scheme {
 public:
  explicit RungeKutta2(const SchemeSettings& s) : rotation_(s.rotation), orientation_(s.orientation) {}
  [[nodiscard]] double start_weight() const noexcept override { return 0.0; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    derivative_of(state, acc, d_);
    advance(state, 0.5 * dt, d_, rotation_, mid_, orientation_);
    f.weigh(1.0, 0.0);  // u_{n+1} − u_n = Δt a(midpoint)
    f.trial(mid_, 0.5 * dt, acc_mid_);
    derivative_of(mid_, acc_mid_, d_);
    advance(state, dt, d_, rotation_, next_, orientation_);
    std::swap(state, next_);
    f.weigh(0.0, 0.0);
    f.commit(state, dt, acc);
    diagnostics_.force_evaluations += 2;
  }

 private:
  bool rotation_;
  bool orientation_;
  Derivative d_;
  KinematicState mid_;
  KinematicState next_;
  Accelerations acc_mid_;
};

/// Classical fourth-order Runge–Kutta, eq D.5.
class RungeKutta4 final : public Scheme {
 public:
  explicit RungeKutta4(const SchemeSettings& s) : rotation_(s.rotation), orientation_(s.orientation) {}
  [[nodiscard]] double start_weight() const noexcept override { return 1.0 / 6.0; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    diagnostics_.force_evaluations +=
        static_cast<std::uint64_t>(runge_kutta_4_step(state, acc, dt, f, rotation_, orientation_, work_, {}));
  }

 private:
  bool rotation_;
  bool orientation_;
  RungeKutta4Workspace work_;
};

}  // namespace

int runge_kutta_4_step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                       bool rotation, bool orientation, RungeKutta4Workspace& w,
                       const RungeKutta4Weights& weights) {
  // Weights of the stages in u_{n+1} − u_n = Δt (a₁ + 2a₂ + 2a₃ + a₄)/6 (a₁: the last commit).
  const auto stage_weight = [&](double share) { f.weigh(weights.scale * share, 0.0); };
  derivative_of(state, acc, w.k1);
  advance(state, 0.5 * dt, w.k1, rotation, w.stage, orientation);
  stage_weight(2.0 / 6.0);
  f.trial(w.stage, 0.5 * dt, w.acc_stage);
  derivative_of(w.stage, w.acc_stage, w.k2);
  advance(state, 0.5 * dt, w.k2, rotation, w.stage, orientation);
  stage_weight(2.0 / 6.0);
  f.trial(w.stage, 0.5 * dt, w.acc_stage);
  derivative_of(w.stage, w.acc_stage, w.k3);
  advance(state, dt, w.k3, rotation, w.stage, orientation);
  stage_weight(1.0 / 6.0);
  f.trial(w.stage, dt, w.acc_stage);
  derivative_of(w.stage, w.acc_stage, w.k4);

  scale(1.0 / 6.0, w.k1, w.sum);
  add_scaled(w.sum, 2.0 / 6.0, w.k2);
  add_scaled(w.sum, 2.0 / 6.0, w.k3);
  add_scaled(w.sum, 1.0 / 6.0, w.k4);
  advance(state, dt, w.sum, rotation, w.stage, orientation);
  std::swap(state, w.stage);
  f.weigh(weights.commit_now, weights.commit_next);
  f.commit(state, dt, acc);
  return 4;
}

std::unique_ptr<Scheme> make_forward_euler(const SchemeSettings& s) {
  return std::make_unique<ForwardEuler>(s);
}
std::unique_ptr<Scheme> make_symplectic_euler(const SchemeSettings& s) {
  return std::make_unique<SymplecticEuler>(s);
}
std::unique_ptr<Scheme> make_runge_kutta_2(const SchemeSettings& s) {
  return std::make_unique<RungeKutta2>(s);
}
std::unique_ptr<Scheme> make_runge_kutta_4(const SchemeSettings& s) {
  return std::make_unique<RungeKutta4>(s);
}

}  // namespace dem::detail
