// SPDX-License-Identifier: MIT
// Section readers for [domain] (box and periodic axes) and [neighbors] (Verlet skin, reorder).
#include <array>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "cases/loader_sections.hpp"

namespace cases::loader {
namespace {

constexpr auto kDomainKeys = std::to_array<std::string_view>({"min", "max", "periodic"});
constexpr auto kNeighborKeys = std::to_array<std::string_view>({"skin", "sort_every"});

}  // namespace

void read_domain(const Table& root, Scene& scene) {
  const auto section = root.find("domain");
  if (!section) return;
  const Table t = section->table();
  t.allow_only(kDomainKeys);
  DomainSpec& d = scene.domain;
  d.min = t.require("min").vector3();
  d.max = t.require("max").vector3();
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(d.max[k] > d.min[k])) {
      t.fail("max", fmt::format("must exceed min along every axis (axis {}: min {}, max {})", kAxes[k], d.min[k], d.max[k]));
    }
  }
  if (const auto v = t.find("periodic")) {
    for (const Value& axis : v->elements()) {
      const std::string name = axis.keyword(kAxes, "axis");
      const std::size_t k = name == "x" ? 0 : (name == "y" ? 1 : 2);
      if (d.periodic[k]) axis.fail(fmt::format("axis {} is listed twice", name));
      d.periodic[k] = true;
    }
  }
  // A plane wall across a periodic axis would cut the ring; one along it is fine.
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (d.periodic[k] && scene.walls[w].shape != dem::WallShape::plane) {
        t.fail("periodic", fmt::format("axis {} is periodic, but wall {} ('{}') is a {}; bounded walls have no "
                                       "periodic images, so a periodic domain takes plane walls only",
                                       kAxes[k], w, scene.walls[w].name, wall_shape_name(scene.walls[w])));
      }
      if (d.periodic[k] && scene.walls[w].normal[k] != 0.0) {
        t.fail("periodic", fmt::format("axis {} is periodic, but wall {} ('{}') has a normal component along it; "
                                       "a plane wall must be parallel to every periodic axis",
                                       kAxes[k], w, scene.walls[w].name));
      }
    }
  }
}

void read_neighbors(const Table& root, Scene& scene) {
  const auto section = root.find("neighbors");
  if (!section) return;
  const Table t = section->table();
  t.allow_only(kNeighborKeys);
  if (const auto v = t.find("skin")) scene.neighbors.skin = v->number(positive_range());
  if (const auto v = t.find("sort_every")) scene.neighbors.sort_every = static_cast<std::uint32_t>(v->integer(0, 1'000'000));
}

}  // namespace cases::loader
