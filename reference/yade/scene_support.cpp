// SPDX-License-Identifier: MIT
#include "reference/yade/scene_support.hpp"

#include <algorithm>

namespace reference::yade {

std::vector<std::string> unsupported_scene_features(const cases::Scene& scene) {
  std::vector<std::string> reasons;
  if (scene.fluid) {
    reasons.emplace_back("YADE driver: fluid forces (drag, buoyancy, pressure gradient) are not mapped");
  }
  if (scene.model.pair_lever_arm == dem::PairLeverArm::radius ||
      scene.model.pair_lever_arm == dem::PairLeverArm::radius_velocity ||
      scene.model.wall_lever_arm == dem::WallLeverArm::radius ||
      scene.model.tangential_history == dem::TangentialHistory::increment_project) {
    reasons.emplace_back(
        "YADE driver: the lever arms 'radius' and 'radius_velocity' and the tangential_history "
        "'increment_project' are LAMMPS conventions, not mapped onto YADE's laws");
  }
  if (scene.model.coulomb_test == dem::CoulombTest::spring && scene.model.tangential != "none") {
    reasons.emplace_back(
        "YADE driver: coulomb_test = 'spring' is LIGGGHTS' rule; YADE's laws cap the shear force as a whole");
  }
  if (!scene.output.trace_aggregates.empty()) {
    reasons.emplace_back(
        "YADE driver: output.trace_aggregates (kinetic and rotational energy, coordination number) "
        "are not written by the YADE script yet");
  }
  if (scene.domain.any_periodic()) {
    reasons.emplace_back(
        "YADE driver: periodic boundaries are not mapped: YADE's periodic cell (O.periodic) wraps all "
        "three axes at once, so a box periodic along some axes only cannot be expressed, and the driver "
        "does not map the fully periodic cell yet");
  }
  const auto& ps = scene.particles;
  if (std::any_of(ps.begin(), ps.end(), [](const auto& p) { return p.charge != 0.0; })) {
    reasons.emplace_back("YADE driver: electric charges (Coulomb forces) are not mapped");
  }
  if (std::any_of(ps.begin(), ps.end(), [](const auto& p) { return !p.motion.empty(); })) {
    reasons.emplace_back("YADE driver: prescribed motion of fixed particles is not mapped yet");
  }
  return reasons;
}

std::vector<std::string> unproduced_outputs(const cases::Scene& scene) {
  std::vector<std::string> warnings;
  if (scene.output.trace_energy) {
    warnings.emplace_back("output.trace_energy: the YADE driver does not record the energy ledger");
  }
  return warnings;
}

}  // namespace reference::yade
