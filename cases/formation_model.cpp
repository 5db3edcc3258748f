// SPDX-License-Identifier: MIT
#include "cases/formation_model.hpp"

namespace cases {

std::vector<dem::MaterialProperties> formation_materials(std::vector<dem::MaterialProperties> materials,
                                                         const FormationStageSpec& stage) {
  for (dem::MaterialProperties& m : materials) m.restitution = stage.restitution;
  return materials;
}

std::vector<dem::MaterialProperties> settle_materials(std::vector<dem::MaterialProperties> materials,
                                                      const SettleStageSpec& stage) {
  if (!stage.restitution) return materials;
  for (dem::MaterialProperties& m : materials) m.restitution = *stage.restitution;
  return materials;
}

dem::ModelChoice formation_model(dem::ModelChoice model, const FormationStageSpec& stage) {
  if (!stage.friction) {
    model.tangential = "none";
    model.rolling = "none";
  }
  return model;
}

}  // namespace cases
