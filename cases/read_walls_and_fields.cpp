// SPDX-License-Identifier: MIT
// Section readers for what surrounds the particles: [[walls]] and [fields].
#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/mesh/stl_reader.hpp"
#include "cases/names.hpp"
#include "dem/contact/wall.hpp"
#include "support/text_file.hpp"
#include "support/sha256.hpp"

namespace cases::loader {
namespace {

constexpr auto kPlaneKeys = std::to_array<std::string_view>(
    {"type", "name", "point", "normal", "material", "velocity", "rigid", "remove_at", "in_preparation"});
constexpr auto kBoxWallKeys = std::to_array<std::string_view>(
    {"type", "name", "min", "max", "material", "open_faces", "rigid", "remove_at", "in_preparation"});
constexpr auto kRectangleWallKeys = std::to_array<std::string_view>(
    {"type", "name", "centre", "normal", "axis", "size", "material", "velocity", "rigid", "remove_at", "in_preparation"});
constexpr auto kDiscWallKeys = std::to_array<std::string_view>(
    {"type", "name", "centre", "normal", "radius", "hole_radius", "material", "velocity", "rigid", "remove_at", "in_preparation"});
constexpr auto kCylinderWallKeys = std::to_array<std::string_view>(
    {"type", "name", "base", "axis", "height", "radius", "material", "velocity", "rigid", "remove_at", "in_preparation"});
constexpr auto kConeWallKeys = std::to_array<std::string_view>({"type", "name", "base", "axis", "height", "base_radius",
                                                            "top_radius", "material", "velocity", "rigid",
                                                            "remove_at", "in_preparation"});
constexpr auto kMeshWallKeys = std::to_array<std::string_view>({"type", "name", "file", "scale", "translate", "material",
                                                                "velocity", "rigid", "remove_at", "in_preparation"});
constexpr auto kWallTypes =
    std::to_array<std::string_view>({"plane", "box", "rectangle", "disc", "cylinder", "cone", "mesh"});
constexpr auto kBoxFaces = std::to_array<std::string_view>({"x-", "x+", "y-", "y+", "z-", "z+"});
constexpr auto kFieldKeys = std::to_array<std::string_view>({"gravity", "fluid"});
constexpr auto kFluidKeys = std::to_array<std::string_view>(
    {"density", "viscosity", "drag", "buoyancy", "virtual_mass", "pressure_gradient", "velocity",
     "plug_flow"});
constexpr auto kPlugKeys = std::to_array<std::string_view>({"speed", "ramp_time", "zones"});
constexpr auto kZoneKeys = std::to_array<std::string_view>({"min", "max", "direction"});

/// A nonzero vector scaled to unit length; throws naming the value when it is zero. Its length
/// does not overflow (length()), so components of 1e300 do not give a zero vector.
Vector3 unit_vector(const Value& value) {
  const Vector3 v = value.vector3();
  const double n = length(v);
  if (!(n > 0.0)) value.fail("must be a nonzero vector");
  const Vector3 u{v[0] / n, v[1] / n, v[2] / n};
  if (!(std::fabs(length(u) - 1.0) < 1e-12)) {
    value.fail("cannot be scaled to unit length (its components span too many orders of magnitude)");
  }
  return u;
}

/// `remove_at`: the time the wall is taken away, ≥ 0 [s].
std::optional<double> read_removal(const Table& t) {
  const auto v = t.find("remove_at");
  if (!v) return std::nullopt;
  return v->number(non_negative_range());
}

/// `in_preparation`: whether the wall stands while the spheres are prepared (default true).
bool read_in_preparation(const Table& t) {
  const auto v = t.find("in_preparation");
  return v ? v->boolean() : true;
}

/// The keys every wall type shares: name, material, velocity, rigid, remove_at, in_preparation.
WallSpec read_common(const Table& t, const Scene& scene, std::size_t index) {
  WallSpec w;
  w.in_preparation = read_in_preparation(t);
  w.name = t.has("name") ? read_name(t.require("name")) : fmt::format("wall{}", index);
  w.material = material_index(t.require("material"), scene);
  if (const auto v = t.find("velocity")) w.velocity = read_velocity(*v);
  if (const auto v = t.find("rigid")) w.rigid = v->boolean();
  w.removed_at = read_removal(t);
  return w;
}

WallSpec read_plane(const Table& t, const Scene& scene, std::size_t index) {
  t.allow_only(kPlaneKeys);
  WallSpec w = read_common(t, scene, index);
  w.point = t.require("point").vector3();
  w.normal = unit_vector(t.require("normal"));
  return w;
}

/// A bounded rectangle: centre, normal, the direction of its first side and its two side lengths.
WallSpec read_rectangle(const Table& t, const Scene& scene, std::size_t index) {
  t.allow_only(kRectangleWallKeys);
  WallSpec w = read_common(t, scene, index);
  w.shape = dem::WallShape::rectangle;
  w.point = t.require("centre").vector3();
  w.normal = unit_vector(t.require("normal"));
  const Value axis = t.require("axis");
  w.axis_u = unit_vector(axis);
  const double cosine = w.axis_u[0] * w.normal[0] + w.axis_u[1] * w.normal[1] + w.axis_u[2] * w.normal[2];
  if (!(std::fabs(cosine) < 1e-9)) {
    axis.fail(fmt::format("must lie in the rectangle's plane (orthogonal to its normal); the cosine between them is {:.6g}",
                          cosine));
  }
  const Value size = t.require("size");
  const std::vector<Value> sides = size.elements();
  if (sides.size() != 2) size.fail(fmt::format("must list two side lengths [along axis, across], got {}", sides.size()));
  w.size_u = 0.5 * sides[0].number(positive_range());
  w.size_v = 0.5 * sides[1].number(positive_range());
  return w;
}

/// A disc, or a ring when hole_radius > 0 (a floor with a round orifice).
WallSpec read_disc(const Table& t, const Scene& scene, std::size_t index) {
  t.allow_only(kDiscWallKeys);
  WallSpec w = read_common(t, scene, index);
  w.shape = dem::WallShape::annulus;
  w.point = t.require("centre").vector3();
  w.normal = unit_vector(t.require("normal"));
  w.size_v = t.require("radius").number(positive_range());
  if (const auto v = t.find("hole_radius")) {
    w.size_u = v->number(non_negative_range());
    if (!(w.size_u < w.size_v)) v->fail(fmt::format("must be smaller than radius {:.6g} m", w.size_v));
  }
  return w;
}

/// The open lateral surface of a cylinder or cone frustum: base point on the axis, axis
/// direction, height along it, and the radii at the base and at the top.
WallSpec read_frustum(const Table& t, const Scene& scene, std::size_t index, bool cylinder) {
  t.allow_only(cylinder ? std::span<const std::string_view>(kCylinderWallKeys) : std::span<const std::string_view>(kConeWallKeys));
  WallSpec w = read_common(t, scene, index);
  w.shape = dem::WallShape::frustum;
  w.point = t.require("base").vector3();
  w.normal = unit_vector(t.require("axis"));
  w.length = t.require("height").number(positive_range());
  if (cylinder) {
    w.size_u = w.size_v = t.require("radius").number(positive_range());
  } else {
    w.size_u = t.require("base_radius").number(non_negative_range());
    const Value top = t.require("top_radius");
    w.size_v = top.number(non_negative_range());
    if (!(w.size_u > 0.0 || w.size_v > 0.0)) top.fail("base_radius and top_radius cannot both be 0");
  }
  return w;
}

/// A triangle mesh read from an STL file (ASCII or binary; path relative to the case file),
/// scaled by `scale` (the file's unit in metres) and then moved by `translate` [m]: one triangle
/// wall per facet, all of one material and velocity.
std::vector<WallSpec> read_mesh(const Table& t, Scene& scene, std::size_t index) {
  t.allow_only(kMeshWallKeys);
  const WallSpec common = read_common(t, scene, index);
  const Value file = t.require("file");
  const std::string name = file.string();
  if (name.empty()) file.fail("must name an STL file");
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene.source_path).parent_path() / path;
  double scale = 1.0;
  if (const auto v = t.find("scale")) scale = v->number(positive_range());
  Vector3 shift{};
  if (const auto v = t.find("translate")) shift = v->vector3();
  std::string bytes;
  TriangleMesh mesh;
  try {
    bytes = support::read_file(path);
    mesh = parse_stl(bytes, path.string());
  } catch (const std::exception& e) {
    file.fail(e.what());
  }
  MeshSpec spec{common.name, name, support::sha256_hex(bytes), mesh.triangles.size()};
  std::vector<WallSpec> walls;
  walls.reserve(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    WallSpec w = common;
    w.name = fmt::format("{}.{}", common.name, f);
    w.shape = dem::WallShape::triangle;
    w.mesh = scene.meshes.size();
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t a = 0; a < 3; ++a) w.corners[k][a] = scale * mesh.triangles[f].vertex[k][a] + shift[a];
    }
    dem::Wall frame{};
    try {
      frame = dem::triangle_wall({w.corners[0][0], w.corners[0][1], w.corners[0][2]},
                                 {w.corners[1][0], w.corners[1][1], w.corners[1][2]},
                                 {w.corners[2][0], w.corners[2][1], w.corners[2][2]});
    } catch (const std::invalid_argument&) {
      file.fail(fmt::format("triangle {} has no area once scaled by {:.6g} and moved by [{:.6g}, {:.6g}, {:.6g}] "
                            "(its corners coincide in double precision)",
                            f + 1, scale, shift[0], shift[1], shift[2]));
    }
    w.point = w.corners[0];
    w.normal = {frame.normal.x(), frame.normal.y(), frame.normal.z()};
    walls.push_back(std::move(w));
  }
  scene.meshes.push_back(std::move(spec));
  return walls;
}

/// The inner faces of an axis-aligned box, normals pointing inwards, minus the open ones.
std::vector<WallSpec> read_box(const Table& t, const Scene& scene, std::size_t index) {
  t.allow_only(kBoxWallKeys);
  const std::string name = t.has("name") ? read_name(t.require("name")) : fmt::format("box{}", index);
  const Vector3 lo = t.require("min").vector3();
  const Vector3 hi = t.require("max").vector3();
  for (int k = 0; k < 3; ++k) {
    if (!(hi[k] > lo[k])) t.fail("max", fmt::format("must exceed min in every component, got {} <= {}", hi[k], lo[k]));
  }
  const std::size_t material = material_index(t.require("material"), scene);
  bool rigid = false;
  if (const auto v = t.find("rigid")) rigid = v->boolean();
  const std::optional<double> removed_at = read_removal(t);
  const bool in_preparation = read_in_preparation(t);
  std::vector<std::string> open;
  if (const auto v = t.find("open_faces")) {
    for (const Value& f : v->elements()) open.push_back(f.keyword(kBoxFaces, "box face"));
  }
  std::vector<WallSpec> walls;
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      const std::string face = fmt::format("{}{}", "xyz"[axis], side < 0 ? '-' : '+');
      if (std::find(open.begin(), open.end(), face) != open.end()) continue;
      WallSpec w;
      w.name = name + "." + face;
      w.point = side < 0 ? lo : hi;
      w.normal = {0.0, 0.0, 0.0};
      w.normal[static_cast<std::size_t>(axis)] = side < 0 ? 1.0 : -1.0;
      w.material = material;
      w.rigid = rigid;
      w.removed_at = removed_at;
      w.in_preparation = in_preparation;
      walls.push_back(w);
    }
  }
  return walls;
}

std::vector<FlowZoneSpec> read_zones(const Value& value) {
  std::vector<FlowZoneSpec> zones;
  for (const Value& item : value.elements()) {
    const Table z = item.table();
    z.allow_only(kZoneKeys);
    FlowZoneSpec spec{z.require("min").vector3(), z.require("max").vector3(),
                      unit_vector(z.require("direction"))};
    for (int k = 0; k < 3; ++k) {
      if (!(spec.max[k] > spec.min[k])) z.fail("max", "must exceed min in every component");
    }
    zones.push_back(spec);
  }
  if (zones.empty()) value.fail("must list at least one zone");
  return zones;
}

FluidSpec read_fluid(const Table& t) {
  t.allow_only(kFluidKeys);
  FluidSpec f;
  if (const auto v = t.find("density")) f.density = v->number(positive_range());
  if (const auto v = t.find("viscosity")) f.viscosity = v->number(positive_range());
  if (const auto v = t.find("drag")) f.drag = v->boolean();
  if (const auto v = t.find("buoyancy")) f.buoyancy = v->boolean();
  if (const auto v = t.find("virtual_mass")) f.virtual_mass = v->boolean();
  if (const auto v = t.find("pressure_gradient")) f.pressure_gradient = v->vector3();
  if (const auto v = t.find("velocity")) f.velocity = read_velocity(*v);
  if (const auto v = t.find("plug_flow")) {
    if (t.has("velocity")) v->fail("give either a uniform fluid velocity or plug_flow, not both");
    const Table plug = v->table();
    plug.allow_only(kPlugKeys);
    const Value speed = plug.require("speed");
    f.plug_speed = speed.number(positive_range());
    check_speed(speed, f.plug_speed, "plug speed");
    if (const auto r = plug.find("ramp_time")) f.ramp_time = r->number(dem::ValueRange{0.0, std::numeric_limits<double>::infinity(), false, true});
    f.zones = read_zones(plug.require("zones"));
  }
  return f;
}

}  // namespace

void read_walls(const Table& root, Scene& scene) {
  const auto section = root.find("walls");
  if (!section) return;
  std::size_t index = 0;
  for (const Value& entry : section->elements()) {
    const Table t = entry.table();
    const std::string type = t.require("type").keyword(kWallTypes, "wall type");
    if (type == "plane") {
      scene.walls.push_back(read_plane(t, scene, index));
    } else if (type == "box") {
      for (auto& w : read_box(t, scene, index)) scene.walls.push_back(std::move(w));
    } else if (type == "rectangle") {
      scene.walls.push_back(read_rectangle(t, scene, index));
    } else if (type == "disc") {
      scene.walls.push_back(read_disc(t, scene, index));
    } else if (type == "mesh") {
      for (auto& w : read_mesh(t, scene, index)) scene.walls.push_back(std::move(w));
    } else {
      scene.walls.push_back(read_frustum(t, scene, index, type == "cylinder"));
    }
    if (!read_in_preparation(t)) {
      if (!root.has("stages")) {
        t.fail("in_preparation", "false places the wall when the run starts, after the preparation stages, but the "
                                 "case has none ([[stages]]); drop the key");
      }
      if (read_removal(t) == 0.0) {
        t.fail("in_preparation", "false with remove_at = 0 makes a wall that never stands; drop the wall");
      }
    }
    const auto facets = static_cast<std::size_t>(std::count_if(
        scene.walls.begin(), scene.walls.end(), [](const WallSpec& w) { return w.mesh.has_value(); }));
    if (scene.walls.size() - facets > kMaxWalls) {
      entry.fail(fmt::format("makes {} walls (a box counts its faces), more than the limit of {}",
                             scene.walls.size() - facets, kMaxWalls));
    }
    if (facets > kMaxMeshFacets) {
      entry.fail(fmt::format("makes {} mesh facets (all meshes together), more than the limit of {}", facets,
                             kMaxMeshFacets));
    }
    ++index;
  }
}

void apply_rigid_walls(Scene& scene) {
  const std::size_t base_count = scene.materials.size();
  std::vector<bool> used_compliant(base_count, false);
  for (const auto& p : scene.particles) used_compliant[p.material] = true;
  for (const auto& w : scene.walls) {
    if (!w.rigid) used_compliant[w.material] = true;
  }
  std::vector<std::size_t> rigid_copy(base_count, base_count);  // base_count: none yet
  for (auto& w : scene.walls) {
    if (!w.rigid) continue;
    const std::size_t base = w.material;
    if (!used_compliant[base]) {
      scene.materials[base].rigid = true;  // only rigid walls use it: it becomes rigid itself
      continue;
    }
    if (rigid_copy[base] == base_count) {
      dem::MaterialProperties copy = scene.materials[base];
      copy.name += " (rigid)";
      copy.rigid = true;
      rigid_copy[base] = scene.materials.size();
      scene.materials.push_back(std::move(copy));
      // The copy inherits the material's [[pairs]] entries: measured pair values still win. An
      // entry (base, x) becomes (copy, x); a self entry (base, base) becomes (base, copy), the
      // particle against the rigid wall (copy against copy would be two rigid bodies).
      const std::size_t overrides = scene.pair_overrides.size();
      for (std::size_t k = 0; k < overrides; ++k) {
        dem::PairOverride o = scene.pair_overrides[k];
        if (o.material_a == base) {
          o.material_a = rigid_copy[base];
        } else if (o.material_b == base) {
          o.material_b = rigid_copy[base];
        } else {
          continue;
        }
        scene.pair_overrides.push_back(o);
      }
    }
    w.material = rigid_copy[base];
  }
}

void read_fields(const Table& root, Scene& scene) {
  const auto section = root.find("fields");
  if (!section) return;
  const Table fields = section->table();
  fields.allow_only(kFieldKeys);
  if (const auto v = fields.find("gravity")) scene.gravity = v->vector3();
  if (const auto v = fields.find("fluid")) scene.fluid = read_fluid(v->table());
}

}  // namespace cases::loader
