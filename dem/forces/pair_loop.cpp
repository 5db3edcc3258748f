// SPDX-License-Identifier: MIT
#include "dem/forces/pair_loop.hpp"

#include <algorithm>
#include <array>

#include "dem/contact/contact_model.hpp"

namespace dem {
namespace {

/// Entries gathered per chunk: 240, not 256, keeps the gather buffers of successive chunks from
/// falling on the same 4 KiB-aliased addresses as the list (docs/performance.md).
constexpr std::size_t kChunk = 240;

/// The per-sphere inputs of the geometry, with a prescribed motion's velocity when it has one.
inline SphereState sphere_at(const PairLoopInput& in, std::uint32_t i, double x, double y, double z) noexcept {
  const double* u = in.velocity + 3 * static_cast<std::size_t>(i);
  const double* w = in.angular_velocity + 3 * static_cast<std::size_t>(i);
  const ContactSphere& c = in.spheres[i];
  SphereState s{Vec3(x, y, z), Vec3(u[0], u[1], u[2]), Vec3(w[0], w[1], w[2]), c.radius,
                c.effect_radius, c.inverse_mass, c.charge};
  if (in.motion_of != nullptr && in.motion_of[i] >= 0) s.velocity = in.motion_velocity[in.motion_of[i]];
  return s;
}

/// One gathered pair: its owner and its list entry.
struct Gathered {
  std::uint32_t owner;
  std::uint32_t entry;
};

/// Evaluates one gathered pair and applies its forces, energies (when `Energies`) and (on
/// commit) history.
template <class Slots, bool Energies>
inline void evaluate_pair(const PairLoopInput& in, NeighborList& list, std::uint32_t i, std::uint32_t k,
                          double* force, double* torque, EnergyTotals& t) noexcept {
  std::uint8_t& active = list.active()[k];
  Vec3& slip = list.slips()[k];
  const std::span<ExtendedHistory> ext = list.extended();
  const PartnerCode partner = list.partners()[k];
  const std::uint32_t j = partner & kPartnerMask;
  const std::uint32_t code = partner >> kPartnerBits;
  const PackedSphere& pi = in.packed[i];
  const PackedSphere& pj = in.packed[j];
  double qx = pj.x;
  double qy = pj.y;
  double qz = pj.z;
  if (code != kNoShift) {
    const Vec3& shift = list.shift(code);
    qx -= shift[0];
    qy -= shift[1];
    qz -= shift[2];
  }
  const ContactGeometry g = pair_geometry(sphere_at(in, i, pi.x, pi.y, pi.z), sphere_at(in, j, qx, qy, qz),
                                          in.lever_arm_is_radius);
  ContactHistory committed;
  if (active != 0) {
    committed.tangential_slip = slip;
    if (!ext.empty()) {
      committed.rolling_slip = ext[k].rolling_slip;
      committed.max_overlap = ext[k].max_overlap;
      committed.attached = ext[k].attached != 0;
    }
  }
  const ContactOutcome c =
      evaluate_contact_in(Slots{in.table->law(in.material[i], in.material[j])}, g, committed, in.elapsed);
  if (!c.interacting) {
    if (in.commit) active = 0;
    return;
  }
  double* fi = force + 3 * static_cast<std::size_t>(i);
  double* fj = force + 3 * static_cast<std::size_t>(j);
  double* ti = torque + 3 * static_cast<std::size_t>(i);
  double* tj = torque + 3 * static_cast<std::size_t>(j);
  for (int a = 0; a < 3; ++a) {
    fi[a] += c.force_on_p[a];
    fj[a] -= c.force_on_p[a];
    ti[a] += c.torque_on_p[a];
    tj[a] += c.torque_on_q[a];
  }
  if constexpr (Energies) {
    t.elastic += c.elastic_energy;
    t.cohesive += c.cohesive_energy;
    t.damping += c.dissipated_damping;
    t.friction += c.dissipated_friction;
  }
  if (in.commit) {
    active = 1;
    slip = c.history.tangential_slip;
    if (!ext.empty()) {
      ext[k] = {c.history.rolling_slip, c.history.max_overlap, static_cast<std::uint8_t>(c.history.attached ? 1 : 0)};
    }
  }
}

/// The loop for one kind of law (DynamicSlots: any law, dispatching per slot).
template <class Slots, bool Energies>
[[gnu::flatten]] EnergyTotals pair_loop_as(const PairLoopInput& in, NeighborList& list,
                                           std::span<const std::uint32_t> owners, double* force, double* torque) {
  EnergyTotals t;
  const std::span<const PartnerCode> partners = list.partners();
  const std::span<const std::uint8_t> active = list.active();
  std::array<Gathered, kChunk> gathered;
  std::size_t count = 0;
  const auto flush = [&] {
    for (std::size_t g = 0; g < count; ++g) {
      evaluate_pair<Slots, Energies>(in, list, gathered[g].owner, gathered[g].entry, force, torque, t);
    }
    count = 0;
  };
  for (const std::uint32_t i : owners) {
    const PackedSphere pi = in.packed[i];
    std::uint32_t k = list.begin(i);
    const std::uint32_t end = list.begin(i + 1);
    while (k < end) {
      if (count == kChunk) flush();
      // Branch-free distance test over as many entries as fit in the gather buffer.
      const std::uint32_t stop = std::min<std::uint32_t>(end, k + static_cast<std::uint32_t>(kChunk - count));
      for (; k < stop; ++k) {
        const PartnerCode partner = partners[k];
        const PackedSphere& pj = in.packed[partner & kPartnerMask];
        const Vec3& shift = list.shift(partner >> kPartnerBits);
        const double dx = pi.x - (pj.x - shift[0]);
        const double dy = pi.y - (pj.y - shift[1]);
        const double dz = pi.z - (pj.z - shift[2]);
        const double reach = pi.half_reach + pj.half_reach;
        gathered[count] = {i, k};
        count += static_cast<std::size_t>((dx * dx + dy * dy + dz * dz <= reach * reach) | (active[k] != 0));
      }
    }
  }
  flush();
  return t;
}

/// Law kinds compiled without dispatch (the many-body scenes' common laws); others dispatch.
using ChuteLaw = StaticSlots<LinearNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using HertzBoxLaw = StaticSlots<HertzNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using LinearRestitutionLaw = StaticSlots<LinearNormal, RestitutionDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using HertzMindlinLaw = StaticSlots<HertzNormal, TsujiDamping, Mindlin8GTangential, NoCohesion, NoRolling>;
using LinearCohesiveLaw = StaticSlots<LinearNormal, RestitutionDamping, SpringCoulombTangential, LinearCohesion, NoRolling>;
using JkrLaw = StaticSlots<HertzNormal, TsujiDamping, SpringCoulombTangential, JkrCohesion, NoRolling>;

/// The loop for the law kind `Slots`, with or without energy sums.
template <class Slots>
EnergyTotals pair_loop_for(const PairLoopInput& in, NeighborList& list, std::span<const std::uint32_t> owners,
                           double* force, double* torque) {
  return in.energies ? pair_loop_as<Slots, true>(in, list, owners, force, torque)
                     : pair_loop_as<Slots, false>(in, list, owners, force, torque);
}

}  // namespace

EnergyTotals run_pair_loop(const PairLoopInput& in, NeighborList& list, std::span<const std::uint32_t> owners,
                           double* force, double* torque) {
  // Every material pair holds the same sub-model types (the model choice is global).
  const PairLaw& law = in.table->law(0, 0);
  if (ChuteLaw::holds(law)) return pair_loop_for<ChuteLaw>(in, list, owners, force, torque);
  if (HertzBoxLaw::holds(law)) return pair_loop_for<HertzBoxLaw>(in, list, owners, force, torque);
  if (LinearRestitutionLaw::holds(law)) return pair_loop_for<LinearRestitutionLaw>(in, list, owners, force, torque);
  if (HertzMindlinLaw::holds(law)) return pair_loop_for<HertzMindlinLaw>(in, list, owners, force, torque);
  if (LinearCohesiveLaw::holds(law)) return pair_loop_for<LinearCohesiveLaw>(in, list, owners, force, torque);
  if (JkrLaw::holds(law)) return pair_loop_for<JkrLaw>(in, list, owners, force, torque);
  return pair_loop_for<DynamicSlots>(in, list, owners, force, torque);
}

}  // namespace dem
