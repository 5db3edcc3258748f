// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "cases/scene.hpp"

namespace cases {

/// The materials as a formation stage runs them: every restitution replaced by the stage's.
[[nodiscard]] std::vector<dem::MaterialProperties> formation_materials(std::vector<dem::MaterialProperties> materials,
                                                                       const FormationStageSpec& stage);

/// The contact model as a formation stage runs it: frictionless (no tangential or rolling
/// resistance) unless the stage keeps friction.
[[nodiscard]] dem::ModelChoice formation_model(dem::ModelChoice model, const FormationStageSpec& stage);

/// The materials as a settle stage runs them: every restitution replaced by the stage's, when it
/// sets one.
[[nodiscard]] std::vector<dem::MaterialProperties> settle_materials(std::vector<dem::MaterialProperties> materials,
                                                                    const SettleStageSpec& stage);

}  // namespace cases
