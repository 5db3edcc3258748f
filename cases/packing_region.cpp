// SPDX-License-Identifier: MIT
#include "cases/packing_region.hpp"

#include <algorithm>

namespace cases {

bool is_packing_metric(std::string_view metric) noexcept {
  return std::find(kPackingMetrics.begin(), kPackingMetrics.end(), metric) != kPackingMetrics.end();
}

bool is_fluidisation_metric(std::string_view metric) noexcept {
  return std::find(kFluidisationMetrics.begin(), kFluidisationMetrics.end(), metric) != kFluidisationMetrics.end();
}

double interior_margin(const Scene& scene, const PackingSpec& packing) noexcept {
  if (packing.interior_margin) return *packing.interior_margin;
  double sum = 0.0;
  std::size_t n = 0;
  for (const bool mobile_only : {true, false}) {
    for (const ParticleSpec& p : scene.particles) {
      if (mobile_only && p.fixed) continue;
      sum += 2.0 * p.radius;
      ++n;
    }
    if (n > 0) break;
  }
  return n > 0 ? 2.0 * sum / static_cast<double>(n) : 0.0;
}

}  // namespace cases
