// SPDX-License-Identifier: MIT
// Self-starting explicit schemes of thesis appendix D: FE (D.2), SE (D.3), RK2 (D.4), RK4 (D.5).
#include "dem/integrators/scheme_factories.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {
namespace {

/// Forward Euler, eq D.2: x and u both advance with the derivative at t_n.
class ForwardEuler final : public Scheme {
 public:
  explicit ForwardEuler(const SchemeSettings& s) : rotation_(s.rotation) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    KinematicState next;
    advance(state, dt, derivative_of(state, acc), rotation_, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
};

/// Symplectic Euler, eq D.3: u advances first and the new u moves x.
class SymplecticEuler final : public Scheme {
 public:
  explicit SymplecticEuler(const SchemeSettings& s) : rotation_(s.rotation) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    Derivative d = derivative_of(state, acc);
    d.velocity += dt * acc.linear;
    if (rotation_) d.angular_velocity += dt * acc.angular;
    KinematicState next;
    advance(state, dt, d, rotation_, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
};

/// Second-order Runge–Kutta (midpoint), eq D.4.
class RungeKutta2 final : public Scheme {
 public:
  explicit RungeKutta2(const SchemeSettings& s) : rotation_(s.rotation) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    KinematicState mid;
    advance(state, 0.5 * dt, derivative_of(state, acc), rotation_, mid);
    Accelerations acc_mid;
    f.trial(mid, 0.5 * dt, acc_mid);
    KinematicState next;
    advance(state, dt, derivative_of(mid, acc_mid), rotation_, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    diagnostics_.force_evaluations += 2;
  }

 private:
  bool rotation_;
};

/// Classical fourth-order Runge–Kutta, eq D.5.
class RungeKutta4 final : public Scheme {
 public:
  explicit RungeKutta4(const SchemeSettings& s) : rotation_(s.rotation) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    diagnostics_.force_evaluations +=
        static_cast<std::uint64_t>(runge_kutta_4_step(state, acc, dt, f, rotation_));
  }

 private:
  bool rotation_;
};

}  // namespace

int runge_kutta_4_step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                       bool rotation) {
  const Derivative k1 = derivative_of(state, acc);
  KinematicState s2;
  advance(state, 0.5 * dt, k1, rotation, s2);
  Accelerations a2;
  f.trial(s2, 0.5 * dt, a2);
  const Derivative k2 = derivative_of(s2, a2);
  KinematicState s3;
  advance(state, 0.5 * dt, k2, rotation, s3);
  Accelerations a3;
  f.trial(s3, 0.5 * dt, a3);
  const Derivative k3 = derivative_of(s3, a3);
  KinematicState s4;
  advance(state, dt, k3, rotation, s4);
  Accelerations a4;
  f.trial(s4, dt, a4);
  const Derivative k4 = derivative_of(s4, a4);

  Derivative sum = scaled(1.0 / 6.0, k1);
  add_scaled(sum, 2.0 / 6.0, k2);
  add_scaled(sum, 2.0 / 6.0, k3);
  add_scaled(sum, 1.0 / 6.0, k4);
  KinematicState next;
  advance(state, dt, sum, rotation, next);
  state = std::move(next);
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
