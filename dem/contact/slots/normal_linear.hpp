// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/linear_spring.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Normal sub-model `linear`: Hooke repulsion F = k_e δ while δ > 0 (thesis eq 3.10, elastic part).
struct LinearNormal {
  static constexpr std::string_view kKeyword = "linear";
  static constexpr std::string_view kDescription = "linear spring F = k_e δ (eq 3.10)";
  static constexpr std::array<std::string_view, 1> kProperties{"normal_stiffness"};
  static constexpr std::string_view kLammps =
      "pair granular `hooke k_e η` with an explicit pair_coeff per type pair";
  static constexpr std::string_view kYade =
      "FrictMat + Ip2_FrictMat_FrictMat_FrictPhys(kn = k_e per material pair via MatchMaker) + "
      "Law2_ScGeom_FrictPhys_CundallStrack (exact)";
  static constexpr std::string_view kLiggghts =
      "`model hooke/stiffness` with kn = k_e per type pair (not `model hooke`, whose k_n comes from a characteristic velocity)";

  double stiffness;  ///< k_e [N/m]

  /// Sub-model for one material pair.
  static LinearNormal from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::normal_stiffness, "normal_stiffness",
                              "normal = 'linear'")};
  }
  /// Elastic response; zero out of contact. Exactly touching (δ = 0): no force, but the
  /// stiffness k_e, for a dashpot that acts there (ContactPolicies::contact_at_zero_overlap).
  [[nodiscard]] NormalResponse evaluate(const ContactInput& in, ContactHistory&) const noexcept {
    if (in.g.overlap == 0.0) return {0.0, stiffness, 0.0, false};
    if (in.g.overlap < 0.0) return {};
    return {laws::linear_spring_force(stiffness, in.g.overlap), stiffness,
            laws::linear_spring_energy(stiffness, in.g.overlap), true};
  }
  /// Acts only while the bodies overlap.
  [[nodiscard]] double range(const PairExtent& e) const noexcept { return e.contact_distance; }
  /// Constant stiffness.
  [[nodiscard]] double collision_stiffness(const CollisionScale&) const noexcept {
    return stiffness;
  }
};

}  // namespace dem
