// SPDX-License-Identifier: MIT
#pragma once
// The many-body pair loop's batched contact evaluation: the same arithmetic as evaluate_contact
// for two families of laws without cohesion or rolling resistance — a linear or Hertz spring with
// the mass-scaled dashpot and spring–Coulomb friction (LAMMPS' granular benchmarks), and Hertz
// with Tsuji's dashpot and Mindlin friction, total or incremental (the packing and hopper cases,
// the box benchmark) — laid
// out as one structure of arrays per batch of pairs so
// that the compiler evaluates several pairs per instruction. A test holds it bit-for-bit to
// evaluate_contact on random pairs under every policy (tests/dem/contact_batch_test.cpp); the
// pair loop uses it only for runs that keep no energy ledger, and evaluate_contact otherwise —
// the two give the same forces to the last bit, so a ledger never changes a trajectory.
// Deliberately free of Eigen: the kernel is compiled for more than one instruction set
// (docs/performance.md, "The batched contact kernel").

#include <cstdint>

namespace dem {

/// Pairs per batch (the pair loop's gather chunk; 240, not 256: see pair_loop.cpp).
inline constexpr std::uint32_t kContactBatch = 240;

/// Which law a batch evaluates.
enum class BatchLawKind : std::uint8_t {
  linear,  ///< F = k δ (LinearNormal, thesis eq 3.10), mass-scaled dashpot, spring–Coulomb friction
  hertz,   ///< F = 4/3 E* √R* δ^{3/2} (HertzNormal, eq 3.12–3.13), mass-scaled dashpot, spring–Coulomb
  /// Hertz, Tsuji's dashpot η = α √(m* F/δ) (TsujiDamping) and Mindlin friction k_t = 8 G* a
  /// (Mindlin8GTangential) in either MindlinForm (BatchPolicies::mindlin_total)
  hertz_mindlin,
};

/// The contact model's policies as the batch kernel reads them (values of ContactPolicies and
/// PairLeverArm, docs/physics.md). The kernel handles every combination except the lever arm
/// PairLeverArm::yade_incident (and radius_velocity outside the Mindlin law), the history rule
/// yade_rotate, CoulombTest::spring and models that keep an extended history (an energy ledger),
/// which the pair loop leaves to evaluate_contact.
struct BatchPolicies {
  BatchLawKind kind = BatchLawKind::linear;  ///< the law the batch evaluates
  bool lever_arm_radius = false;          ///< PairLeverArm::radius (else contact_point, r − δ/2)
  bool radius_velocity = false;           ///< PairLeverArm::radius_velocity (hertz_mindlin only)
  bool increment_project = false;         ///< TangentialHistory::increment_project (else project_rescale)
  bool limit_elastic = false;             ///< FrictionLimit::elastic (else |F_e + F_d|: the others without cohesion)
  bool clamp_tensile = false;             ///< ContactPolicies::clamp_tensile
  bool contact_at_zero_overlap = false;   ///< ContactPolicies::contact_at_zero_overlap
  bool zero_when_unloaded = false;        ///< UnloadedSlider::zero (else cap)
  bool mindlin_total = false;             ///< MindlinForm::total (hertz_mindlin only; else incremental)
};

/// One material pair's parameters in the batch family.
struct BatchLaw {
  double normal;         ///< k_e [N/m] (linear) or E* [Pa] (Hertz)
  double damping_rate;   ///< η/m* [1/s] (LammpsMassVelocityDamping); hertz_mindlin: Tsuji's α(ε) [-]
  double tangential;     ///< k_f [N/m]; hertz_mindlin: k_t per unit contact radius, 8 G* [N/m²]
  double friction;       ///< μ [-]
  double damping_ratio;  ///< η_t/η_n [-]
};

/// A batch of pairs p–q in structure-of-arrays form: the inputs the pair loop loads, the
/// outputs the kernel writes. Every array has kContactBatch lanes.
struct ContactBatch {
  // Inputs.
  alignas(64) double dx[kContactBatch];  ///< x_p − x_q (q at its periodic image) [m]
  alignas(64) double dy[kContactBatch];
  alignas(64) double dz[kContactBatch];
  alignas(64) double rp[kContactBatch];  ///< radii [m]
  alignas(64) double rq[kContactBatch];
  alignas(64) double mp[kContactBatch];  ///< inverse masses [1/kg], 0 for a fixed sphere
  alignas(64) double mq[kContactBatch];
  alignas(64) double upx[kContactBatch];  ///< velocities [m/s]
  alignas(64) double upy[kContactBatch];
  alignas(64) double upz[kContactBatch];
  alignas(64) double uqx[kContactBatch];
  alignas(64) double uqy[kContactBatch];
  alignas(64) double uqz[kContactBatch];
  alignas(64) double wpx[kContactBatch];  ///< angular velocities [rad/s]
  alignas(64) double wpy[kContactBatch];
  alignas(64) double wpz[kContactBatch];
  alignas(64) double wqx[kContactBatch];
  alignas(64) double wqy[kContactBatch];
  alignas(64) double wqz[kContactBatch];
  /// Committed tangential slip ς (zero for a new contact) in; the proposed slip out [m].
  alignas(64) double sx[kContactBatch];
  alignas(64) double sy[kContactBatch];
  alignas(64) double sz[kContactBatch];
  /// Per-lane law parameters (BatchLaw; set_law).
  alignas(64) double normal[kContactBatch];
  alignas(64) double rate[kContactBatch];  ///< BatchLaw::damping_rate
  alignas(64) double kt[kContactBatch];    ///< BatchLaw::tangential
  alignas(64) double mu[kContactBatch];
  alignas(64) double ratio[kContactBatch];
  // Outputs.
  alignas(64) double overlap[kContactBatch];  ///< δ = r_p + r_q − |x_pq| [m]
  alignas(64) double fx[kContactBatch];  ///< force on p [N]; q receives the opposite
  alignas(64) double fy[kContactBatch];
  alignas(64) double fz[kContactBatch];
  alignas(64) double tpx[kContactBatch];  ///< torque on p about its centre [N·m]
  alignas(64) double tpy[kContactBatch];
  alignas(64) double tpz[kContactBatch];
  alignas(64) double tqx[kContactBatch];  ///< torque on q about its centre [N·m]
  alignas(64) double tqy[kContactBatch];
  alignas(64) double tqz[kContactBatch];
};

/// True when lane `g` of an evaluated batch is a contact (and so interacting: the family has no
/// long-range law), as evaluate_contact's ContactOutcome::contact.
[[nodiscard]] inline bool batch_contact(const ContactBatch& b, std::uint32_t g, const BatchPolicies& p) noexcept {
  return b.overlap[g] > 0.0 || (p.contact_at_zero_overlap && b.overlap[g] == 0.0);
}

/// Sets lane g of the three arrays of one vector quantity to (v[0], v[1], v[2]).
inline void set_lane(double* x, double* y, double* z, std::uint32_t g, const double* v) noexcept {
  x[g] = v[0];
  y[g] = v[1];
  z[g] = v[2];
}

/// Sets lane g's law parameters.
inline void set_law(ContactBatch& b, std::uint32_t g, const BatchLaw& law) noexcept {
  b.normal[g] = law.normal;
  b.rate[g] = law.damping_rate;
  b.kt[g] = law.tangential;
  b.mu[g] = law.friction;
  b.ratio[g] = law.damping_ratio;
}

/// Evaluates lanes [0, n) of `batch` (n ≤ kContactBatch), `elapsed` seconds after the last
/// commit: writes each lane's overlap, force and torques, and replaces its slip by the proposed
/// one. Lanes that are not in contact (batch_contact false) carry no meaningful force or slip.
void evaluate_contact_batch(ContactBatch& batch, std::uint32_t n, const BatchPolicies& policies,
                            double elapsed) noexcept;

}  // namespace dem
