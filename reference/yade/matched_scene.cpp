// SPDX-License-Identifier: MIT
#include "reference/yade/matched_scene.hpp"

#include "reference/common/core_setup.hpp"
#include "reference/yade/matched_calibration.hpp"
#include "reference/yade/model_mapping.hpp"
#include "reference/yade/restitution_calibration.hpp"
#include "reference/yade/run_plan.hpp"
#include "cases/time_step.hpp"

namespace reference::yade {

/// YADE 2023.02a: NewtonIntegrator is leapfrog with half-step velocities, and the velocity a
/// script gives is taken as v(−Δt/2). The matched core starts from exactly the velocities the
/// native YADE run is given (start_velocities: v(0) − Δt/2·g for a sphere that starts free of
/// contacts under gravity, v(0) otherwise), as leapfrog with given half-step velocities. The
/// sub-models and policies are replaced by the variants the mapped YADE law computes
/// (model_mapping.hpp).
cases::Scene matched_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  cases::Scene matched = scene;
  matched.integration.timestep = core_setup(prepared).simulation.timestep;
  const StartVelocities start = start_velocities(scene, *matched.integration.timestep);
  for (std::size_t i = 0; i < matched.particles.size(); ++i) matched.particles[i].velocity = start.velocity[i];
  matched.integration.scheme = dem::SchemeId::leapfrog;
  matched.integration.leapfrog_start = dem::LeapfrogStart::given_is_half_step;
  // FrictViscoPhys: the dashpot sees α·u_n, α = (r_p + r_q)/(r_p + r_q − δ) (2r/(2r − δ), wall).
  if (matched.model.damping == "restitution" && matched.model.normal == "linear") {
    matched.model.damping = "yade_frictvisco";
  }
  // Coulomb cap: CundallStrack on k_n δ; CundallStrackVisco on the elastic force plus its
  // dashpot, which leaves out the linear cohesion the script adds as a separate force; Mindlin on
  // the magnitude of the whole normal force after the dashpot (and its clip), plus the DMT
  // adhesion force 4πR*γ when adhesive (HertzMindlin.cpp: maxFs = tanφ (F_ad + |F_n|)).
  const YadeLaw law = map_contact_model(prepared).law;
  matched.model.friction_limit = law == YadeLaw::frict         ? dem::FrictionLimit::elastic
                                 : law == YadeLaw::frict_visco ? dem::FrictionLimit::elastic_damping
                                                               : dem::FrictionLimit::total_plus_pulloff;
  // Mindlin clips the total normal force at ≥ 0 without adhesion (adhesionForce = 0); with DMT
  // adhesion it never clips, but a dashpot that leaves the normal force tensile acts with at
  // most the adhesion force 4πR*γ.
  if (law == YadeLaw::mindlin) {
    matched.model.clamp_tensile = true;
    matched.model.adhesive_dashpot = dem::AdhesiveDashpot::pulloff_cap;
  } else {
    matched.model.adhesive_dashpot = dem::AdhesiveDashpot::clamp;
  }
  // YADE's sliders cap as always (no LAMMPS-style drop; its mapped laws have no tangential dashpot).
  matched.model.unloaded_slider = dem::UnloadedSlider::cap;
  // Ig2 creates a contact at (r_p + r_q)² − d² ≥ 0 and the Law2 keeps it while δ ≥ 0: a pair
  // that lands exactly on δ = 0 gets the dashpot (and friction) in that step.
  matched.model.contact_at_zero_overlap = true;
  // Torque lever arm r − δ/2 (CundallStrack, sphericalBodies); the shear increment from
  // ScGeom::getIncidentVel with avoidGranularRatcheting: spins with the radii, the centres'
  // tangential velocity scaled by α = D/(D − δ) (D = r_p + r_q, or 2r against a wall).
  matched.model.wall_lever_arm = dem::WallLeverArm::yade_incident;
  matched.model.pair_lever_arm = dem::PairLeverArm::yade_incident;
  // The stored shear turned by n_old × n and the mean spin about n, not re-projected.
  matched.model.tangential_history = dem::TangentialHistory::yade_rotate;
  // Law2_ScGeom_MindlinPhys_Mindlin: F_s −= k_s(δ) Δu_s, each increment at its own stiffness.
  matched.model.mindlin_form = dem::MindlinForm::incremental;
  // The native YADE run calibrates FrictViscoMat.betan (restitution_calibration.hpp); the core
  // repeats that calibration on its own replica and takes the ε' whose β(ε')/2 is that betan.
  const YadeModelMapping mapping = map_contact_model(prepared);
  const auto calibration =
      plan_calibration(scene, mapping, cases::step_count(scene.integration.duration, *matched.integration.timestep));
  if (calibration) {
    if (const auto e = matched_calibrated_restitution(matched, *calibration)) {
      matched.materials[calibration->material].restitution = *e;
    }
  }
  return matched;
}

const CodeConventions& conventions() noexcept {
  static constexpr CodeConventions kConventions{"yade", &matched_scene};
  return kConventions;
}

}  // namespace reference::yade
