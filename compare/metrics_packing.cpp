// SPDX-License-Identifier: MIT
#include "compare/metrics_packing.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "cases/packing_region.hpp"
#include "compare/packing_geometry.hpp"
#include "compare/packing_series.hpp"

namespace comparison {
namespace {

/// A metric read from the run's snapshots of the bed: fluidisation_time or orf_largest_drop from
/// the ORF curve, largest_departed_fragment from the departed spheres.
CohesionMetric fluidisation_metric(const std::string& name, const cases::Scene& scene, const cases::RunResult& run) {
  auto series = packing_series(scene, run);
  if (const auto* problem = std::get_if<std::string>(&series)) return CohesionMetric{std::nullopt, *problem};
  const auto& samples = std::get<std::vector<PackingSample>>(series);
  if (samples.size() < cases::kMinFluidisationSnapshots) {
    return CohesionMetric{std::nullopt, fmt::format("the run has {} snapshot(s); the ORF curve needs {}", samples.size(),
                                                    cases::kMinFluidisationSnapshots)};
  }
  std::vector<double> times;
  std::vector<double> orf;
  double fragment = 0.0;
  for (const PackingSample& s : samples) {
    times.push_back(s.time);
    orf.push_back(s.orf);
    fragment = std::max(fragment, s.largest_departed_fragment);
  }
  if (name == "largest_departed_fragment") return CohesionMetric{fragment, ""};
  if (name == "orf_largest_drop") return CohesionMetric{largest_drop(orf), ""};
  const double level = scene.compare.packing->orf_threshold;
  if (const auto t = first_time_at_or_below(times, orf, level)) return CohesionMetric{*t, ""};
  return CohesionMetric{std::nullopt,
                        fmt::format("the ORF stayed above {} (compare.packing.orf_threshold) until the end, t = {} s, "
                                    "where it is {:.4g}: the bed did not fluidise",
                                    level, times.back(), orf.back())};
}

}  // namespace

std::optional<CohesionMetric> packing_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::RunResult& run) {
  if (!cases::is_packing_metric(name)) return std::nullopt;
  if (!scene.compare.packing) return CohesionMetric{std::nullopt, "the case has no [compare.packing] region"};
  if (run.snapshots.empty()) {
    return CohesionMetric{std::nullopt, "the run has no snapshot (output.snapshot_times)"};
  }
  if (cases::is_fluidisation_metric(name)) return fluidisation_metric(name, scene, run);
  const bool at_start = scene.compare.packing->at_start;
  const cases::Snapshot& last = at_start ? run.snapshots.front() : run.snapshots.back();
  if (last.position.size() != scene.particles.size()) {
    return CohesionMetric{std::nullopt, fmt::format("the {} snapshot holds {} spheres, the scene {}",
                                                    at_start ? "first" : "last", last.position.size(),
                                                    scene.particles.size())};
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
      return CohesionMetric{packing_fraction(centres, radii, interior(region, cases::interior_margin(scene, spec))), ""};
    }
    if (name == "orf") return CohesionMetric{obscured_fraction(centres, radii, region, spec.orf_ny, spec.orf_nz), ""};
    if (name == "coordination_number") return CohesionMetric{coordination_number(centres, radii, region), ""};
    return CohesionMetric{share_inside(centres, region), ""};  // dose_remaining
  } catch (const std::invalid_argument& e) {
    return CohesionMetric{std::nullopt, e.what()};
  }
}

}  // namespace comparison
