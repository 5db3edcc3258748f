// SPDX-License-Identifier: MIT
#include "reports/snapshot_vtk.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cases/core_wall.hpp"
#include "compare/packing_geometry.hpp"
#include "dem/core/vector.hpp"

namespace reports {
namespace {

void append_vectors(std::string& out, const char* name, const std::vector<cases::Vector3>& v) {
  out += fmt::format("VECTORS {} double\n", name);
  for (const auto& x : v) out += fmt::format("{:.17g} {:.17g} {:.17g}\n", x[0], x[1], x[2]);
}

void append_ints(std::string& out, const char* name, const std::vector<int>& v) {
  out += fmt::format("SCALARS {} int 1\nLOOKUP_TABLE default\n", name);
  for (const int x : v) out += fmt::format("{}\n", x);
}

}  // namespace

std::vector<int> snapshot_contacts(const cases::Scene& scene, const cases::Snapshot& snap) {
  const std::size_t n = snap.position.size();
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) radii[i] = scene.particles.at(i).radius;
  const std::vector<std::uint32_t> spheres = comparison::contact_counts(snap.position, radii);
  std::vector<int> count(spheres.begin(), spheres.end());
  std::vector<dem::Wall> walls;
  for (const cases::WallSpec& spec : scene.walls) walls.push_back(cases::core_wall(spec));
  const std::vector<dem::MeshTopology> meshes = cases::core_meshes(scene, walls);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const dem::Wall& w = walls[k];
    if (!w.present(snap.time)) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const dem::Vec3 x(snap.position[i][0], snap.position[i][1], snap.position[i][2]);
      if (!(dem::wall_frame(w, x, snap.time).distance < radii[i])) continue;
      // A mesh counts a point that several facets share once, as the core does.
      if (dem::facet_counts(walls, meshes, static_cast<std::uint32_t>(k), x, snap.time)) ++count[i];
    }
  }
  return count;
}

std::string vtk_series(const std::vector<std::pair<std::string, double>>& files) {
  nlohmann::ordered_json j;
  j["file-series-version"] = "1.0";
  j["files"] = nlohmann::ordered_json::array();
  for (const auto& [name, time] : files) j["files"].push_back({{"name", name}, {"time", time}});
  return j.dump(2) + "\n";
}

std::string snapshot_vtk(const cases::Scene& scene, const cases::Snapshot& snap,
                         const std::string& engine) {
  const std::size_t n = snap.position.size();
  std::string out = "# vtk DataFile Version 3.0\n";
  out += fmt::format("dem-workbench {} {} t={:.17g} s\nASCII\nDATASET POLYDATA\n", scene.name, engine, snap.time);
  out += fmt::format("POINTS {} double\n", n);
  for (const auto& x : snap.position) out += fmt::format("{:.17g} {:.17g} {:.17g}\n", x[0], x[1], x[2]);
  out += fmt::format("VERTICES {} {}\n", n, 2 * n);
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("1 {}\n", i);
  out += fmt::format("POINT_DATA {}\n", n);
  out += "SCALARS radius double 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("{:.17g}\n", scene.particles.at(i).radius);
  out += "SCALARS effect_radius double 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < n; ++i) out += fmt::format("{:.17g}\n", scene.particles.at(i).effect_radius);
  out += "SCALARS fixed int 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < n; ++i) out += scene.particles.at(i).fixed ? "1\n" : "0\n";
  std::vector<int> material(n);
  for (std::size_t i = 0; i < n; ++i) material[i] = static_cast<int>(scene.particles.at(i).material);
  append_ints(out, "material", material);
  append_ints(out, "contacts", snapshot_contacts(scene, snap));
  append_vectors(out, "velocity", snap.velocity);
  append_vectors(out, "angular_velocity", snap.angular_velocity);
  return out;
}

}  // namespace reports
