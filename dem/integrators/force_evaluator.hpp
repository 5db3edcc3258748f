// SPDX-License-Identifier: MIT
#pragma once

#include "dem/particles/particles.hpp"

namespace dem {

/// What an integrator asks of the force model. Contact history advances only on `commit`;
/// `trial` evaluations (Runge–Kutta stages, predictor and implicit iterates) see a history
/// advanced by `elapsed` from the last commit and leave nothing behind.
class ForceEvaluator {
 public:
  virtual ~ForceEvaluator() = default;
  /// Accelerations at `state`, `elapsed` seconds after the last commit; keeps nothing.
  virtual void trial(const KinematicState& state, double elapsed, Accelerations& out) = 0;
  /// Accelerations at `state`; the contact history advanced by `elapsed` becomes the committed one.
  virtual void commit(const KinematicState& state, double elapsed, Accelerations& out) = 0;
  /// commit, then a scheme's closing kick: u += kick·a, and ω += kick·α when `rotation`, for
  /// every sphere. An evaluator may fold the kick into its own last pass over the spheres, as
  /// long as each sphere's arithmetic is the same.
  virtual void commit_and_kick(KinematicState& state, double elapsed, Accelerations& out, double kick,
                               bool rotation) {
    commit(state, elapsed, out);
    const auto n = state.velocity.cols();
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index k = 0; k < 3; ++k) state.velocity(k, i) += kick * out.linear(k, i);
      if (!rotation) continue;
      for (Eigen::Index k = 0; k < 3; ++k) state.angular_velocity(k, i) += kick * out.angular(k, i);
    }
  }
  /// A whole velocity-Verlet step fused into the evaluator's own passes over the spheres, when it
  /// offers one: u += ½Δt·a_n (ω += ½Δt·α_n when `rotation`) for every sphere, x += Δt·u for
  /// those not fixed, time += Δt, then commit_and_kick(state, Δt, acc, ½Δt, rotation) — each
  /// sphere's arithmetic exactly the scheme's. `acc` holds a_n on entry and a_{n+1} on return
  /// (unless the evaluator was asked to defer the closing kick, which it then owes). False, with
  /// nothing done, when it offers no such step.
  virtual bool verlet_step(KinematicState& state, Accelerations& acc, double dt, bool rotation) {
    static_cast<void>(state);
    static_cast<void>(acc);
    static_cast<void>(dt);
    static_cast<void>(rotation);
    return false;
  }
  /// Says how the forces of the next evaluation (trial or commit) enter the velocity change:
  /// with weight `now` in the step under way and `next` in the following one (so that
  /// u_{n+1} − u_n = Δt Σ weight·F/m). An energy ledger books work with these weights; a scheme
  /// that does not call it gets the trapezoid weights (½, ½) at commits and 0 at trials.
  virtual void weigh(double now, double next) noexcept {
    static_cast<void>(now);
    static_cast<void>(next);
  }
};

}  // namespace dem
