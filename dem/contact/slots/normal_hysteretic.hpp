// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

#include "dem/contact/laws/walton_braun.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Normal sub-model `hysteretic`: Walton–Braun loading k_l δ / unloading k_u (δ − δ_0) springs
/// (thesis eq 3.20–3.21; docs/physics-normal.md), k_u = k_l/ε² so that the rebound has restitution
/// ε. δ_max is the contact history's largest overlap so far (committed) together with the current
/// one; reloading retraces the unloading line until δ_max is exceeded.
struct HystereticNormal {
  static constexpr std::string_view kKeyword = "hysteretic";
  static constexpr std::string_view kDescription =
      "Walton–Braun: loading k_l δ, unloading k_u (δ − δ_0), δ_0 = δ_max (1 − k_l/k_u), F ≥ 0, "
      "k_u = k_l/ε² (eq 3.20–3.21)";
  static constexpr std::array<std::string_view, 2> kProperties{"normal_stiffness", "restitution"};
  static constexpr std::string_view kLammps =
      "none: pair granular in this build has no hysteretic normal model";
  static constexpr std::string_view kYade =
      "no exact counterpart: LudingMat(k1 = k_l, kp, kc = 0, G0 = 0) + Ip2_LudingMat_LudingMat_"
      "LudingPhys + Law2_ScGeom_LudingPhys_Basic has the same branches and reloading rule but "
      "k2 = k1 + (kp − k1) δ_max/δ_Pmax grows with δ_max (equal to k_u only for one δ_max), and "
      "against walls it is purely elastic (kp): use large fixed spheres as walls";
  static constexpr std::string_view kLiggghts =
      "not mapped yet: `hooke/hysteresis` is LIGGGHTS' Walton–Braun law";

  double loading_stiffness;    ///< k_l [N/m]
  double unloading_stiffness;  ///< k_u = k_l / ε² [N/m]

  /// Sub-model for one material pair.
  static HystereticNormal from_pair(const PairProperties& pair) {
    const double k = required_property(pair, &PairProperties::normal_stiffness,
                                       "normal_stiffness", "normal = 'hysteretic'");
    const double e = required_property(pair, &PairProperties::restitution, "restitution",
                                       "normal = 'hysteretic'");
    return {k, laws::walton_braun_unloading_stiffness(k, e)};
  }
  /// Hysteretic response; zero out of contact. The stored energy is the recoverable part.
  [[nodiscard]] NormalResponse evaluate(const ContactInput& in, ContactHistory&) const noexcept {
    const double delta = in.g.overlap;
    if (delta <= 0.0) return {};
    const double reached = std::max(in.committed.max_overlap, delta);
    const laws::HystereticResponse r = laws::walton_braun(loading_stiffness, unloading_stiffness, delta, reached);
    return {r.force, r.stiffness, r.energy, true,
            laws::walton_braun_plastic_work(loading_stiffness, unloading_stiffness, in.committed.max_overlap, reached)};
  }
  /// Acts only while the bodies overlap.
  [[nodiscard]] double range(const PairExtent& e) const noexcept { return e.contact_distance; }
  /// The unloading (stiffer) spring k_u, which sets the shortest time scale.
  [[nodiscard]] double collision_stiffness(const CollisionScale&) const noexcept {
    return unloading_stiffness;
  }
};

}  // namespace dem
