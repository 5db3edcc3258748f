// SPDX-License-Identifier: MIT
#pragma once

#include "reference/engine.hpp"

namespace reference {

/// The in-house DEM core (dem/) as an engine: turns the Scene into a dem::Simulation, runs
/// it for the case's duration and records the requested traces and snapshots.
class InhouseEngine final : public Engine {
 public:
  [[nodiscard]] std::string_view name() const noexcept override { return "inhouse"; }
  [[nodiscard]] std::optional<std::string> version() const override;
  [[nodiscard]] Support supports(const cases::Scene& scene) const override;
  [[nodiscard]] cases::RunResult run(const cases::Scene& scene,
                                     const RunOptions& options) const override;
};

}  // namespace reference
