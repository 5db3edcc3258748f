// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference::analytic {

/// One family of exact (or high-accuracy reference) solutions the analytic engine offers. A
/// solver says which scenes it can solve and solves them on the in-house core's time points.
class Solver {
 public:
  virtual ~Solver() = default;
  /// Short name for reasons and conventions, e.g. "collinear linear contacts".
  [[nodiscard]] virtual std::string_view name() const noexcept = 0;
  /// Why this solver cannot express `scene` (empty when it can), each reason starting with
  /// "analytic" and naming what it solves, so reports read well when several solvers decline.
  [[nodiscard]] virtual std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const = 0;
  /// Solves a supported scene: status ok, trace in cases::trace_layout order on the core's time
  /// points, exact metrics where closed forms exist, conventions.
  [[nodiscard]] virtual cases::RunResult run(const PreparedScene& prepared) const = 0;

  /// unsupported_reasons() of `scene` prepared for this one call.
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const cases::Scene& scene) const {
    return unsupported_reasons(PreparedScene(scene));
  }
  /// run() of `scene` prepared for this one call.
  [[nodiscard]] cases::RunResult run(const cases::Scene& scene) const { return run(PreparedScene(scene)); }
};

/// Every solver, in the order the analytic engine tries them (solvers.cpp: one line each).
std::vector<std::unique_ptr<Solver>> all_solvers();

}  // namespace reference::analytic
