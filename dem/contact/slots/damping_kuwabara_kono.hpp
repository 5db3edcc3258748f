// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `kuwabara_kono`: η = 2 E' √(R* δ) (thesis eq 3.14; Kuwabara & Kono 1987,
/// Brilliantov et al. 1996), with the pair's dissipative modulus E' [Pa·s] (`viscous_modulus`).
struct KuwabaraKonoDamping {
  static constexpr std::string_view kKeyword = "kuwabara_kono";
  static constexpr std::string_view kDescription =
      "viscoelastic dashpot η = 2 E' √(R* δ) (eq 3.14); E' [Pa·s] is viscous_modulus";
  static constexpr std::array<std::string_view, 1> kProperties{"viscous_modulus"};
  static constexpr std::string_view kLammps =
      "`damping viscoelastic` with η₀ = 2 E'/m* per type pair (LAMMPS: η = η₀ a m*, the same "
      "a-proportional form; one m* per type pair, so one type per size class)";
  static constexpr std::string_view kYade =
      "none: YADE's Hertz–Mindlin dashpot grows as δ^{1/4}, not as √δ";
  static constexpr std::string_view kLiggghts =
      "not mapped yet: `hertz/stiffness` with gamman = 2 E'/m* per type pair gives 2 E' √(R* δ) (one m* per type pair)";

  double viscous_modulus;  ///< E' [Pa·s]

  /// Sub-model for one material pair.
  static KuwabaraKonoDamping from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::viscous_modulus, "viscous_modulus",
                              "damping = 'kuwabara_kono'")};
  }
  /// Dashpot coefficient η [kg/s] for this contact (0 when δ ≤ 0).
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse&) const noexcept {
    return laws::kuwabara_kono_damping_coefficient(viscous_modulus, g.reduced_radius, g.overlap);
  }
};

}  // namespace dem
