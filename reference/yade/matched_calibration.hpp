// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "cases/scene.hpp"
#include "reference/yade/restitution_calibration.hpp"

namespace reference::yade {

/// Restitution ε' whose textbook dashpot β(ε')/2 is FrictViscoMat.betan = `betan`:
/// ε' = exp(−π b/√(1 − b²)) (eq 3.11 inverted, b = betan = β/2). Pure; betan ∈ [0, 1).
[[nodiscard]] double restitution_for_betan(double betan) noexcept;

/// The native YADE run calibrates betan on two-body YADE runs (restitution_calibration.hpp).
/// The matched core repeats that calibration with its own YADE replica (leapfrog, damping
/// 'yade_frictvisco'), whose two-body runs equal YADE's to round-off, and returns the
/// restitution ε' to give material `plan.material` so that 'yade_frictvisco' uses the calibrated
/// betan. `matched` is the scene with YADE's numerics already set. Empty when a two-body run
/// fails.
std::optional<double> matched_calibrated_restitution(const cases::Scene& matched,
                                                     const YadeCalibrationPlan& plan);

}  // namespace reference::yade
