// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `yade_viscel`: the constant c_n of YADE's ViscElPhys as the verified
/// "kncn" deck passes it, c_n = −2 ln ε √(m* k_e/(π² + ln² ε)) with k_e = normal_stiffness (eq
/// 3.11 on the linear spring, whatever the normal model's tangent stiffness). YADE's law clips
/// F_n ≥ 0, so matched runs need clamp_tensile = true; the rebound is then the clipped value
/// (laws::linear_clipped_restitution, 0.5503 for ε = 0.5), not ε.
struct YadeViscElDamping {
  static constexpr std::string_view kKeyword = "yade_viscel";
  static constexpr std::string_view kDescription =
      "YADE ViscElPhys constant c_n = −2 ln ε √(m* k_e/(π² + ln² ε)), k_e = normal_stiffness "
      "(clip with clamp_tensile to match YADE)";
  static constexpr std::array<std::string_view, 2> kProperties{"normal_stiffness", "restitution"};
  static constexpr std::string_view kLammps =
      "`damping velocity` with η = c_n per type pair, plus `limit_damping` when clamp_tensile";
  static constexpr std::string_view kYade =
      "ViscElMat(kn = 2k_e, cn = 2c_n, ks, cs) per material (contact values are series "
      "k1k2/(k1+k2)) + Ip2_ViscElMat_ViscElMat_ViscElPhys + Law2_ScGeom_ViscElPhys_Basic; "
      "F_n clipped at ≥ 0. Not ViscElMat(tc, en): its m_red counts a fixed partner's own mass "
      "(m/2 against walls), nor ViscElMat(young, en) (c_n solved to 1 % only)";
  static constexpr std::string_view kLiggghts =
      "none: YADE's own law";

  double stiffness;    ///< k_e [N/m] the coefficient is built from
  double restitution;  ///< ε ∈ (0, 1]
  double factor;       ///< β(ε) = c_n/√(m* k_e)

  /// Sub-model for one material pair.
  static YadeViscElDamping from_pair(const PairProperties& pair) {
    constexpr std::string_view who = "damping = 'yade_viscel'";
    const double k =
        required_property(pair, &PairProperties::normal_stiffness, "normal_stiffness", who);
    const double e = required_property(pair, &PairProperties::restitution, "restitution", who);
    return {k, e, laws::restitution_damping_factor(e)};
  }
  /// Dashpot coefficient c_n [kg/s] for this pair's reduced mass.
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse&) const noexcept {
    return factor * std::sqrt(g.reduced_mass * stiffness);
  }
};

}  // namespace dem
