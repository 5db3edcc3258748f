// SPDX-License-Identifier: MIT
#include "reports/snapshot_vtk.hpp"

#include <fmt/format.h>

namespace reports {
namespace {

void append_vectors(std::string& out, const char* name, const std::vector<cases::Vector3>& v) {
  out += fmt::format("VECTORS {} double\n", name);
  for (const auto& x : v) out += fmt::format("{:.17g} {:.17g} {:.17g}\n", x[0], x[1], x[2]);
}

}  // namespace

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
  append_vectors(out, "velocity", snap.velocity);
  append_vectors(out, "angular_velocity", snap.angular_velocity);
  return out;
}

}  // namespace reports
