// SPDX-License-Identifier: MIT
#pragma once

#include <utility>

#include "reference/common/engine.hpp"
#include "reference/common/exact_states.hpp"

namespace reference {

/// The in-house DEM core (dem/) as an engine: turns the Scene into a dem::Simulation, runs
/// it for the case's duration and records the requested traces and snapshots.
class InhouseEngine final : public Engine {
 public:
  using Engine::run;
  using Engine::supports;
  /// The core without exact start-up data: a scene asking for `integration.startup = "exact"`
  /// fails with the reason.
  InhouseEngine() = default;
  /// The core taking a multi-step scheme's exact start-up states from `exact` (the registry
  /// passes the closed forms).
  explicit InhouseEngine(ExactStates exact) : exact_(std::move(exact)) {}
  [[nodiscard]] std::string_view name() const noexcept override { return "inhouse"; }
  [[nodiscard]] std::optional<std::string> version() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;

 private:
  ExactStates exact_;
};

}  // namespace reference
