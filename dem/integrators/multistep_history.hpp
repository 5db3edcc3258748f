// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "dem/integrators/scheme.hpp"
#include "dem/integrators/scheme_factories.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {

/// Base of the multi-step schemes: keeps the derivatives of the last `needed` time points (a
/// ring of preallocated buffers) and fills them either by an RK4 start-up or from exact past
/// states (docs/integrators.md).
class MultiStepScheme : public Scheme {
 public:
  MultiStepScheme(const SchemeSettings& settings, std::size_t needed)
      : settings_(settings), needed_(needed), ring_(needed) {}

  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) final;
  [[nodiscard]] std::size_t past_states_needed() const noexcept final { return needed_; }
  /// A step that starts with RK4 sub-steps takes the last commit as its first stage (1/6 of the
  /// first of n sub-steps); the multi-step formula is booked with the trapezoid rule.
  [[nodiscard]] double start_weight() const noexcept override {
    return settings_.startup == StartupPolicy::rk4 && filled_ < needed_ ? 1.0 / (6.0 * settings_.startup_substeps) : 0.5;
  }
  void set_past(const std::vector<KinematicState>& past, ForceEvaluator& f, double dt) final;
  void permute(std::span<const std::uint32_t> order) final;

 protected:
  /// One step of the scheme proper, with `current` = derivative at t_n and past(k) the
  /// derivative at t_{n−1−k}.
  virtual void multistep(KinematicState& state, Accelerations& acc, double dt,
                         ForceEvaluator& f, const Derivative& current) = 0;
  /// Derivative at t_{n−1−k} (k = 0 is the most recent).
  [[nodiscard]] const Derivative& past(std::size_t k) const noexcept {
    return ring_[(head_ + k) % needed_];
  }
  /// State at t_{n−1} (kept for back-differenced schemes).
  [[nodiscard]] const KinematicState& previous_state() const noexcept { return previous_; }
  /// out = Σ weights[0]·current + Σ_k weights[k+1]·past(k).
  void weighted(const Derivative& current, std::initializer_list<double> weights, Derivative& out) const;

  SchemeSettings settings_;
  // Workspaces of the concrete schemes.
  Derivative work_;
  Derivative work2_;
  KinematicState next_;
  Accelerations acc_work_;

 private:
  void remember(const Derivative& current);
  std::size_t needed_;
  std::vector<Derivative> ring_;
  std::size_t filled_ = 0;
  std::size_t head_ = 0;
  KinematicState previous_;
  KinematicState before_;
  Derivative current_;
  RungeKutta4Workspace rk4_;
};

}  // namespace dem::detail
