// SPDX-License-Identifier: MIT
#include "reference/lammps/atom_types.hpp"

#include <map>
#include <tuple>

#include "dem/particles/particles.hpp"

namespace reference::lammps {

std::optional<double> AtomTypes::reduced_mass(std::size_t a, std::size_t b) const {
  const AtomType& ta = types.at(a);
  const AtomType& tb = types.at(b);
  if (ta.fixed && tb.fixed) return std::nullopt;
  // The same arithmetic as dem::pair_geometry, so η matches the core's to the last bit.
  const double inverse_a = ta.fixed ? 0.0 : 1.0 / ta.mass;
  const double inverse_b = tb.fixed ? 0.0 : 1.0 / tb.mass;
  return 1.0 / (inverse_a + inverse_b);
}

AtomTypes classify_particles(const cases::Scene& scene) {
  AtomTypes out;
  out.type_of.reserve(scene.particles.size());
  // Classes by (material, radius, fixed) in order of first appearance, found through a map so
  // that a million particles classify in O(N log N).
  std::map<std::tuple<std::size_t, double, bool>, std::size_t> index_of;
  for (const cases::ParticleSpec& p : scene.particles) {
    const auto key = std::make_tuple(p.material, p.radius, p.fixed);
    auto it = index_of.find(key);
    if (it == index_of.end()) {
      const double density = scene.materials.at(p.material).density;
      it = index_of.emplace(key, out.types.size()).first;
      out.types.push_back({p.material, p.radius, p.fixed, dem::sphere_mass(density, p.radius)});
    }
    out.type_of.push_back(it->second);
  }
  if (out.types.size() <= kMaxAtomTypes) return out;
  // Too many classes: one type per (material, fixed), diameters per atom.
  AtomTypes coarse;
  coarse.per_atom_diameter = true;
  std::map<std::pair<std::size_t, bool>, std::size_t> coarse_of;
  for (const cases::ParticleSpec& p : scene.particles) {
    const auto key = std::make_pair(p.material, p.fixed);
    auto it = coarse_of.find(key);
    if (it == coarse_of.end()) {
      it = coarse_of.emplace(key, coarse.types.size()).first;
      coarse.types.push_back({p.material, 0.0, p.fixed, 0.0});
    }
    coarse.type_of.push_back(it->second);
  }
  return coarse;
}

bool atoms_in_data_file(const cases::Scene& scene) {
  // Diameters per atom go in the data file: `set type … diameter` would give a type one diameter.
  return scene.particles.size() > kMaxInlineAtoms || classify_particles(scene).per_atom_diameter;
}

}  // namespace reference::lammps
