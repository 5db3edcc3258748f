// SPDX-License-Identifier: MIT
#include "dem/contact/mesh_topology.hpp"

#include <algorithm>
#include <map>

namespace dem {
namespace {

// The snap distance, as a share of a facet's longest edge: nearest points this close to an edge
// or corner name it, so that facets around it agree on the name.
constexpr double kSnapShare = 1e-6;
// The local-minimum test's allowance for rounding, as a share of the longest edge: far below the
// snap distance, so that a sphere one snap distance beside a flat seam already fails the
// neighbour's test (its tilt over an edge length exceeds the allowance while the facets are
// not more than ~1e4 times smaller than the sphere).
constexpr double kSlackShare = 1e-10;

/// Marks the unused second id of a part that is one corner.
constexpr std::uint32_t kNoCorner = 0xffffffffU;

/// Whether corner id c is one of the part's ids.
bool in_part(const std::array<std::uint32_t, 2>& part, std::uint32_t c) noexcept {
  return part[0] == c || part[1] == c;
}

}  // namespace

MeshTopology build_mesh_topology(std::span<const std::array<Vec3, 3>> facets, std::uint32_t first_wall) {
  MeshTopology m;
  m.first_wall = first_wall;
  std::map<std::array<double, 3>, std::uint32_t> ids;
  m.facets.reserve(facets.size());
  for (const auto& f : facets) {
    std::array<std::uint32_t, 3> corner{};
    double longest = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::array<double, 3> key{f[k].x(), f[k].y(), f[k].z()};
      const auto [it, added] = ids.emplace(key, static_cast<std::uint32_t>(m.corners.size()));
      if (added) m.corners.push_back(f[k]);
      corner[k] = it->second;
      longest = std::max(longest, (f[(k + 1) % 3] - f[k]).norm());
    }
    m.facets.push_back(corner);
    m.snap.push_back(kSnapShare * longest);
    m.slack.push_back(kSlackShare * longest);
  }
  // Facets around each corner, in ascending order (counting sort).
  m.around_offsets.assign(m.corners.size() + 1, 0);
  for (const auto& f : m.facets) {
    for (const std::uint32_t c : f) ++m.around_offsets[c + 1];
  }
  for (std::size_t c = 0; c < m.corners.size(); ++c) m.around_offsets[c + 1] += m.around_offsets[c];
  m.around.resize(m.around_offsets.back());
  std::vector<std::uint32_t> fill(m.around_offsets.begin(), m.around_offsets.end() - 1);
  for (std::uint32_t f = 0; f < m.facets.size(); ++f) {
    for (const std::uint32_t c : m.facets[f]) {
      // A degenerate facet naming one corner twice is refused upstream (it has no area).
      m.around[fill[c]++] = f;
    }
  }
  return m;
}

template <typename Visit>
void MeshTopology::for_each_sharing(std::uint32_t f, const std::array<std::uint32_t, 2>& part, Visit&& visit) const {
  for (std::uint32_t k = around_offsets[part[0]]; k < around_offsets[part[0] + 1]; ++k) {
    const std::uint32_t g = around[k];
    if (g == f) continue;
    if (part[1] != kNoCorner) {
      const auto& c = facets[g];
      if (c[0] != part[1] && c[1] != part[1] && c[2] != part[1]) continue;
    }
    visit(g);
  }
}

MeshTopology::Candidate MeshTopology::candidate(std::span<const Wall> walls, std::uint32_t f,
                                                const Vec3& x_rest) const {
  const Wall& w = walls[first_wall + f];
  const Vec3 v = w.normal.cross(w.axis_u);
  const Vec3 rel = x_rest - w.point;
  const TriangleNearest near =
      nearest_on_triangle(PlaneTriangle{w.length, w.size_u, w.size_v}, rel.dot(w.axis_u), rel.dot(v), snap[f]);
  Candidate out{w.point + near.u * w.axis_u + near.v * v, {kNoCorner, kNoCorner}, near.part == TrianglePart::face, true};
  if (out.face) return out;
  const auto& c = facets[f];
  if (near.part == TrianglePart::corner) {
    out.part = {c[near.index], kNoCorner};
  } else {
    const std::uint32_t a = c[near.index];
    const std::uint32_t b = c[(near.index + 1) % 3];
    out.part = {std::min(a, b), std::max(a, b)};  // named alike by the facets on either side
  }
  // A projection inside the facet is a local minimum of the distance whatever part it is named
  // after. A point on the boundary is one when no facet around it comes nearer: every corner of
  // those facets off the part lies on the far side of the tangent plane through the point.
  if (near.inside) return out;
  const Vec3 n = x_rest - out.point;
  for_each_sharing(f, out.part, [&](std::uint32_t g) {
    for (const std::uint32_t q : facets[g]) {
      if (in_part(out.part, q)) continue;
      if (n.dot(corners[q] - out.point) > slack[g] * n.norm()) out.minimum = false;
    }
  });
  return out;
}

bool MeshTopology::counts(std::span<const Wall> walls, std::uint32_t f, const Vec3& x, double t) const {
  const Vec3 x_rest = x - t * walls[first_wall + f].velocity;
  const Candidate mine = candidate(walls, f, x_rest);
  if (mine.face) return true;
  if (!mine.minimum) return false;
  // The point is shared: the lowest-numbered facet that names the same part and finds it a
  // minimum counts it. Each facet decides from the same arithmetic, so one of them counts it
  // (docs/walls.md names the slivers where tolerances tied to facet sizes can let two).
  bool lower_counts = false;
  for_each_sharing(f, mine.part, [&](std::uint32_t g) {
    if (lower_counts || g > f) return;
    const Candidate theirs = candidate(walls, g, x_rest);
    if (!theirs.face && theirs.minimum && theirs.part == mine.part) lower_counts = true;
  });
  return !lower_counts;
}

bool facet_counts(std::span<const Wall> walls, std::span<const MeshTopology> meshes, std::uint32_t w, const Vec3& x,
                  double t) {
  const Wall& wall = walls[w];
  if (wall.mesh == kNoMesh) return true;
  const MeshTopology& mesh = meshes[wall.mesh];
  return mesh.counts(walls, w - mesh.first_wall, x, t);
}

}  // namespace dem
