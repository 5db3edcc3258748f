// SPDX-License-Identifier: MIT
#pragma once

#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// Exact piecewise solution of a sphere attracted by linear cohesion (thesis eq 3.33, E.5) to a
/// fixed sphere on its line of motion: free flight while the effect spheres are apart, the
/// unstable linear attraction m δ'' = k_c δ̂ (cosh/sinh) while only they overlap, and the damped
/// oscillator m δ'' + η δ' + (k_e − k_c) δ = k_c Δ about δ_eq = k_c Δ/(k_e − k_c) while the
/// bodies touch (Δ = δ̂ − δ). Region changes are located in closed form (cosh/sinh) or by TOMS
/// 748. Exact metrics: equilibrium overlap, and the first contact's duration and maximum overlap.
class LinearCohesionSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override { return "linear cohesion pair"; }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

}  // namespace reference::analytic
