// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "dem/integrators/scheme.hpp"
#include "dem/integrators/state_algebra.hpp"

// Factories of the concrete schemes, one translation unit per family (internal to dem).
namespace dem::detail {

std::unique_ptr<Scheme> make_forward_euler(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_symplectic_euler(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_runge_kutta_2(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_runge_kutta_4(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_adams_bashforth_2(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_adams_bashforth_4(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_adams_bashforth_moulton(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_backward_difference_1(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_backward_difference_2(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_velocity_verlet(const SchemeSettings& settings);
std::unique_ptr<Scheme> make_leapfrog(const SchemeSettings& settings);

/// The stages of one RK4 step, kept between steps so that a step allocates nothing.
struct RungeKutta4Workspace {
  Derivative k1, k2, k3, k4, sum;
  KinematicState stage;
  Accelerations acc_stage;
};

/// The weights an RK4 step states for its evaluations (ForceEvaluator::weigh), as shares of the
/// step being booked: the stages (2/6, 2/6, 1/6) times `scale` (1/n for one of n sub-steps), and
/// the commit's share of that step (`commit_now`) and of the next one (`commit_next`).
struct RungeKutta4Weights {
  double scale = 1.0;
  double commit_now = 0.0;
  double commit_next = 1.0 / 6.0;
};

/// One classical RK4 step (thesis eq D.5) of size dt, committing at the new state.
/// Returns the number of force evaluations (4).
int runge_kutta_4_step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f,
                       bool rotation, bool orientation, RungeKutta4Workspace& work,
                       const RungeKutta4Weights& weights);

}  // namespace dem::detail
