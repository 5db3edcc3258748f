// SPDX-License-Identifier: MIT
#include "store/scene_json.hpp"

#include <nlohmann/json.hpp>

#include "dem/materials/material_properties.hpp"
#include "support/sha256.hpp"

namespace store {
namespace {

using Json = nlohmann::ordered_json;

Json material_json(const dem::MaterialProperties& m) {
  Json j;
  j["name"] = m.name;
  j["density"] = m.density;
  for (const auto& spec : dem::property_specs()) {
    if (spec.material_field == nullptr) continue;
    if (const auto& v = m.*spec.material_field) j[std::string(spec.key)] = *v;
  }
  if (m.rigid) j["rigid"] = true;  // only when set: older scenes keep their fingerprints
  return j;
}

Json pair_json(const dem::PairProperties& p) {
  Json j = Json::object();
  for (const auto& spec : dem::property_specs()) {
    if (spec.pair_field == nullptr) continue;
    if (const auto& v = p.*spec.pair_field) j[std::string(spec.key)] = *v;
  }
  return j;
}

Json particle_json(const cases::ParticleSpec& p) {
  Json j;
  j["radius"] = p.radius;
  j["effect_radius"] = p.effect_radius;
  j["material"] = p.material;
  j["position"] = p.position;
  j["velocity"] = p.velocity;
  j["angular_velocity"] = p.angular_velocity;
  j["fixed"] = p.fixed;
  j["charge"] = p.charge;
  Json motion = Json::array();
  for (const auto& s : p.motion) motion.push_back({{"duration", s.duration}, {"velocity", s.velocity}});
  j["motion"] = motion;
  return j;
}

Json fluid_json(const cases::FluidSpec& f) {
  Json j;
  j["density"] = f.density;
  j["viscosity"] = f.viscosity;
  j["drag"] = f.drag;
  j["buoyancy"] = f.buoyancy;
  j["virtual_mass"] = f.virtual_mass;
  j["pressure_gradient"] = f.pressure_gradient;
  j["velocity"] = f.velocity;
  Json zones = Json::array();
  for (const auto& z : f.zones) zones.push_back({{"min", z.min}, {"max", z.max}, {"direction", z.direction}});
  j["zones"] = zones;
  j["plug_speed"] = f.plug_speed;
  j["ramp_time"] = f.ramp_time;
  return j;
}

Json pairs_json(const std::vector<cases::ParticlePair>& pairs) {
  Json j = Json::array();
  for (const auto& [a, b] : pairs) j.push_back({a, b});
  return j;
}

/// A preparation stage's physical settings (its name is a label and left out).
Json stage_json(const cases::StageSpec& st) {
  if (const auto* f = std::get_if<cases::FormationStageSpec>(&st.action)) {
    return {{"kind", "formation"},         {"pull", f->pull},
            {"pull_time", f->pull_time},   {"restitution", f->restitution},
            {"friction", f->friction},     {"walls", f->walls},
            {"gravity", f->gravity},       {"kinetic_energy", f->kinetic_energy},
            {"max_duration", f->max_duration}};
  }
  if (const auto* settle = std::get_if<cases::SettleStageSpec>(&st.action)) {
    Json j = {{"kind", "settle"},
              {"kinetic_energy", settle->kinetic_energy},
              {"min_duration", settle->min_duration},
              {"max_duration", settle->max_duration}};
    if (settle->restitution) j["restitution"] = *settle->restitution;
    if (settle->remove_above) j["remove_above"] = *settle->remove_above;
    if (settle->remove_by_top) j["remove_by"] = "top";
    if (!settle->count_spin) j["count_spin"] = false;  // absent when true: older stage caches stay valid
    return j;
  }
  const auto& l = std::get<cases::LaunchStageSpec>(st.action);
  return {{"kind", "launch"}, {"wall", l.wall},           {"speed", l.speed},
          {"angle", l.angle}, {"direction", l.direction}, {"height", l.height}};
}

}  // namespace

nlohmann::ordered_json scene_json(const cases::Scene& s) {
  Json j;
  Json materials = Json::array();
  for (const auto& m : s.materials) materials.push_back(material_json(m));
  j["materials"] = materials;
  Json mixing = Json::object();
  for (const auto& [key, rule] : s.mixing) mixing[key] = std::string(dem::to_string(rule));
  j["mixing"] = mixing;
  Json overrides = Json::array();
  for (const auto& o : s.pair_overrides) {
    overrides.push_back({{"materials", {o.material_a, o.material_b}}, {"values", pair_json(o.values)}});
  }
  j["pair_overrides"] = overrides;
  j["model"] = {{"normal", s.model.normal},
                {"damping", s.model.damping},
                {"tangential", s.model.tangential},
                {"cohesion", s.model.cohesion},
                {"rolling", s.model.rolling},
                {"clamp_tensile", s.model.clamp_tensile},
                {"friction_limit", std::string(dem::to_string(s.model.friction_limit))},
                {"jkr_rupture", std::string(dem::to_string(s.model.jkr_rupture))},
                {"wall_lever_arm", std::string(dem::to_string(s.model.wall_lever_arm))}};
  if (s.model.pair_lever_arm != dem::PairLeverArm::contact_point) {
    j["model"]["pair_lever_arm"] = std::string(dem::to_string(s.model.pair_lever_arm));
  }
  if (s.model.tangential_history != dem::TangentialHistory::project_rescale) {
    j["model"]["tangential_history"] = std::string(dem::to_string(s.model.tangential_history));
  }
  if (s.model.coulomb_test != dem::CoulombTest::total) {  // only when set: older scenes keep their fingerprints
    j["model"]["coulomb_test"] = std::string(dem::to_string(s.model.coulomb_test));
  }
  // Each policy that changes a result, only when it differs from its default (so that scenes
  // without it keep their fingerprints): a cached LAMMPS result of incremental Mindlin must never
  // answer for the total form.
  if (s.model.constant_torque_form != dem::ConstantTorqueForm::tangent) {
    j["model"]["constant_torque_form"] = std::string(dem::to_string(s.model.constant_torque_form));
  }
  if (s.model.mindlin_form != dem::MindlinForm::total) {
    j["model"]["mindlin_form"] = std::string(dem::to_string(s.model.mindlin_form));
  }
  if (s.model.mindlin_radius != dem::MindlinRadius::overlap) {
    j["model"]["mindlin_radius"] = std::string(dem::to_string(s.model.mindlin_radius));
  }
  if (s.model.unloaded_slider != dem::UnloadedSlider::cap) {
    j["model"]["unloaded_slider"] = std::string(dem::to_string(s.model.unloaded_slider));
  }
  if (s.model.adhesive_dashpot != dem::AdhesiveDashpot::clamp) {
    j["model"]["adhesive_dashpot"] = std::string(dem::to_string(s.model.adhesive_dashpot));
  }
  if (s.model.contact_at_zero_overlap) j["model"]["contact_at_zero_overlap"] = true;
  Json particles = Json::array();
  for (const auto& p : s.particles) particles.push_back(particle_json(p));
  j["particles"] = particles;
  Json walls = Json::array();
  for (const auto& w : s.walls) {
    Json wall = {{"point", w.point}, {"normal", w.normal}, {"velocity", w.velocity}, {"material", w.material}};
    if (w.rigid) wall["rigid"] = true;  // only when set: older scenes keep their fingerprints
    if (w.shape == dem::WallShape::triangle) {
      wall["shape"] = "triangle";
      wall["corners"] = w.corners;
      if (w.mesh) wall["mesh"] = s.meshes.at(*w.mesh).name;
    } else if (w.shape != dem::WallShape::plane) {
      wall["shape"] = std::string(cases::wall_shape_name(w));
      wall["axis_u"] = w.axis_u;
      wall["size_u"] = w.size_u;
      wall["size_v"] = w.size_v;
      wall["length"] = w.length;
    }
    if (w.removed_at) wall["removed_at"] = *w.removed_at;
    if (!w.in_preparation) wall["in_preparation"] = false;
    walls.push_back(std::move(wall));
  }
  j["walls"] = walls;
  if (!s.meshes.empty()) {  // written only when present: older scenes keep their fingerprints
    Json meshes = Json::array();
    for (const auto& m : s.meshes) {
      meshes.push_back({{"name", m.name}, {"file", m.file}, {"sha256", m.sha256}, {"facets", m.facets}});
    }
    j["meshes"] = meshes;
  }
  // Written only when set, so that the fingerprints of scenes without them stay as they were.
  if (s.domain.any_periodic()) {
    j["domain"] = {{"min", s.domain.min}, {"max", s.domain.max}, {"periodic", s.domain.periodic}};
  }
  if (s.neighbors.skin || s.neighbors.sort_every != 8) {
    j["neighbors"] = {{"skin", s.neighbors.skin ? Json(*s.neighbors.skin) : Json(nullptr)},
                      {"sort_every", s.neighbors.sort_every}};
  }
  j["gravity"] = s.gravity;
  j["fluid"] = s.fluid ? fluid_json(*s.fluid) : Json(nullptr);
  const auto& in = s.integration;
  j["integration"] = {{"scheme", std::string(dem::scheme_info(in.scheme).keyword)},
                      {"timestep", in.timestep ? Json(*in.timestep) : Json("auto")},
                      {"steps_per_collision", in.steps_per_collision},
                      {"duration", in.duration},
                      {"rotation", in.rotation},
                      {"startup", in.startup == dem::StartupPolicy::exact ? "exact" : "rk4"},
                      {"startup_substeps", in.startup_substeps},
                      {"implicit_tolerance", in.implicit_tolerance},
                      {"implicit_max_iterations", in.implicit_max_iterations},
                      {"leapfrog_start", in.leapfrog_start == dem::LeapfrogStart::half_kick ? "half_kick"
                                                                                           : "given_is_half_step"}};
  j["output"] = {{"trace_every", s.output.trace_every},
                 {"trace_particles", s.output.trace_particles},
                 {"trace_pairs", pairs_json(s.output.trace_pairs)},
                 {"trace_walls", pairs_json(s.output.trace_walls)},
                 {"trace_energy", s.output.trace_energy},
                 {"snapshot_times", s.output.snapshot_times}};
  if (!s.output.trace_aggregates.empty()) j["output"]["trace_aggregates"] = s.output.trace_aggregates;
  // Stages still to run (an unprepared scene); a prepared scene has none and its explicit
  // particles already say everything.
  if (!s.stages.empty()) {
    Json stages = Json::array();
    for (const cases::StageSpec& st : s.stages) stages.push_back(stage_json(st));
    j["stages"] = stages;
    j["integration"]["duration"] = s.duration_from_launch ? Json("launch") : Json(in.duration);
  }
  return j;
}

std::string scene_fingerprint(const cases::Scene& scene) {
  return support::sha256_hex(scene_json(scene).dump());
}

}  // namespace store
