// SPDX-License-Identifier: MIT
#include "cases/scene.hpp"

namespace cases {

std::optional<std::size_t> find_material(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return i;
  }
  return std::nullopt;
}

}  // namespace cases
