// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/slots/responses.hpp"
#include "dem/materials/material_properties.hpp"

namespace dem {

/// Shared metadata of the `none` sub-model of every optional slot.
struct NoneModelInfo {
  static constexpr std::string_view kKeyword = "none";
  static constexpr std::array<std::string_view, 0> kProperties{};
  static constexpr std::string_view kLammps = "omitted";
  static constexpr std::string_view kYade = "omitted";
  static constexpr std::string_view kLiggghts =
      "omitted";
};

/// Damping sub-model `none`: purely elastic normal contact.
struct NoDamping : NoneModelInfo {
  static constexpr std::string_view kDescription = "no normal damping";
  static constexpr std::string_view kLammps =
      "`damping velocity` with η = 0 (never left to LAMMPS' default, viscoelastic)";
  static constexpr std::string_view kYade =
      "no dashpot: FrictMat + Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator(damping=0)";
  static constexpr std::string_view kLiggghts =
      "no dashpot: coefficientRestitution 1 (model hertz) or gamman_abs 0 (hooke/stiffness)";
  static NoDamping from_pair(const PairProperties&) { return {}; }
  [[nodiscard]] double coefficient(const ContactGeometry&, const NormalResponse&) const noexcept {
    return 0.0;
  }
};

/// Tangential sub-model `none`: frictionless contact.
struct NoTangential : NoneModelInfo {
  static constexpr std::string_view kDescription = "frictionless";
  static constexpr std::string_view kLammps = "tangential linear_nohistory 0 0";
  static constexpr std::string_view kYade = "ks = 0 per material pair (MatchMaker), frictionAngle = 0";
  static constexpr std::string_view kLiggghts =
      "`tangential no_history` with `tangential_damping off`: no tangential force";
  static NoTangential from_pair(const PairProperties&) { return {}; }
  [[nodiscard]] TangentialResponse evaluate(const ContactInput&, const TangentialInput&,
                                            ContactHistory&) const noexcept {
    return {};
  }
};

/// Cohesion sub-model `none`: no attraction; pairs interact only through the normal law.
struct NoCohesion : NoneModelInfo {
  static constexpr std::string_view kDescription = "no cohesion";
  static NoCohesion from_pair(const PairProperties&) { return {}; }
  [[nodiscard]] CohesionResponse evaluate(const ContactInput&, const NormalResponse&,
                                          ContactHistory&) const noexcept {
    return {};
  }
  [[nodiscard]] double range(const PairExtent&) const noexcept { return 0.0; }
};

/// Rolling sub-model `none`: no rolling resistance.
struct NoRolling : NoneModelInfo {
  static constexpr std::string_view kDescription = "no rolling resistance";
  static NoRolling from_pair(const PairProperties&) { return {}; }
  [[nodiscard]] RollingResponse evaluate(const ContactInput&, const RollingInput&, ContactHistory&) const noexcept {
    return {};
  }
};

}  // namespace dem
