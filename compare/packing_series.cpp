// SPDX-License-Identifier: MIT
#include "compare/packing_series.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "cases/core_vector.hpp"
#include "compare/metrics_breakup.hpp"
#include "compare/packing_geometry.hpp"
#include "dem/particles/particles.hpp"

namespace comparison {
namespace {

/// The largest fragment of the spheres (centres, radii) outside `region` as a share of `dose`, the
/// volume of them all: fragments are the connected components of the pairs closer than
/// kFragmentGap times the sum of their radii.
double largest_departed_fragment(std::span<const cases::Vector3> centres, std::span<const double> radii,
                                 const Box& region, double dose) {
  std::vector<breakup::SnapshotSphere> out;
  breakup::BondRule rule;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (region.contains(centres[i])) continue;
    out.push_back({cases::core_vec(centres[i]), radii[i]});
    rule.half_reach.push_back(kFragmentGap * radii[i]);
  }
  if (out.empty() || !(dose > 0.0)) return 0.0;
  return breakup::fragments(out, rule).volume.front() / dose;
}

}  // namespace

std::variant<std::vector<PackingSample>, std::string> packing_series(const cases::Scene& scene,
                                                                     const cases::RunResult& run) {
  if (!scene.compare.packing) return std::string("the case has no [compare.packing] region");
  const cases::PackingSpec& spec = *scene.compare.packing;
  const Box region{spec.min, spec.max};
  std::vector<double> radii;
  double dose = 0.0;
  for (const cases::ParticleSpec& p : scene.particles) {
    if (p.fixed) continue;
    radii.push_back(p.radius);
    dose += dem::sphere_volume(p.radius);
  }
  std::vector<PackingSample> out;
  std::vector<cases::Vector3> centres;
  for (const cases::Snapshot& snap : run.snapshots) {
    if (snap.position.size() != scene.particles.size()) {
      return fmt::format("the snapshot at t = {} s holds {} spheres, the scene {}", snap.time, snap.position.size(),
                         scene.particles.size());
    }
    centres.clear();
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
      if (!scene.particles[i].fixed) centres.push_back(snap.position[i]);
    }
    try {
      out.push_back({snap.time, obscured_fraction(centres, radii, region, spec.orf_ny, spec.orf_nz),
                     share_inside(centres, region), largest_departed_fragment(centres, radii, region, dose)});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
  }
  return out;
}

std::optional<double> first_time_at_or_below(std::span<const double> times, std::span<const double> values,
                                             double level) {
  if (times.size() != values.size()) throw std::invalid_argument("first_time_at_or_below: sizes differ");
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!(values[k] <= level)) continue;
    if (k == 0) return times[0];
    const double above = values[k - 1];
    if (!std::isfinite(above)) return times[k];
    const double s = (above - level) / (above - values[k]);  // above > level >= values[k]
    return times[k - 1] + s * (times[k] - times[k - 1]);
  }
  return std::nullopt;
}

double largest_drop(std::span<const double> values) noexcept {
  double drop = 0.0;
  for (std::size_t k = 1; k < values.size(); ++k) drop = std::max(drop, values[k - 1] - values[k]);
  return drop;
}

}  // namespace comparison
