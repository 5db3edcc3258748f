// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

#include "dem/integrators/scheme.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {

/// Base of the multi-step schemes: keeps the derivatives of the last `needed` time points and
/// fills them either by an RK4 start-up or from exact past states (PHYSICS.md §7).
class MultiStepScheme : public Scheme {
 public:
  MultiStepScheme(const SchemeSettings& settings, std::size_t needed)
      : settings_(settings), needed_(needed) {}

  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) final;
  [[nodiscard]] std::size_t past_states_needed() const noexcept final { return needed_; }
  void set_past(const std::vector<KinematicState>& past, ForceEvaluator& f, double dt) final;

 protected:
  /// One step of the scheme proper, with `current` = derivative at t_n and `past()` holding
  /// the derivatives at t_{n−1}, t_{n−2}, … (most recent first).
  virtual void multistep(KinematicState& state, Accelerations& acc, double dt,
                         ForceEvaluator& f, const Derivative& current) = 0;
  /// Derivatives at earlier time points, most recent first.
  [[nodiscard]] const std::deque<Derivative>& past() const noexcept { return past_; }
  /// State at t_{n−1} (kept for back-differenced schemes).
  [[nodiscard]] const KinematicState& previous_state() const noexcept { return previous_; }
  SchemeSettings settings_;

 private:
  void remember(const KinematicState& state, Derivative current);
  std::size_t needed_;
  std::deque<Derivative> past_;
  KinematicState previous_;
};

}  // namespace dem::detail
