// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `lammps_mass_velocity`: η = damping_rate · m*, LAMMPS `damping
/// mass_velocity` (and gran/hooke/history's γ_n). m* = the mobile mass against fixed bodies and
/// walls, as LAMMPS with `fix freeze`.
struct LammpsMassVelocityDamping {
  static constexpr std::string_view kKeyword = "lammps_mass_velocity";
  static constexpr std::string_view kDescription =
      "mass-scaled dashpot η = damping_rate · m* (LAMMPS `damping mass_velocity`)";
  static constexpr std::array<std::string_view, 1> kProperties{"damping_rate"};
  static constexpr std::string_view kLammps =
      "`damping mass_velocity` with the pair_coeff damping value η/m* [1/s] (gran/hooke/history: "
      "γ_n); fixed partners need `fix freeze` so that LAMMPS takes m* = m";
  static constexpr std::string_view kYade =
      "none: YADE dashpots are given as c_n or β_n, not as a rate; pass c_n = rate · m* per pair";
  static constexpr std::string_view kLiggghts =
      "not mapped yet: hooke/stiffness without absolute_damping takes γ_n = m* gamman (on linear)";

  double rate;  ///< η/m* [1/s]

  /// Sub-model for one material pair.
  static LammpsMassVelocityDamping from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::damping_rate, "damping_rate",
                              "damping = 'lammps_mass_velocity'")};
  }
  /// Dashpot coefficient η [kg/s].
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse&) const noexcept {
    return rate * g.reduced_mass;
  }
};

}  // namespace dem
