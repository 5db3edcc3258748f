// SPDX-License-Identifier: MIT
#include "cases/core_wall.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "cases/core_vector.hpp"
#include "dem/contact/mesh_topology.hpp"

namespace cases {

std::vector<dem::MeshTopology> core_meshes(const Scene& scene, std::vector<dem::Wall>& walls) {
  std::vector<dem::MeshTopology> out;
  std::vector<std::uint32_t> renumber(scene.meshes.size(), dem::kNoMesh);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    std::vector<std::array<dem::Vec3, 3>> facets;
    std::size_t first = scene.walls.size();
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      const WallSpec& spec = scene.walls[w];
      if (spec.mesh != m) continue;
      if (facets.empty()) first = w;
      if (w != first + facets.size()) {
        throw std::invalid_argument("the facets of mesh " + scene.meshes[m].name + " are not consecutive walls");
      }
      facets.push_back({core_vec(spec.corners[0]), core_vec(spec.corners[1]), core_vec(spec.corners[2])});
    }
    if (facets.empty()) continue;  // none of its facets is in this scene
    renumber[m] = static_cast<std::uint32_t>(out.size());
    out.push_back(dem::build_mesh_topology(facets, static_cast<std::uint32_t>(first)));
  }
  for (dem::Wall& w : walls) {
    if (w.mesh != dem::kNoMesh) w.mesh = renumber.at(w.mesh);
  }
  return out;
}

dem::Wall core_wall(const WallSpec& w) {
  // A facet's frame comes from its corners (the one formula, dem::triangle_wall); every other
  // shape's from its keys.
  dem::Wall out = w.shape == dem::WallShape::triangle
                      ? dem::triangle_wall(core_vec(w.corners[0]), core_vec(w.corners[1]), core_vec(w.corners[2]))
                      : dem::Wall{core_vec(w.point), core_vec(w.normal)};
  if (w.shape != dem::WallShape::triangle) {
    out.shape = w.shape;
    out.axis_u = core_vec(w.axis_u);
    out.size_u = w.size_u;
    out.size_v = w.size_v;
    out.length = w.length;
  }
  out.velocity = core_vec(w.velocity);
  out.material = static_cast<std::uint32_t>(w.material);
  out.mesh = w.mesh ? static_cast<std::uint32_t>(*w.mesh) : dem::kNoMesh;
  out.removed_at = w.removed_at.value_or(std::numeric_limits<double>::infinity());
  return out;
}

std::optional<WallOverlap> first_wall_overlap(const Scene& scene, const std::function<bool(const WallSpec&)>& counts,
                                              double share) {
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    const dem::Vec3 x = core_vec(p.position);
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      if (!counts(scene.walls[w])) continue;
      const double overlap = p.radius - dem::wall_frame(core_wall(scene.walls[w]), x, 0.0).distance;
      if (!(overlap <= share * p.radius)) return WallOverlap{i, w, overlap};  // NaN counts as inside
    }
  }
  return std::nullopt;
}

}  // namespace cases
