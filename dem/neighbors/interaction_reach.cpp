// SPDX-License-Identifier: MIT
#include "dem/neighbors/interaction_reach.hpp"

#include <algorithm>
#include <vector>

namespace dem {

ScalarArray half_reaches(const ParticleProperties& props, const PairTable& table) {
  std::vector<std::uint8_t> present(table.material_count(), 0);
  for (const std::uint32_t m : props.material) present[m] = 1;
  ScalarArray h(static_cast<Eigen::Index>(props.size()));
  for (std::size_t i = 0; i < props.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const double r = props.radius[k];
    const double r_hat = props.effect_radius[k];
    const PairExtent self{2.0 * r, 2.0 * r_hat, 0.5 * r};
    double reach = 2.0 * r;  // two copies of i touch at 2r whatever the law
    for (std::size_t b = 0; b < present.size(); ++b) {
      if (present[b] == 0) continue;
      reach = std::max(reach, interaction_range(table.law(props.material[i], b), self));
    }
    h[k] = 0.5 * reach;
  }
  return h;
}

double wall_reach(const PairLaw& law, double radius, double effect_radius) noexcept {
  return interaction_range(law, {radius, effect_radius, radius});
}

}  // namespace dem
