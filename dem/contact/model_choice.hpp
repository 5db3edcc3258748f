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
  total_plus_pulloff,  ///< |F_n| + F_pulloff (YADE Hertz–Mindlin with adhesion, after Thornton 1991)
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
  /// r − δ/2 for the torque; the slip velocity YADE's way (ScGeom::getIncidentVel with
  /// avoidGranularRatcheting): spin with the radius r, the sphere's own velocity scaled by
  /// α = 2r/(2r − δ) in the tangential part (YADE Ig2_Wall_Sphere_ScGeom + CundallStrack).
  /// Against a mesh facet YADE's Ig2_Facet_Sphere_ScGeom forms the velocity without α at the
  /// contact point r − δ/2, so there this arm is `contact_point`.
  yade_incident,
};

/// Lever arm of the contact point about each sphere's centre in a sphere–sphere contact: it sets
/// the contact-point velocity u_c and the torque of the tangential force.
enum class PairLeverArm {
  contact_point,    ///< r − δ/2 for both (common-normal method, thesis §3.3.3; default)
  radius,           ///< the body radius r for both, as LAMMPS gran/hooke/history
  radius_velocity,  ///< r for the contact-point velocity, r − δ/2 for the torque: LAMMPS pair granular
  /// r − δ/2 for the torque; the slip velocity YADE's way: spins with the radii r, the centres'
  /// relative velocity scaled by α = (r_p + r_q)/(r_p + r_q − δ) in the tangential part (YADE
  /// ScGeom::getIncidentVel with avoidGranularRatcheting). The normal speed is not scaled.
  yade_incident,
};

/// How the stored tangential slip ς follows the contact plane as the normal turns (eq 3.9).
enum class TangentialHistory {
  /// Carry ς into the current tangent plane keeping its magnitude, then add u_t·Δt (LAMMPS pair
  /// granular, Luding 2008 eq 17; default).
  project_rescale,
  /// Add u_t·Δt, then drop the part along n without rescaling (LAMMPS gran/hooke/history).
  increment_project,
  /// Turn ς by the normal's rotation, ς − ς × (n_old × n), then by the mean spin about n over the
  /// step about the old normal, ς − ς × (½ Δt n_old·(ω_p + ω_q)) n_old, without re-projecting; then add
  /// u_t·Δt (YADE ScGeom::rotate and precompute). Needs the normal of the last evaluation, which
  /// the history keeps under this rule.
  yade_rotate,
};

/// The contact radius a in Mindlin's tangential stiffness k_t ∝ G* a (docs/physics-tangential.md).
enum class MindlinRadius {
  overlap,         ///< a = √(R* δ), the Hertz radius of the body overlap (default; thesis eq 3.25)
  contact_radius,  ///< the cohesion law's contact radius where it sets one (an attached JKR neck), else √(R* δ): LAMMPS pair granular
};

/// What a spring–dashpot–slider (tangential or rolling) does when its stored displacement is
/// exactly zero — a contact's first evaluation before any slip is integrated, such as one that
/// already touches at t = 0 — and its dashpot alone exceeds the Coulomb limit
/// (docs/physics-tangential.md, "Unloaded slider").
enum class UnloadedSlider {
  cap,   ///< the force is scaled back to the limit, as at any other evaluation (default)
  zero,  ///< the force is set to zero and the displacement stays zero: LAMMPS pair granular, fix wall/gran, gran/hooke/history
};

/// How a Mindlin tangential spring (`mindlin`, `mindlin_8g`) turns slip into force when its
/// stiffness k_t = c a changes with the contact radius a (docs/physics-tangential.md).
enum class MindlinForm {
  total,        ///< F = −k_t(a) ς on the whole stored slip, at the current stiffness (default; LAMMPS `mindlin`)
  incremental,  ///< F = F_old − k_t(a) Δς: each increment at the stiffness of its step (YADE Law2_ScGeom_MindlinPhys_Mindlin)
};

/// What a tangential spring–dashpot–slider tests against its Coulomb limit μ·basis
/// (docs/physics-tangential.md, "Coulomb test").
enum class CoulombTest {
  total,   ///< the whole trial force −k ς − η_t u_t, capped to the limit (Cundall–Strack; LAMMPS) (default)
  spring,  ///< the spring alone, k|ς| against the limit: sliding, the spring force is scaled to it and the dashpot dropped; stuck, the dashpot is added uncapped (LIGGGHTS tangential history)
};

/// How the constant directional rolling torque (`rolling = "constant_torque"`) takes its size
/// and direction (docs/physics-tangential.md, "Rolling sub-models").
enum class ConstantTorqueForm {
  /// μ_r R* F ω̂_t: F the friction-limit basis, ω̂_t the unit vector of the tangent-plane part of
  /// ω_p − ω_q (default; Ai et al., Powder Technol. 206 (2011), model type A).
  tangent,
  /// μ_r R* F_el (ω̂ − (ω̂·n) n): F_el the elastic normal force, ω̂ the unit vector of the whole
  /// ω_p − ω_q, of which the tangent-plane part is kept without renormalising (LIGGGHTS
  /// rolling_friction cdt).
  projected,
};

/// How the normal dashpot is limited while a cohesion law with a pull-off force F_po > 0 (DMT)
/// acts (docs/physics-cohesion.md, "Dashpot under adhesion").
enum class AdhesiveDashpot {
  clamp,        ///< as without adhesion: clamp_tensile (if set) keeps elastic + dashpot ≥ 0 (default)
  pulloff_cap,  ///< when the whole normal force is tensile, the dashpot's magnitude is capped at F_po and clamp_tensile is not applied: YADE Law2_ScGeom_MindlinPhys_Mindlin with includeAdhesion
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
  UnloadedSlider unloaded_slider = UnloadedSlider::cap;
  AdhesiveDashpot adhesive_dashpot = AdhesiveDashpot::clamp;
  MindlinForm mindlin_form = MindlinForm::total;
  CoulombTest coulomb_test = CoulombTest::total;
  ConstantTorqueForm constant_torque_form = ConstantTorqueForm::tangent;
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
/// Case-file keyword of an unloaded-slider policy.
std::string_view to_string(UnloadedSlider p) noexcept;
/// Unloaded-slider policy named `keyword`, or empty.
std::optional<UnloadedSlider> parse_unloaded_slider(std::string_view keyword) noexcept;
/// Case-file keyword of a Mindlin-form policy.
std::string_view to_string(MindlinForm p) noexcept;
/// Mindlin-form policy named `keyword`, or empty.
std::optional<MindlinForm> parse_mindlin_form(std::string_view keyword) noexcept;
/// Case-file keyword of a Coulomb-test policy ("total", "spring").
std::string_view to_string(CoulombTest p) noexcept;
/// Coulomb-test policy named `keyword`, or empty.
std::optional<CoulombTest> parse_coulomb_test(std::string_view keyword) noexcept;
/// Case-file keyword of a constant-torque form ("tangent", "projected").
std::string_view to_string(ConstantTorqueForm p) noexcept;
/// Constant-torque form named `keyword`, or empty.
std::optional<ConstantTorqueForm> parse_constant_torque_form(std::string_view keyword) noexcept;
/// Case-file keyword of an adhesive-dashpot policy.
std::string_view to_string(AdhesiveDashpot p) noexcept;
/// Adhesive-dashpot policy named `keyword`, or empty.
std::optional<AdhesiveDashpot> parse_adhesive_dashpot(std::string_view keyword) noexcept;

}  // namespace dem
