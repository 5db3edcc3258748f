// SPDX-License-Identifier: MIT
#include "reference/liggghts/matched_scene.hpp"

#include "reference/common/core_setup.hpp"

namespace reference::liggghts {

cases::Scene matched_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  cases::Scene matched = scene;
  // fix nve/sphere (fix nve without rotation): velocity Verlet, forces with v(t + Δt/2).
  matched.integration.timestep = core_setup(prepared).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::velocity_verlet;
  // tangential_model_history.h: μ |F_n| with F_n = k_n δ − γ_n v_n (limitForce clamps both).
  matched.model.friction_limit = dem::FrictionLimit::elastic_damping;
  // shear += v_t Δt, then shear −= (shear·n) n: no rescaling to the old length.
  matched.model.tangential_history = dem::TangentialHistory::increment_project;
  // tangential_model_history.h: k_t|ς| against μ|F_n|; sliding drops the dashpot, sticking adds it uncapped.
  matched.model.coulomb_test = dem::CoulombTest::spring;
  // rolling_model_cdt.h: μ_r k_n δ R* along the unit relative spin, its twist part dropped afterwards.
  matched.model.constant_torque_form = dem::ConstantTorqueForm::projected;
  // surface_model_default.h: c_r = r − δ/2 for v_t and the torque, pairs and walls alike.
  matched.model.pair_lever_arm = dem::PairLeverArm::contact_point;
  matched.model.wall_lever_arm = dem::WallLeverArm::contact_point;
  return matched;
}

const CodeConventions& conventions() noexcept {
  static constexpr CodeConventions kConventions{"liggghts", &matched_scene};
  return kConventions;
}

}  // namespace reference::liggghts
