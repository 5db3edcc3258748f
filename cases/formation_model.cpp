// SPDX-License-Identifier: MIT
#include "cases/formation_model.hpp"

#include <utility>

namespace cases {

namespace {

/// `materials` with every restitution replaced by `restitution`.
std::vector<dem::MaterialProperties> with_restitution(std::vector<dem::MaterialProperties> materials,
                                                      double restitution) {
  for (dem::MaterialProperties& m : materials) m.restitution = restitution;
  return materials;
}

}  // namespace

std::vector<dem::MaterialProperties> formation_materials(std::vector<dem::MaterialProperties> materials,
                                                         const FormationStageSpec& stage) {
  return with_restitution(std::move(materials), stage.restitution);
}

std::vector<dem::MaterialProperties> settle_materials(std::vector<dem::MaterialProperties> materials,
                                                      const SettleStageSpec& stage) {
  if (!stage.restitution) return materials;
  return with_restitution(std::move(materials), *stage.restitution);
}

dem::ModelChoice formation_model(dem::ModelChoice model, const FormationStageSpec& stage) {
  if (!stage.friction) {
    model.tangential = "none";
    model.rolling = "none";
  }
  return model;
}

}  // namespace cases
