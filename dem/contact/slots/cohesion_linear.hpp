// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/linear_cohesion.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Cohesion sub-model `linear`: F = −k_c δ̂ while the effect spheres overlap (δ̂ > 0), added to
/// the normal force whether or not the bodies touch (thesis eq 3.33, appendix E eq E.5). The
/// effect radius r̂ = λ r comes from the particles (`effect_radius`, or the material's
/// `interaction_ratio`). Cohesion alone is not a contact: no damping, no friction.
struct LinearCohesion {
  static constexpr std::string_view kKeyword = "linear";
  static constexpr std::string_view kDescription =
      "linear cohesion F = −k_c δ̂ over the effect overlap (eq 3.33)";
  static constexpr std::array<std::string_view, 1> kProperties{"cohesive_stiffness"};
  static constexpr std::string_view kLammps =
      "no granular style: pair_style hybrid/overlay granular table with F = −k_c (r̂_p + r̂_q − r) "
      "per type pair (exact for discrete size classes only)";
  static constexpr std::string_view kYade =
      "not built in: a per-step Python force between InteractionLoop and NewtonIntegrator";
  static constexpr std::string_view kLiggghts =
      "none: sjkr/sjkr2 pull with k·A and only while the bodies overlap (the core's linear cohesion acts over the effect radii)";

  double stiffness;  ///< k_c [N/m]

  /// Sub-model for one material pair.
  static LinearCohesion from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::cohesive_stiffness, "cohesive_stiffness",
                              "cohesion = 'linear'")};
  }
  /// Attraction while δ̂ > 0; nothing otherwise.
  [[nodiscard]] CohesionResponse evaluate(const ContactInput& in, const NormalResponse&,
                                          ContactHistory&) const noexcept {
    const double d = in.g.effect_overlap;
    if (!(d > 0.0)) return {};
    return {laws::linear_cohesion_force(stiffness, d), laws::linear_cohesion_energy(stiffness, d),
            true, false, 0.0};
  }
  /// Acts while the effect spheres overlap.
  [[nodiscard]] double range(const PairExtent& e) const noexcept { return e.effect_distance; }
};

}  // namespace dem
