// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// Exact piecewise solution of collinear linear spring–dashpot scenes: one mobile sphere among
/// fixed spheres on its line of motion, or two mobile spheres head-on (thesis §4.3, fig 4.15).
class CollinearSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override { return "collinear linear contacts"; }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

/// Exact states of every particle at the given times (negative times continue the motion
/// backwards); the scene must be supported by CollinearSolver.
std::vector<cases::Snapshot> collinear_exact_states(const PreparedScene& prepared,
                                                    const std::vector<double>& times);

}  // namespace reference::analytic
