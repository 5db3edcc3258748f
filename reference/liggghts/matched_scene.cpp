// SPDX-License-Identifier: MIT
#include "reference/liggghts/matched_scene.hpp"

#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/pair_table.hpp"
#include "reference/common/core_setup.hpp"

namespace reference::liggghts {
namespace {

/// The tangential dashpot ratio and friction of a law, when it has a tangential slider.
std::optional<std::pair<double, double>> slider(const dem::PairLaw& law) {
  if (const auto* s = std::get_if<dem::SpringCoulombTangential>(&law.tangential)) {
    return std::make_pair(s->damping_ratio, s->friction);
  }
  if (const auto* m = std::get_if<dem::Mindlin8GTangential>(&law.tangential)) {
    return std::make_pair(m->p.damping_ratio, m->p.friction);
  }
  return std::nullopt;
}

/// True when the law has a normal dashpot.
bool damped(const dem::PairLaw& law) { return !std::holds_alternative<dem::NoDamping>(law.damping); }

}  // namespace

cases::Scene matched_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const dem::PairTable& table = prepared.pair_table();
  std::vector<std::size_t> used;
  for (const cases::ParticleSpec& p : scene.particles) used.push_back(p.material);
  for (const cases::WallSpec& w : scene.walls) used.push_back(w.material);
  for (const std::size_t a : used) {
    for (const std::size_t b : used) {
      const dem::PairLaw& law = table.law(a, b);
      const auto s = slider(law);
      if (s && s->first > 0.0 && s->second > 0.0 && damped(law)) {
        throw std::invalid_argument(fmt::format(
            "materials '{}' and '{}' have a tangential dashpot (ratio {}) on a frictional contact: LIGGGHTS tests "
            "the Coulomb limit on the spring alone and drops the dashpot while sliding, which no core policy does",
            scene.materials.at(a).name, scene.materials.at(b).name, s->first));
      }
    }
  }
  cases::Scene matched = scene;
  // fix nve/sphere (fix nve without rotation): velocity Verlet, forces with v(t + Δt/2).
  matched.integration.timestep = core_setup(prepared).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::velocity_verlet;
  // tangential_model_history.h: μ |F_n| with F_n = k_n δ − γ_n v_n (limitForce clamps both).
  matched.model.friction_limit = dem::FrictionLimit::elastic_damping;
  // shear += v_t Δt, then shear −= (shear·n) n: no rescaling to the old length.
  matched.model.tangential_history = dem::TangentialHistory::increment_project;
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
