// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace dem {

/// What the Coulomb limit μ·basis of the tangential force is based on (docs/physics-tangential.md).
enum class FrictionLimit {
  total,            ///< |F_n| of the whole normal force (default; thesis eq 3.23)
  elastic,          ///< |F_elastic| (YADE)
  elastic_damping,  ///< |F_elastic + F_damping| (LAMMPS, LIGGGHTS)
  jkr_shifted,      ///< |F_n + 2 F_pulloff| (Thornton; LAMMPS JKR/DMT)
};

/// Where a JKR contact breaks on separation (docs/physics-cohesion.md).
enum class JkrRupture {
  displacement,  ///< at δ_c = −¾ (π² Γ² R*/E*²)^{1/3}, force −5/9 F_po (default)
  load,          ///< at the load-controlled pull-off point, the maximum tension (as LAMMPS)
};

/// Lever arm of the tangential force about a sphere's centre in a sphere–wall contact.
enum class WallLeverArm {
  contact_point,  ///< r − δ/2, as for sphere pairs (default; common-normal method)
  radius,         ///< r, as LAMMPS fix wall/gran
};

/// Lever arm of the contact point about each sphere's centre in a sphere–sphere contact: it sets
/// the contact-point velocity u_c and the torque of the tangential force.
enum class PairLeverArm {
  contact_point,    ///< r − δ/2 for both (common-normal method, thesis §3.3.3; default)
  radius,           ///< the body radius r for both, as LAMMPS gran/hooke/history
  radius_velocity,  ///< r for the contact-point velocity, r − δ/2 for the torque: LAMMPS pair granular
};

/// How the stored tangential slip ς follows the contact plane as the normal turns (eq 3.9).
enum class TangentialHistory {
  /// Carry ς into the current tangent plane keeping its magnitude, then add u_t·Δt (LAMMPS pair
  /// granular, Luding 2008 eq 17; default).
  project_rescale,
  /// Add u_t·Δt, then drop the part along n without rescaling (LAMMPS gran/hooke/history).
  increment_project,
};

/// The contact radius a in Mindlin's tangential stiffness k_t ∝ G* a (docs/physics-tangential.md).
enum class MindlinRadius {
  overlap,         ///< a = √(R* δ), the Hertz radius of the body overlap (default; thesis eq 3.25)
  contact_radius,  ///< the cohesion law's contact radius where it sets one (an attached JKR neck), else √(R* δ): LAMMPS pair granular
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
  PairLeverArm pair_lever_arm = PairLeverArm::contact_point;
  TangentialHistory tangential_history = TangentialHistory::project_rescale;
  MindlinRadius mindlin_radius = MindlinRadius::overlap;
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
/// Case-file keyword of a pair lever-arm policy.
std::string_view to_string(PairLeverArm p) noexcept;
/// Pair lever-arm policy named `keyword`, or empty.
std::optional<PairLeverArm> parse_pair_lever_arm(std::string_view keyword) noexcept;
/// Case-file keyword of a tangential-history rule.
std::string_view to_string(TangentialHistory p) noexcept;
/// Tangential-history rule named `keyword`, or empty.
std::optional<TangentialHistory> parse_tangential_history(std::string_view keyword) noexcept;
/// Case-file keyword of a Mindlin-radius policy.
std::string_view to_string(MindlinRadius p) noexcept;
/// Mindlin-radius policy named `keyword`, or empty.
std::optional<MindlinRadius> parse_mindlin_radius(std::string_view keyword) noexcept;

}  // namespace dem
