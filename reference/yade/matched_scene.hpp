// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "reference/common/code_conventions.hpp"

namespace reference::yade {

/// The scene the in-house core runs to reproduce YADE 2023.02a's numerics (leapfrog with
/// half-step velocities as NewtonIntegrator, pinned Δt, and every sub-model replaced by the
/// variant YADE computes).
cases::Scene matched_scene(const PreparedScene& prepared);

/// YADE's numerics as the matched engine "inhouse@yade" adopts them (matched_scene above).
[[nodiscard]] const CodeConventions& conventions() noexcept;

}  // namespace reference::yade
