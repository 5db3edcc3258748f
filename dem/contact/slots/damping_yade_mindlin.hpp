// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `yade_mindlin`: YADE Hertz–Mindlin's c_n = 2 β_n √(m* k_n) with the
/// normal law's tangent stiffness k_n (= 1.5 k_no √δ for Hertz) and β_n(ε) from Thornton et al.
/// 2013 eqs B6–B7 (laws::thornton_damping_ratio). The fit is for the clipped force: with
/// clamp_tensile = true and hertz the rebound is ε within about 1e-4.
struct YadeMindlinDamping {
  static constexpr std::string_view kKeyword = "yade_mindlin";
  static constexpr std::string_view kDescription =
      "YADE Hertz–Mindlin c_n = 2 β_n(ε) √(m* k_n), β_n from Thornton 2013 (B6–B7), k_n the "
      "tangent stiffness (clip with clamp_tensile to match YADE)";
  static constexpr std::array<std::string_view, 1> kProperties{"restitution"};
  static constexpr std::string_view kLammps =
      "none: LAMMPS `damping tsuji` has the same δ^{1/4} form but takes its own α_L(e); pass the "
      "e_in with α_L(e_in) = 2√1.5 β_n and `limit_damping` (not verified)";
  static constexpr std::string_view kYade =
      "FrictMat + Ip2_FrictMat_FrictMat_MindlinPhys(en = ε) + Law2_ScGeom_MindlinPhys_Mindlin "
      "(F_n clipped at ≥ 0; m̄ = the dynamic body's mass when the partner is fixed, as ours)";
  static constexpr std::string_view kLiggghts =
      "none: YADE's own law";

  double restitution;    ///< ε passed to YADE as en
  double damping_ratio;  ///< β_n(ε) [-]

  /// Sub-model for one material pair.
  static YadeMindlinDamping from_pair(const PairProperties& pair) {
    const double e = required_property(pair, &PairProperties::restitution, "restitution",
                                       "damping = 'yade_mindlin'");
    return {e, laws::thornton_damping_ratio(e)};
  }
  /// Dashpot coefficient c_n [kg/s] for this contact.
  [[nodiscard]] double coefficient(const ContactGeometry& g,
                                   const NormalResponse& normal) const noexcept {
    return laws::yade_mindlin_damping_coefficient(damping_ratio, g.reduced_mass, normal.stiffness);
  }
};

}  // namespace dem
