// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace dem {

/// What the Coulomb limit μ·basis of the tangential force is based on (STYLE.md table).
enum class FrictionLimit {
  total,            ///< |F_n| of the whole normal force (default; thesis eq 3.23)
  elastic,          ///< |F_elastic| (YADE)
  elastic_damping,  ///< |F_elastic + F_damping| (LAMMPS, LIGGGHTS)
  jkr_shifted,      ///< |F_n + 2 F_pulloff| (Thornton; LAMMPS JKR/DMT)
};

/// Where a JKR contact breaks on separation (PHYSICS.md §5).
enum class JkrRupture {
  displacement,  ///< at δ_c = −¾ (π² Γ² R*/E*²)^{1/3}, force −5/9 F_po (default)
  load,          ///< at the load-controlled pull-off point, the maximum tension (as LAMMPS)
};

/// Lever arm of the tangential force about a sphere's centre in a sphere–wall contact.
enum class WallLeverArm {
  contact_point,  ///< r − δ/2, as for sphere pairs (default; common-normal method)
  radius,         ///< r, as LAMMPS fix wall/gran
};

/// Keywords of the sub-model chosen for each slot and the named policies, as a case file gives
/// them ([model] table).
struct ModelChoice {
  std::string normal = "linear";
  std::string damping = "none";
  std::string tangential = "none";
  std::string cohesion = "none";
  std::string rolling = "none";
  bool clamp_tensile = false;                      ///< clamp elastic + damping force at ≥ 0
  FrictionLimit friction_limit = FrictionLimit::total;
  JkrRupture jkr_rupture = JkrRupture::displacement;
  WallLeverArm wall_lever_arm = WallLeverArm::contact_point;
  /// Bodies exactly touching (δ = 0) are in contact, so the dashpot and friction act there
  /// (YADE's Ig2/Law2 keep δ ≥ 0); default false: contact needs δ > 0. Set by matched runs only.
  bool contact_at_zero_overlap = false;
};

/// Case-file keyword of a friction-limit policy ("total", …).
std::string_view to_string(FrictionLimit p) noexcept;
/// Friction-limit policy named `keyword`, or empty.
std::optional<FrictionLimit> parse_friction_limit(std::string_view keyword) noexcept;
/// Case-file keyword of a JKR rupture policy.
std::string_view to_string(JkrRupture p) noexcept;
/// JKR rupture policy named `keyword`, or empty.
std::optional<JkrRupture> parse_jkr_rupture(std::string_view keyword) noexcept;
/// Case-file keyword of a wall lever-arm policy.
std::string_view to_string(WallLeverArm p) noexcept;
/// Wall lever-arm policy named `keyword`, or empty.
std::optional<WallLeverArm> parse_wall_lever_arm(std::string_view keyword) noexcept;

}  // namespace dem
