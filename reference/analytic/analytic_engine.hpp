// SPDX-License-Identifier: MIT
#pragma once

#include "reference/common/engine.hpp"

namespace reference {

/// Closed-form solutions (engine `analytic`, docs/architecture.md "Engines"). Supports the
/// collinear scenes of linear spring–dashpot contacts: one mobile sphere among fixed spheres on the
/// line of its velocity (single collision, sandwich), or two mobile spheres in a head-on collision.
/// Its trace is sampled at exactly the time points the in-house core uses, so amplitude errors
/// compare like with like (thesis §4.3.3). It also reports the exact contact duration, restitution,
/// maximum overlap and maximum force of the compared pair.
class AnalyticEngine final : public Engine {
 public:
  using Engine::run;
  using Engine::supports;
  [[nodiscard]] std::string_view name() const noexcept override { return "analytic"; }
  [[nodiscard]] std::optional<std::string> version() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;
};

/// Exact states of every particle of the prepared scene at the given times (negative times allowed:
/// the motion is continued backwards). Throws std::invalid_argument with the reasons when the
/// analytic engine does not support the scene. Used for exact multi-step start-up data.
std::vector<cases::Snapshot> exact_states(const PreparedScene& prepared,
                                          const std::vector<double>& times);

}  // namespace reference
