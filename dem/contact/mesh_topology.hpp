// SPDX-License-Identifier: MIT
#pragma once
// Which facet contacts of a mesh wall count (docs/walls.md, "Meshes: one contact per surface
// point"). A sphere near an edge or a corner of a mesh sees that edge or corner from every facet
// around it; counted facet by facet, a sphere rolling over a flat triangulated floor would feel
// an extra push at every seam. A facet's contact counts when its nearest point is a local
// minimum of the distance over the whole mesh, and a point that several facets share is counted
// by the lowest-numbered of them.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dem/contact/wall.hpp"
#include "dem/core/vector.hpp"

namespace dem {

/// The connectivity of one mesh wall: corners welded where their coordinates agree exactly, the
/// corners of each facet, and the facets around each corner. The facets are consecutive walls.
struct MeshTopology {
  std::uint32_t first_wall = 0;                        ///< wall index of facet 0
  std::vector<Vec3> corners;                           ///< welded corner positions at t = 0 [m]
  std::vector<std::array<std::uint32_t, 3>> facets;    ///< each facet's corner ids, in its corner order
  std::vector<std::uint32_t> around_offsets;           ///< facets around corner c: around[around_offsets[c], around_offsets[c + 1])
  std::vector<std::uint32_t> around;                   ///< facet ids, ascending per corner
  std::vector<double> snap;                            ///< per facet: nearest_on_triangle's snap distance [m]
  std::vector<double> slack;                           ///< per facet: rounding allowance of the local-minimum test [m]

  /// Whether facet f's contact with a sphere centred at x at time t counts (see the file's
  /// comment). `walls` holds the facets at [first_wall, first_wall + facets.size()).
  [[nodiscard]] bool counts(std::span<const Wall> walls, std::uint32_t f, const Vec3& x, double t) const;

 private:
  /// A facet's nearest point to x (in the mesh's frame at t = 0), the mesh part it names (one or
  /// two corner ids) and whether it is a local minimum over the mesh.
  struct Candidate {
    Vec3 point;
    std::array<std::uint32_t, 2> part;
    bool face;
    bool minimum;
  };
  [[nodiscard]] Candidate candidate(std::span<const Wall> walls, std::uint32_t f, const Vec3& x_rest) const;
  /// Calls visit(g) for every facet g ≠ f around the named part.
  template <typename Visit>
  void for_each_sharing(std::uint32_t f, const std::array<std::uint32_t, 2>& part, Visit&& visit) const;
};

/// Whether wall w's contact with a sphere centred at x at time t counts: always for a wall of no
/// mesh, MeshTopology::counts for a facet (`meshes` indexed by Wall::mesh).
[[nodiscard]] bool facet_counts(std::span<const Wall> walls, std::span<const MeshTopology> meshes, std::uint32_t w,
                                const Vec3& x, double t);

/// The facets' connectivity, from their corners (each facet's corners in its own order); a
/// mesh whose facets are walls first_wall, first_wall + 1, ….
[[nodiscard]] MeshTopology build_mesh_topology(std::span<const std::array<Vec3, 3>> facets, std::uint32_t first_wall);

}  // namespace dem
