// SPDX-License-Identifier: MIT
#include "reference/lammps/matched_scene.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "reference/common/core_setup.hpp"
#include "reference/lammps/wall_mapping.hpp"

namespace reference::lammps {

cases::Scene matched_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  for (const cases::WallSpec& w : scene.walls) {
    if (w.shape == dem::WallShape::plane || !wall_in_run(w)) continue;
    // fix wall/gran/region takes R* with the region's curvature (−2ρ for a cylinder or cone,
    // rims included); the core's walls have R* = r.
    throw std::runtime_error(fmt::format("wall '{}' is a {}: LAMMPS' region walls take R* from the region's "
                                         "curvature, which the core does not reproduce",
                                         w.name, cases::wall_shape_name(w)));
  }
  cases::Scene matched = scene;
  // fix nve/sphere (fix nve without rotation): velocity Verlet, forces with v(t + Δt/2).
  matched.integration.timestep = core_setup(prepared).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::velocity_verlet;
  // pair granular's Coulomb cap: |F_ne + F_damp|, or |F_ne + 2 F_pulloff| for jkr/dmt.
  const bool adhesive = scene.model.cohesion == "jkr" || scene.model.cohesion == "dmt";
  matched.model.friction_limit =
      adhesive ? dem::FrictionLimit::jkr_shifted : dem::FrictionLimit::elastic_damping;
  // fix wall/gran: lever arm and contact-point velocity with r, not r − δ/2.
  matched.model.wall_lever_arm = dem::WallLeverArm::radius;
  // pair granular: contact-point velocity with r, torque with r − δ/2.
  matched.model.pair_lever_arm = dem::PairLeverArm::radius_velocity;
  // pair granular mindlin: k_t scales with the normal model's contact radius, the JKR one under jkr.
  matched.model.mindlin_radius = dem::MindlinRadius::contact_radius;
  // pair granular jkr: the neck breaks at the load-controlled pull-off overlap δ_f.
  matched.model.jkr_rupture = dem::JkrRupture::load;
  // pair granular, fix wall/gran: a capped slider (tangential or rolling) with no stored
  // displacement — a contact at t = 0, where the setup force integrates no slip — gives no force.
  matched.model.unloaded_slider = dem::UnloadedSlider::zero;
  // pair granular has no cap of the dashpot at the pull-off force (YADE's rule): limit_damping
  // (the case's clamp_tensile) is its only limit.
  matched.model.adhesive_dashpot = dem::AdhesiveDashpot::clamp;
  // mindlin_form stays the case's: the driver writes `mindlin` (the whole slip at today's k_t)
  // for 'total' and `mindlin/force` (each increment at its step's k_t) for 'incremental'.
  return matched;
}

const CodeConventions& conventions() noexcept {
  static constexpr CodeConventions kConventions{"lammps", &matched_scene};
  return kConventions;
}

}  // namespace reference::lammps
