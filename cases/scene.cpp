// SPDX-License-Identifier: MIT
#include "cases/scene.hpp"

namespace cases {

std::string_view wall_shape_name(const WallSpec& wall) noexcept {
  switch (wall.shape) {
    case dem::WallShape::plane: return "plane";
    case dem::WallShape::rectangle: return "rectangle";
    case dem::WallShape::annulus: return "disc";
    case dem::WallShape::frustum: return wall.size_u == wall.size_v ? "cylinder" : "cone";
    case dem::WallShape::triangle: return "mesh";
  }
  return "plane";
}

std::optional<std::size_t> find_material(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return i;
  }
  return std::nullopt;
}

}  // namespace cases
