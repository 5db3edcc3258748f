// SPDX-License-Identifier: MIT
#include "reference/lammps/atom_types.hpp"

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
  for (const cases::ParticleSpec& p : scene.particles) {
    std::size_t index = 0;
    while (index < out.types.size() &&
           !(out.types[index].material == p.material && out.types[index].radius == p.radius &&
             out.types[index].fixed == p.fixed)) {
      ++index;
    }
    if (index == out.types.size()) {
      const double density = scene.materials.at(p.material).density;
      out.types.push_back({p.material, p.radius, p.fixed, dem::sphere_mass(density, p.radius)});
    }
    out.type_of.push_back(index);
  }
  return out;
}

}  // namespace reference::lammps
