// SPDX-License-Identifier: MIT
#include "compare/metrics_packing.hpp"

#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "cases/packing_region.hpp"
#include "compare/metrics_breakup.hpp"
#include "compare/packing_geometry.hpp"

namespace comparison {

std::optional<CohesionMetric> packing_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::RunResult& run) {
  if (!cases::is_packing_metric(name)) return std::nullopt;
  if (!scene.compare.packing) return CohesionMetric{std::nullopt, "the case has no [compare.packing] region"};
  if (run.snapshots.empty()) {
    return CohesionMetric{std::nullopt, "the run has no snapshot (output.snapshot_times)"};
  }
  const cases::Snapshot& last = run.snapshots.back();
  if (last.position.size() != scene.particles.size()) {
    return CohesionMetric{std::nullopt, fmt::format("the last snapshot holds {} spheres, the scene {}",
                                                    last.position.size(), scene.particles.size())};
  }
  std::vector<cases::Vector3> centres;
  std::vector<double> radii;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (scene.particles[i].fixed) continue;
    centres.push_back(last.position[i]);
    radii.push_back(scene.particles[i].radius);
  }
  const cases::PackingSpec& spec = *scene.compare.packing;
  const Box region{spec.min, spec.max};
  try {
    if (name == "packing_fraction") return CohesionMetric{packing_fraction(centres, radii, region), ""};
    if (name == "packing_fraction_interior") {
      return CohesionMetric{packing_fraction(centres, radii, interior(region, cases::interior_margin(scene))), ""};
    }
    if (name == "orf") return CohesionMetric{obscured_fraction(centres, radii, region, spec.orf_ny, spec.orf_nz), ""};
    if (name == "coordination_number") {
      // Body contacts among the mobile spheres (the breakup metrics' cell search), averaged over
      // the spheres whose centres lie in the region.
      std::vector<breakup::SnapshotSphere> spheres;
      for (std::size_t k = 0; k < centres.size(); ++k) {
        spheres.push_back({dem::Vec3(centres[k][0], centres[k][1], centres[k][2]), radii[k]});
      }
      std::vector<std::uint32_t> contacts(spheres.size(), 0);
      for (const auto& [i, j] : breakup::bonded_pairs(spheres, breakup::body_contact(spheres))) {
        ++contacts[i];
        ++contacts[j];
      }
      std::size_t inside = 0;
      std::size_t sum = 0;
      for (std::size_t k = 0; k < centres.size(); ++k) {
        if (!region.contains(centres[k])) continue;
        ++inside;
        sum += contacts[k];
      }
      if (inside == 0) return CohesionMetric{std::nullopt, "no mobile sphere has its centre in the region"};
      return CohesionMetric{static_cast<double>(sum) / static_cast<double>(inside), ""};
    }
    return CohesionMetric{share_inside(centres, region), ""};  // dose_remaining
  } catch (const std::invalid_argument& e) {
    return CohesionMetric{std::nullopt, e.what()};
  }
}

}  // namespace comparison
