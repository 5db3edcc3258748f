// SPDX-License-Identifier: MIT
#pragma once
// Triangle meshes from STL files (ASCII and binary), checked on reading: the walls a user brings
// (docs/walls.md, "Meshes (STL): the reader"). A file that is truncated, holds a number that is not finite or a
// triangle of no area is refused with the file, the triangle and what is wrong.

#include <array>
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cases {

/// One triangle: its three corners [m after scaling]; its normal follows their order (right hand).
struct MeshTriangle {
  std::array<std::array<double, 3>, 3> vertex{};
};

/// A triangle mesh as read: the solid's name (ASCII; empty for binary) and its triangles in file order.
struct TriangleMesh {
  std::string name;
  std::vector<MeshTriangle> triangles;
};

/// Why an STL file was refused; what() names the file and the problem.
class StlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The most triangles a mesh may hold (a bound on memory and on the wall loop's work).
inline constexpr std::size_t kMaxMeshTriangles = 200000;

/// Reads `bytes` (the content of `source`, named in messages) as an STL mesh. Binary when its size
/// is 84 + 50 n bytes for the n its header gives; otherwise ASCII, which must start with `solid`
/// and hold no NUL byte (a binary file whose header starts with "solid" is not mistaken for text).
/// The facet normals the file lists are ignored (the vertex order orients a triangle). Throws
/// StlError on a truncated or malformed file, a coordinate that is not finite, a triangle whose
/// area is below 1e-12 of its longest edge squared, no triangle, or more than kMaxMeshTriangles.
TriangleMesh parse_stl(std::string_view bytes, const std::string& source);

/// parse_stl of the file at `path`; a file that cannot be read is an StlError too.
TriangleMesh read_stl(const std::filesystem::path& path);

}  // namespace cases
