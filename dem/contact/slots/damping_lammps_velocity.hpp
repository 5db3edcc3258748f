// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `lammps_velocity`: constant η = damping_coefficient, LAMMPS `damping
/// velocity` (F = −η u_n, not clipped unless clamp_tensile, like LAMMPS without limit_damping).
struct LammpsVelocityDamping {
  static constexpr std::string_view kKeyword = "lammps_velocity";
  static constexpr std::string_view kDescription =
      "constant dashpot η = damping_coefficient (LAMMPS `damping velocity`)";
  static constexpr std::array<std::string_view, 1> kProperties{"damping_coefficient"};
  static constexpr std::string_view kLammps =
      "`damping velocity` with the pair_coeff damping value η [kg/s]; `limit_damping` only with "
      "clamp_tensile = true";
  static constexpr std::string_view kYade =
      "linear normal only: ViscElMat(kn = 2k_e, cn = 2η, ks, cs) + Law2_ScGeom_ViscElPhys_Basic "
      "(clips F_n ≥ 0: clamp_tensile = true); none for hertz";
  static constexpr std::string_view kLiggghts =
      "on linear: `hooke/stiffness absolute_damping on`, gamman_abs = η per type pair; none on hertz";

  double damping;  ///< η [kg/s]

  /// Sub-model for one material pair.
  static LammpsVelocityDamping from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::damping_coefficient, "damping_coefficient",
                              "damping = 'lammps_velocity'")};
  }
  /// Dashpot coefficient η [kg/s].
  [[nodiscard]] double coefficient(const ContactGeometry&, const NormalResponse&) const noexcept {
    return damping;
  }
};

}  // namespace dem
