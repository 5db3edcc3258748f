// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// Frictionless Hertz collisions of two bodies (thesis eq 3.12–3.14; docs/physics-normal.md): one
/// mobile sphere head-on against a fixed sphere, two mobile spheres head-on, or one sphere at any
/// incidence against a plane wall at rest (its motion along the wall is uniform). Elastic
/// contacts use the closed form (HertzElasticContact); damped ones (any damping sub-model, with
/// or without clamp_tensile) a Dormand–Prince integration to 1e-12 (solve_normal_contact).
class HertzSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override { return "Hertz two-body contact"; }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

}  // namespace reference::analytic
