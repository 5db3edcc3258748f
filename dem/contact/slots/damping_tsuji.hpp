// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `tsuji`: η = α(ε) √(m* k_n) δ^{1/4} (Tsuji et al. 1992), evaluated as
/// α √(m* F_el/δ) with the normal law's secant stiffness (= k_n δ^{1/2} for Hertz). α(ε) =
/// −√5 ln ε/√(π² + ln² ε) makes the unclipped Hertz rebound have restitution ε exactly at any
/// impact speed (laws::tsuji_factor). With another normal law it is only a δ-dependent dashpot.
struct TsujiDamping {
  static constexpr std::string_view kKeyword = "tsuji";
  static constexpr std::string_view kDescription =
      "Hertz dashpot η = α(ε) √(m* k_n) δ^{1/4}, α = −√5 ln ε/√(π² + ln² ε): restitution ε "
      "exactly with hertz (unclipped)";
  static constexpr std::array<std::string_view, 1> kProperties{"restitution"};
  static constexpr std::string_view kLammps =
      "`damping tsuji` with the e_in solving LAMMPS' polynomial α_L(e_in) = α(ε) (e_in = "
      "0.3666514 for ε = 0.5, 0.8621222 for ε = 0.9; LAMMPS 2021 measured 0.49996 and 0.90000), "
      "no limit_damping";
  static constexpr std::string_view kYade =
      "with clamp_tensile = true: Ip2_FrictMat_FrictMat_MindlinPhys(betan = α/(2√1.5)), the same "
      "dashpot, exact (rebound 0.5503 for ε = 0.5); unclipped it has no counterpart, since "
      "Law2_ScGeom_MindlinPhys_Mindlin clips F_n ≥ 0";
  static constexpr std::string_view kLiggghts =
      "`model hertz` with `coefficientRestitution` ε: γ_n = −2 √(5/6) β √(2 Y* √(R* δ) m*), β = ln ε/√(ln² ε + π²), is this dashpot";

  double restitution;  ///< ε ∈ (0, 1]
  double factor;       ///< α(ε) [-]

  /// Sub-model for one material pair.
  static TsujiDamping from_pair(const PairProperties& pair) {
    const double e =
        required_property(pair, &PairProperties::restitution, "restitution", "damping = 'tsuji'");
    return {e, laws::tsuji_factor(e)};
  }
  /// Dashpot coefficient η [kg/s] for this contact.
  [[nodiscard]] double coefficient(const ContactGeometry& g,
                                   const NormalResponse& normal) const noexcept {
    return laws::tsuji_damping_coefficient(
        factor, g.reduced_mass, laws::secant_stiffness(normal.force, g.overlap, normal.stiffness));
  }
};

}  // namespace dem
