// SPDX-License-Identifier: MIT
#include "reference/liggghts/atom_types.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "dem/particles/particles.hpp"

namespace reference::liggghts {

std::size_t AtomTypes::material_of(std::size_t t) const {
  if (t >= 1 && t <= particles.size()) return particles[t - 1].material;
  return wall_materials.at(t - 1 - particles.size());
}

std::optional<double> AtomTypes::reduced_mass(std::size_t a, std::size_t b) const {
  if (per_atom_diameter) return std::nullopt;
  const auto mobile_mass = [&](std::size_t t) -> std::optional<double> {
    if (t < 1 || t > particles.size() || particles[t - 1].fixed) return std::nullopt;
    return particles[t - 1].mass;
  };
  const std::optional<double> ma = mobile_mass(a);
  const std::optional<double> mb = mobile_mass(b);
  if (ma && mb) return *ma * *mb / (*ma + *mb);  // pair_gran's arithmetic
  if (ma) return ma;
  return mb;
}

AtomTypes classify(const cases::Scene& scene) {
  AtomTypes out;
  out.type_of.reserve(scene.particles.size());
  std::map<std::tuple<std::size_t, double, bool>, std::size_t> index_of;
  for (const cases::ParticleSpec& p : scene.particles) {
    const auto key = std::make_tuple(p.material, p.radius, p.fixed);
    auto it = index_of.find(key);
    if (it == index_of.end()) {
      it = index_of.emplace(key, out.particles.size()).first;
      out.particles.push_back(
          {p.material, p.radius, p.fixed, dem::sphere_mass(scene.materials.at(p.material).density, p.radius)});
    }
    out.type_of.push_back(it->second);
  }
  if (out.particles.size() > kMaxParticleTypes) {
    out.particles.clear();
    out.type_of.clear();
    out.per_atom_diameter = true;
    std::map<std::pair<std::size_t, bool>, std::size_t> coarse;
    for (const cases::ParticleSpec& p : scene.particles) {
      const auto key = std::make_pair(p.material, p.fixed);
      auto it = coarse.find(key);
      if (it == coarse.end()) {
        it = coarse.emplace(key, out.particles.size()).first;
        out.particles.push_back({p.material, 0.0, p.fixed, 0.0});
      }
      out.type_of.push_back(it->second);
    }
  }
  for (const cases::WallSpec& w : scene.walls) {
    const auto it = std::find(out.wall_materials.begin(), out.wall_materials.end(), w.material);
    out.wall_type_of.push_back(static_cast<std::size_t>(it - out.wall_materials.begin()));
    if (it == out.wall_materials.end()) out.wall_materials.push_back(w.material);
  }
  return out;
}

}  // namespace reference::liggghts
