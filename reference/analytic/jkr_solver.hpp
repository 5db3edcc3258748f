// SPDX-License-Identifier: MIT
#pragma once

#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// Exact JKR force–separation curve of a displacement-controlled pull-off rig: two fixed
/// spheres, one of them moved along the line of centres by a prescribed piecewise-constant
/// velocity (approach, then retract). No inertia enters, so the trace is a pure function of
/// time: the overlap from the motion, the force from eq 3.34–3.35 with the JKR hysteresis
/// (forms at δ = 0, breaks at δ_c or, under jkr_rupture = "load", at δ_f).
/// Exact metrics: pull-off force, rupture separation, force at rupture, separation work.
class JkrPulloffSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override { return "JKR pull-off rig"; }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

}  // namespace reference::analytic
