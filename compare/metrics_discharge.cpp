// SPDX-License-Identifier: MIT
#include "compare/metrics_discharge.hpp"

#include <vector>

#include <fmt/format.h>

#include "cases/discharge_metrics.hpp"
#include "dem/particles/particles.hpp"

namespace comparison {

double mass_past(std::span<const cases::Vector3> centres, std::span<const double> masses,
                 const cases::Vector3& point, const cases::Vector3& direction) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    double beyond = 0.0;
    for (std::size_t k = 0; k < 3; ++k) beyond += (centres[i][k] - point[k]) * direction[k];
    if (beyond > 0.0) sum += masses[i];
  }
  return sum;
}

std::optional<support::LineFit> fit_flow_rate(std::span<const double> times, std::span<const double> mass,
                                              double total, double from, double to, std::size_t min_points) {
  std::vector<double> t;
  std::vector<double> m;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double share = mass[k] / total;
    if (share < from || share > to) continue;
    t.push_back(times[k]);
    m.push_back(mass[k]);
  }
  if (t.size() < min_points) return std::nullopt;
  return support::least_squares_line(t, m);
}

std::optional<CohesionMetric> discharge_metric(const std::string& name, const cases::Scene& scene,
                                               const cases::RunResult& run) {
  if (!cases::is_discharge_metric(name)) return std::nullopt;
  if (!scene.compare.discharge) return CohesionMetric{std::nullopt, "the case has no [compare.discharge] outlet"};
  const cases::DischargeSpec& spec = *scene.compare.discharge;
  std::vector<double> masses;
  std::vector<std::size_t> mobile;
  double total = 0.0;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    const double m = dem::sphere_mass(scene.materials.at(p.material).density, p.radius);
    masses.push_back(m);
    mobile.push_back(i);
    total += m;
  }
  if (!(total > 0.0)) return CohesionMetric{std::nullopt, "the scene has no mobile sphere"};
  std::vector<double> times;
  std::vector<double> past;
  std::vector<cases::Vector3> centres(mobile.size());
  for (const cases::Snapshot& snap : run.snapshots) {
    if (snap.position.size() != scene.particles.size()) {
      return CohesionMetric{std::nullopt, fmt::format("the snapshot at t = {} s holds {} spheres, the scene {}", snap.time,
                                                      snap.position.size(), scene.particles.size())};
    }
    for (std::size_t k = 0; k < mobile.size(); ++k) centres[k] = snap.position[mobile[k]];
    times.push_back(snap.time);
    past.push_back(mass_past(centres, masses, spec.point, spec.direction));
  }
  if (times.empty()) return CohesionMetric{std::nullopt, "the run has no snapshot (output.snapshot_every)"};
  if (name == "discharged_fraction") return CohesionMetric{past.back() / total, ""};
  const std::optional<support::LineFit> fit =
      fit_flow_rate(times, past, total, spec.fit_from, spec.fit_to, cases::kMinDischargeSnapshots);
  if (!fit) {
    return CohesionMetric{
        std::nullopt,
        fmt::format("fewer than {} snapshots have between {} and {} of the mobile mass past the outlet (at the end: {:.3g}); "
                    "run longer or take snapshots more often",
                    cases::kMinDischargeSnapshots, spec.fit_from, spec.fit_to, past.back() / total)};
  }
  return CohesionMetric{fit->slope, ""};
}

}  // namespace comparison
