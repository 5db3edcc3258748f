// SPDX-License-Identifier: MIT
#include "dem/integrators/multistep_history.hpp"

#include <stdexcept>
#include <string>

#include "dem/integrators/scheme_factories.hpp"

namespace dem::detail {

void MultiStepScheme::remember(const KinematicState& state, Derivative current) {
  previous_ = state;
  past_.push_front(std::move(current));
  while (past_.size() > needed_) past_.pop_back();
}

void MultiStepScheme::step(KinematicState& state, Accelerations& acc, double dt,
                           ForceEvaluator& f) {
  Derivative current = derivative_of(state, acc);
  const KinematicState before = state;
  if (past_.size() < needed_) {
    // Start-up: RK4 sub-steps until enough time points are known.
    const int n = settings_.startup_substeps;
    for (int i = 0; i < n; ++i) {
      diagnostics_.force_evaluations += static_cast<std::uint64_t>(
          runge_kutta_4_step(state, acc, dt / n, f, settings_.rotation));
    }
    ++diagnostics_.startup_steps;
  } else {
    multistep(state, acc, dt, f, current);
  }
  remember(before, std::move(current));
}

void MultiStepScheme::set_past(const std::vector<KinematicState>& past, ForceEvaluator& f,
                               double dt) {
  static_cast<void>(dt);
  if (past.size() < needed_) {
    throw std::invalid_argument("exact start-up needs " + std::to_string(needed_) +
                                " past states, got " + std::to_string(past.size()));
  }
  past_.clear();
  for (std::size_t k = 0; k < needed_; ++k) {
    Accelerations a;
    f.trial(past[k], 0.0, a);
    past_.push_back(derivative_of(past[k], a));
  }
  previous_ = past.front();
}

}  // namespace dem::detail
