// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>

namespace dem::laws {

/// Force, tangent stiffness and recoverable energy of the Walton–Braun hysteretic spring.
struct HystereticResponse {
  double force = 0.0;      ///< [N], repulsive positive, never negative
  double stiffness = 0.0;  ///< dF/dδ on the branch in use [N/m]
  double energy = 0.0;     ///< elastic energy recoverable on unloading [J]
};

/// Unloading stiffness k_u = k_l / ε² [N/m] that gives restitution ε = √(k_l/k_u) (eq 3.21).
[[nodiscard]] constexpr double walton_braun_unloading_stiffness(double loading_stiffness,
                                                                double restitution) noexcept {
  return loading_stiffness / (restitution * restitution);
}

/// Plastic work of a Walton–Braun contact whose largest overlap deepens from `from` to `to` [J]:
/// ½ k_l (1 − k_l/k_u)(to² − from²), the loading work ½ k_l δ_max² less the recoverable
/// ½ (k_l²/k_u) δ_max² (thesis eq 3.20–3.21); zero when δ_max does not deepen.
[[nodiscard]] constexpr double walton_braun_plastic_work(double loading_stiffness, double unloading_stiffness,
                                                         double from, double to) noexcept {
  return 0.5 * loading_stiffness * (1.0 - loading_stiffness / unloading_stiffness) * (to * to - from * from);
}

/// Walton–Braun linear hysteretic law (thesis eq 3.20–3.21, made continuous at δ_max by δ_0).
/// Loading (δ ≥ δ_max, the largest overlap so far, passed in *including* the current δ):
/// F = k_l δ. Unloading and reloading (δ < δ_max): F = k_u (δ − δ_0), δ_0 = δ_max (1 − k_l/k_u),
/// clipped at F ≥ 0, so F is continuous at δ_max; reloading retraces the unloading line until
/// δ_max is exceeded, then loading resumes on k_l δ. Stiffnesses k_l ≤ k_u [N/m], overlaps [m].
/// The energy is what the spring can give back: ½ k_u (δ − δ_0)² on the unloading line and,
/// while loading, the same expression with δ_max = δ, i.e. ½ (k_l²/k_u) δ²; the rest of the
/// loading work, ½ k_l δ_max² (1 − k_l/k_u) per cycle, is dissipated (plastic). Zero for δ ≤ 0.
[[nodiscard]] inline HystereticResponse walton_braun(double loading_stiffness,
                                                     double unloading_stiffness, double overlap,
                                                     double max_overlap) noexcept {
  if (overlap <= 0.0) return {};
  const double peak = std::max(max_overlap, overlap);
  const double ratio = loading_stiffness / unloading_stiffness;
  if (overlap >= peak) {
    return {loading_stiffness * overlap, loading_stiffness,
            0.5 * loading_stiffness * ratio * overlap * overlap};
  }
  const double unloaded = peak * (1.0 - ratio);  // δ_0, where the unloading line reaches F = 0
  const double stretch = overlap - unloaded;
  if (stretch <= 0.0) return {};
  return {unloading_stiffness * stretch, unloading_stiffness,
          0.5 * unloading_stiffness * stretch * stretch};
}

}  // namespace dem::laws
