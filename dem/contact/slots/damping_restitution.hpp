// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `restitution`: dashpot −η (u_c·n) with η = β(ε) √(m* k) (thesis eq
/// 3.10–3.11), k the normal sub-model's stiffness at the current overlap. For the linear spring
/// the rebound has restitution ε exactly; for Hertz it uses the tangent stiffness.
struct RestitutionDamping {
  static constexpr std::string_view kKeyword = "restitution";
  static constexpr std::string_view kDescription =
      "dashpot η = −2 ln ε √(m* k / (π² + ln² ε)) (eq 3.11)";
  static constexpr std::array<std::string_view, 1> kProperties{"restitution"};
  static constexpr std::string_view kLammps =
      "`damping velocity` with η computed per type pair (no restitution damping in this build)";
  static constexpr std::string_view kYade =
      "FrictViscoMat(betan = β/2) + Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn, kRatio=0) + "
      "Law2_ScGeom_FrictViscoPhys_CundallStrackVisco: η = 2 betan √(m* k) exact, unclamped, but the "
      "dashpot sees α·u_n with α = (r_p + r_q)/(r_p + r_q − δ)";
  static constexpr std::string_view kLiggghts =
      "on linear: `hooke/stiffness absolute_damping on`, gamman_abs = β(ε) √(m* k_e) per type pair; none on hertz (√(6/5) times LIGGGHTS' Hertz dashpot: use tsuji)";

  double restitution;  ///< ε ∈ (0, 1]
  double factor;       ///< β(ε) = η / √(m* k)

  /// Sub-model for one material pair.
  static RestitutionDamping from_pair(const PairProperties& pair) {
    const double e = required_property(pair, &PairProperties::restitution, "restitution",
                                       "damping = 'restitution'");
    return {e, laws::restitution_damping_factor(e)};
  }
  /// Dashpot coefficient η [kg/s] for this contact.
  [[nodiscard]] double coefficient(const ContactGeometry& g,
                                   const NormalResponse& normal) const noexcept {
    return factor * std::sqrt(g.reduced_mass * normal.stiffness);
  }
};

}  // namespace dem
