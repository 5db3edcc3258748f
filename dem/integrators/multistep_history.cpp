// SPDX-License-Identifier: MIT
#include "dem/integrators/multistep_history.hpp"

#include <stdexcept>
#include <string>

namespace dem::detail {
namespace {

/// Reorders every array of a derivative.
void permute(Derivative& d, std::span<const std::uint32_t> order) {
  for (Vec3Array* a : {&d.velocity, &d.acceleration, &d.angular_velocity, &d.angular_acceleration}) {
    if (a->cols() == static_cast<Eigen::Index>(order.size())) dem::permute(*a, order);
  }
}

}  // namespace

void MultiStepScheme::remember(const Derivative& current) {
  std::swap(previous_, before_);
  head_ = (head_ + needed_ - 1) % needed_;
  Derivative& slot = ring_[head_];
  slot.velocity = current.velocity;
  slot.acceleration = current.acceleration;
  slot.angular_velocity = current.angular_velocity;
  slot.angular_acceleration = current.angular_acceleration;
  if (filled_ < needed_) ++filled_;
}

void MultiStepScheme::weighted(const Derivative& current, std::initializer_list<double> weights,
                               Derivative& out) const {
  auto w = weights.begin();
  scale(*w, current, out);
  for (std::size_t k = 0; ++w != weights.end(); ++k) add_scaled(out, *w, past(k));
}

void MultiStepScheme::step(KinematicState& state, Accelerations& acc, double dt,
                           ForceEvaluator& f) {
  derivative_of(state, acc, current_);
  before_ = state;
  if (filled_ < needed_) {
    // Start-up: RK4 sub-steps until enough time points are known.
    // Each sub-step's commit is the next sub-step's first stage, within this step; the last
    // one starts the next step (another start-up step, or the multi-step formula, booked with
    // the trapezoid rule).
    const int n = settings_.startup_substeps;
    const double share = 1.0 / n;
    const double next = filled_ + 1 < needed_ ? share / 6.0 : 0.5;
    for (int i = 0; i < n; ++i) {
      const bool last = i + 1 == n;
      const RungeKutta4Weights weights{share, last ? 0.0 : share / 6.0, last ? next : 0.0};
      diagnostics_.force_evaluations += static_cast<std::uint64_t>(
          runge_kutta_4_step(state, acc, dt / n, f, settings_.rotation, settings_.orientation, rk4_, weights));
    }
    ++diagnostics_.startup_steps;
  } else {
    multistep(state, acc, dt, f, current_);
  }
  remember(current_);
}

void MultiStepScheme::set_past(const std::vector<KinematicState>& past, ForceEvaluator& f,
                               double dt) {
  static_cast<void>(dt);
  if (past.size() < needed_) {
    throw std::invalid_argument("exact start-up needs " + std::to_string(needed_) +
                                " past states, got " + std::to_string(past.size()));
  }
  head_ = 0;
  for (std::size_t k = 0; k < needed_; ++k) {
    f.trial(past[k], 0.0, acc_work_);
    derivative_of(past[k], acc_work_, ring_[k]);
  }
  filled_ = needed_;
  previous_ = past.front();
}

void MultiStepScheme::permute(std::span<const std::uint32_t> order) {
  for (Derivative& d : ring_) detail::permute(d, order);
  if (previous_.position.cols() == static_cast<Eigen::Index>(order.size())) dem::permute(previous_, order);
}

}  // namespace dem::detail
