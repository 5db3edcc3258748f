// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "cases/scene.hpp"
#include "dem/contact/mesh_topology.hpp"
#include "dem/contact/wall.hpp"

namespace cases {

/// The core's wall for a case wall: the same shape, place, velocity, material and removal time.
/// A mesh facet keeps its mesh's index into Scene::meshes (core_meshes renumbers it).
[[nodiscard]] dem::Wall core_wall(const WallSpec& w);

/// The connectivity of the scene's meshes for the core, given `walls` = core_wall of each of
/// scene.walls: one topology per mesh with facets in the scene, in Scene::meshes order; the
/// walls' mesh indices are renumbered to index the result. Throws std::invalid_argument when a
/// mesh's facets are not consecutive walls.
[[nodiscard]] std::vector<dem::MeshTopology> core_meshes(const Scene& scene, std::vector<dem::Wall>& walls);

/// A mobile sphere inside a wall: the sphere, the wall (indices into the scene) and the overlap [m].
struct WallOverlap {
  std::size_t particle = 0;
  std::size_t wall = 0;
  double overlap = 0.0;
};

/// The first mobile sphere of `scene` (then the first wall, in order) among the walls `counts` picks
/// that overlaps the wall by more than `share` of its radius, measured at t = 0 to the wall's
/// nearest surface point (dem::wall_frame); empty when there is none.
[[nodiscard]] std::optional<WallOverlap> first_wall_overlap(const Scene& scene,
                                                            const std::function<bool(const WallSpec&)>& counts,
                                                            double share);

}  // namespace cases
