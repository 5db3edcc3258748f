// SPDX-License-Identifier: MIT
#include "dem/forces/pair_loop.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

#include "dem/contact/contact_model.hpp"
#include "dem/forces/contact_batch.hpp"

namespace dem {
namespace {

/// Entries gathered per chunk: 240, not 256, keeps the gather buffers of successive chunks from
/// falling on the same 4 KiB-aliased addresses as the list (docs/performance.md).
constexpr std::size_t kChunk = kContactBatch;

/// Law kinds compiled without dispatch (the many-body scenes' common laws); others dispatch.
using ChuteLaw = StaticSlots<LinearNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using HertzBoxLaw = StaticSlots<HertzNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using LinearRestitutionLaw = StaticSlots<LinearNormal, RestitutionDamping, SpringCoulombTangential, NoCohesion, NoRolling>;
using HertzMindlinLaw = StaticSlots<HertzNormal, TsujiDamping, Mindlin8GTangential, NoCohesion, NoRolling>;
using LinearCohesiveLaw = StaticSlots<LinearNormal, RestitutionDamping, SpringCoulombTangential, LinearCohesion, NoRolling>;
using JkrLaw = StaticSlots<HertzNormal, TsujiDamping, SpringCoulombTangential, JkrCohesion, NoRolling>;

/// The law kinds the batched kernel evaluates (contact_batch.hpp): their normal spring's slot type
/// and the kernel's name for the law. Other kinds are not batched.
template <class Slots> struct BatchFamily {
  static constexpr bool kBatched = false;
};
template <> struct BatchFamily<ChuteLaw> {
  static constexpr bool kBatched = true;
  using Normal = LinearNormal;
  static constexpr BatchLawKind kKind = BatchLawKind::linear;
};
template <> struct BatchFamily<HertzBoxLaw> {
  static constexpr bool kBatched = true;
  using Normal = HertzNormal;
  static constexpr BatchLawKind kKind = BatchLawKind::hertz;
};
template <> struct BatchFamily<HertzMindlinLaw> {
  static constexpr bool kBatched = true;
  using Normal = HertzNormal;
  static constexpr BatchLawKind kKind = BatchLawKind::hertz_mindlin;
};

/// True when the batched kernel evaluates a law of batch family `Family` under these policies: the
/// r − δ/2 and r lever arms (and for Mindlin the radius_velocity one), the two LAMMPS history
/// rules, the whole-force Coulomb test, and of Mindlin either form.
template <class Family>
[[nodiscard]] bool batch_covers(const ContactPolicies& p, PairLeverArm arm) noexcept {
  if constexpr (!Family::kBatched) {
    return false;
  } else {
    constexpr bool kMindlin = Family::kKind == BatchLawKind::hertz_mindlin;
    return arm != PairLeverArm::yade_incident && (kMindlin || arm != PairLeverArm::radius_velocity) &&
           p.tangential_history != TangentialHistory::yade_rotate && p.coulomb_test == CoulombTest::total;
  }
}

/// A batched law's parameters (the caller knows it holds the batch family's sub-models).
template <class Normal, BatchLawKind Kind>
[[nodiscard]] BatchLaw batch_law(const PairLaw& law) noexcept {
  if constexpr (Kind == BatchLawKind::hertz_mindlin) {
    const auto& tangential = *std::get_if<Mindlin8GTangential>(&law.tangential);
    return {std::get_if<HertzNormal>(&law.normal)->effective_modulus, std::get_if<TsujiDamping>(&law.damping)->factor,
            tangential.stiffness_per_radius(), tangential.p.friction, tangential.p.damping_ratio};
  } else {
    const auto& normal = *std::get_if<Normal>(&law.normal);
    const auto& damping = *std::get_if<LammpsMassVelocityDamping>(&law.damping);
    const auto& tangential = *std::get_if<SpringCoulombTangential>(&law.tangential);
    double spring = 0.0;
    if constexpr (std::is_same_v<Normal, LinearNormal>) {
      spring = normal.stiffness;
    } else {
      spring = normal.effective_modulus;
    }
    return {spring, damping.rate, tangential.stiffness, tangential.friction, tangential.damping_ratio};
  }
}


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

/// The list's arrays, as raw pointers for the loop (none of them aliases the force arrays).
struct ListView {
  const PartnerCode* partners;
  std::uint32_t* contact;                 ///< contact slot of each entry, kNoContact when none
  const Vec3* slips;                      ///< committed slips by slot
  const ExtendedHistory* extended;        ///< committed extended history; null when the model keeps none
  Vec3* next_slips;                       ///< where a commit writes
  ExtendedHistory* next_extended;
  const Vec3* shifts;                     ///< 27 periodic shifts by code
};

/// A partner's centre at the image its list entry names: the wrapped centre minus the entry's
/// periodic shift (`Shifted` false: no shift to apply).
struct PartnerImage {
  double x, y, z;
};
template <bool Shifted>
[[nodiscard]] inline PartnerImage partner_image(const PackedSphere& pj, const Vec3* shifts, PartnerCode partner) noexcept {
  if constexpr (Shifted) {
    const Vec3& shift = shifts[partner >> kPartnerBits];
    return {pj.x - shift[0], pj.y - shift[1], pj.z - shift[2]};
  }
  return {pj.x, pj.y, pj.z};
}

/// Adds a pair's force on i (−force on j) and its torques on i and j to the sums.
inline void apply_pair(double* __restrict force, double* __restrict torque, std::uint32_t i, std::uint32_t j,
                       const Vec3& f, const Vec3& torque_i, const Vec3& torque_j) noexcept {
  double* __restrict fi = force + 3 * static_cast<std::size_t>(i);
  double* __restrict fj = force + 3 * static_cast<std::size_t>(j);
  double* __restrict ti = torque + 3 * static_cast<std::size_t>(i);
  double* __restrict tj = torque + 3 * static_cast<std::size_t>(j);
  for (int a = 0; a < 3; ++a) {
    fi[a] += f[a];
    fj[a] -= f[a];
    ti[a] += torque_i[a];
    tj[a] += torque_j[a];
  }
}

/// Evaluates the pair of entry k (owner i) and applies its forces, energies (when `Energies`)
/// and, on commit, its history, which goes to the slab's next free slot `next`.
template <class Slots, bool Energies>
inline void evaluate_pair(const PairLoopInput& in, const ListView& list, std::uint32_t i, std::uint32_t k,
                          double* __restrict force, double* __restrict torque, EnergyTotals& t,
                          std::uint32_t& next) noexcept {
  const PartnerCode partner = list.partners[k];
  const std::uint32_t j = partner & kPartnerMask;
  const std::uint32_t code = partner >> kPartnerBits;
  const PackedSphere& pi = in.packed[i];
  const PartnerImage q = code != kNoShift ? partner_image<true>(in.packed[j], list.shifts, partner)
                                          : partner_image<false>(in.packed[j], list.shifts, partner);
  const ContactGeometry g = pair_geometry(sphere_at(in, i, pi.x, pi.y, pi.z), sphere_at(in, j, q.x, q.y, q.z),
                                          in.lever_arm);
  const std::uint32_t slot = list.contact[k];
  const ContactHistory committed =
      slot == kNoContact ? ContactHistory{}
                         : history_of(list.slips[slot], list.extended != nullptr ? &list.extended[slot] : nullptr);
  const ContactOutcome c =
      evaluate_contact_in(Slots{in.table->law(in.material[i], in.material[j])}, g, committed, in.elapsed);
  if (!c.interacting) {
    if (in.commit) list.contact[k] = kNoContact;
    if constexpr (Energies) {  // a neck that broke, springs that let go
      t.adhesion += c.dissipated_adhesion;
      t.friction += c.dissipated_friction;
    }
    return;
  }
  apply_pair(force, torque, i, j, c.force_on_p, c.torque_on_p, c.torque_on_q);
  if constexpr (Energies) {
    t.elastic += c.elastic_energy;
    t.cohesive += c.cohesive_energy;
    t.friction += c.dissipated_friction;
    t.adhesion += c.dissipated_adhesion;
    t.plastic += c.dissipated_plastic;
    t.stiffness += c.stiffness_change;
    // The dashpot's force on both spheres: the ledger takes its work on the relative motion.
    double* __restrict di = in.damping_force + 3 * static_cast<std::size_t>(i);
    double* __restrict dj = in.damping_force + 3 * static_cast<std::size_t>(j);
    for (int a = 0; a < 3; ++a) {
      di[a] += c.damping_force * g.normal[a];
      dj[a] -= c.damping_force * g.normal[a];
    }
  }
  if (in.commit) {
    list.contact[k] = next;
    list.next_slips[next] = c.history.tangential_slip;
    if (list.next_extended != nullptr) list.next_extended[next] = extended_of(c.history);
    ++next;
  }
}

/// Evaluates gathered pairs [0, count) through the batched kernel: loads each pair's inputs into
/// the batch's lanes, evaluates them all, then applies forces and commits history in list order
/// exactly as evaluate_pair does (the kernel's arithmetic is evaluate_contact's, bit for bit).
template <class Normal, BatchLawKind Kind>
void evaluate_batch(const PairLoopInput& in, const ListView& list, const std::uint32_t* owners,
                    const std::uint32_t* entries, std::uint32_t count, double* __restrict force,
                    double* __restrict torque, std::uint32_t& next, ContactBatch& b, const BatchPolicies& policies,
                    bool uniform) noexcept {
  for (std::uint32_t g = 0; g < count; ++g) {
    if (g + 8 < count) {  // the partner eight pairs ahead: its velocity, spin and radius records
      const std::size_t ahead = list.partners[entries[g + 8]] & kPartnerMask;
      __builtin_prefetch(in.velocity + 3 * ahead);
      __builtin_prefetch(in.angular_velocity + 3 * ahead);
      __builtin_prefetch(in.spheres + ahead);
    }
    const std::uint32_t i = owners[g];
    const std::uint32_t k = entries[g];
    const PartnerCode partner = list.partners[k];
    const std::uint32_t j = partner & kPartnerMask;
    const PackedSphere& pi = in.packed[i];
    const PartnerImage q = (partner >> kPartnerBits) != kNoShift
                               ? partner_image<true>(in.packed[j], list.shifts, partner)
                               : partner_image<false>(in.packed[j], list.shifts, partner);
    b.dx[g] = pi.x - q.x;
    b.dy[g] = pi.y - q.y;
    b.dz[g] = pi.z - q.z;
    // The partner's force and torque sums are written after the kernel: ask for their lines now,
    // while this pass waits on the partner's other records anyway.
    __builtin_prefetch(force + 3 * static_cast<std::size_t>(j), 1);
    __builtin_prefetch(torque + 3 * static_cast<std::size_t>(j), 1);
    const ContactSphere& si = in.spheres[i];
    const ContactSphere& sj = in.spheres[j];
    b.rp[g] = si.radius;
    b.rq[g] = sj.radius;
    b.mp[g] = si.inverse_mass;
    b.mq[g] = sj.inverse_mass;
    const double* ui = in.velocity + 3 * static_cast<std::size_t>(i);
    const double* uj = in.velocity + 3 * static_cast<std::size_t>(j);
    if (in.motion_of != nullptr) {  // prescribed motions replace the velocity, as sphere_at
      if (in.motion_of[i] >= 0) ui = in.motion_velocity[in.motion_of[i]].data();
      if (in.motion_of[j] >= 0) uj = in.motion_velocity[in.motion_of[j]].data();
    }
    set_lane(b.upx, b.upy, b.upz, g, ui);
    set_lane(b.uqx, b.uqy, b.uqz, g, uj);
    set_lane(b.wpx, b.wpy, b.wpz, g, in.angular_velocity + 3 * static_cast<std::size_t>(i));
    set_lane(b.wqx, b.wqy, b.wqz, g, in.angular_velocity + 3 * static_cast<std::size_t>(j));
    const std::uint32_t slot = list.contact[k];
    const Vec3 slip = slot == kNoContact ? Vec3::Zero() : list.slips[slot];
    set_lane(b.sx, b.sy, b.sz, g, slip.data());
    if (!uniform) set_law(b, g, batch_law<Normal, Kind>(in.table->law(in.material[i], in.material[j])));
  }
  evaluate_contact_batch(b, count, policies, in.elapsed);
  for (std::uint32_t g = 0; g < count; ++g) {
    const std::uint32_t k = entries[g];
    if (!batch_contact(b, g, policies)) {
      if (in.commit) list.contact[k] = kNoContact;
      continue;
    }
    apply_pair(force, torque, owners[g], list.partners[k] & kPartnerMask, Vec3(b.fx[g], b.fy[g], b.fz[g]),
               Vec3(b.tpx[g], b.tpy[g], b.tpz[g]), Vec3(b.tqx[g], b.tqy[g], b.tqz[g]));
    if (in.commit) {
      list.contact[k] = next;
      list.next_slips[next] = Vec3(b.sx[g], b.sy[g], b.sz[g]);
      ++next;
    }
  }
}

/// The branch-free distance test of entries [k, stop) (owners consecutive, as the list's runs
/// give them): appends every entry in reach, or active at the last commit, to the gather
/// buffers and returns the new count. `Shifted`: the owners have entries through a periodic face,
/// so each partner is moved by its entry's shift. One loop over a run rather than one per owner:
/// owners have a few entries each, and the exit of a loop that short is mispredicted.
struct PairGather {
  const ListView& view;
  const PackedSphere* packed;
  const std::uint8_t* owner_step;  // entry k's owner is the run's first plus owner_step[k]
  std::uint32_t* owner;
  std::uint32_t* entry;

  template <bool Shifted>
  [[nodiscard]] std::uint32_t run(std::uint32_t k, std::uint32_t stop, std::uint32_t first_owner,
                                  std::uint32_t count) const noexcept {
    for (; k < stop; ++k) {
      const std::uint32_t i = first_owner + owner_step[k];
      const PackedSphere& pi = packed[i];
      const PartnerCode partner = view.partners[k];
      const PackedSphere& pj = packed[partner & kPartnerMask];
      const PartnerImage q = partner_image<Shifted>(pj, view.shifts, partner);
      const double dx = pi.x - q.x;
      const double dy = pi.y - q.y;
      const double dz = pi.z - q.z;
      const double reach = pi.half_reach + pj.half_reach;
      owner[count] = i;
      entry[count] = k;
      count += static_cast<std::uint32_t>((dx * dx + dy * dy + dz * dz <= reach * reach) |
                                          (view.contact[k] != kNoContact));
    }
    return count;
  }
};

/// The loop for one kind of law (DynamicSlots: any law, dispatching per slot); `Periodic`: some
/// entry carries a periodic shift.
template <class Slots, bool Energies, bool Periodic>
[[gnu::flatten]] EnergyTotals pair_loop_as(const PairLoopInput& in, NeighborList& list, std::uint32_t slab,
                                           double* force, double* torque) {
  EnergyTotals t;
  const bool extended = !list.extended().empty();
  const ListView view{list.partners().data(),
                      list.contacts().data(),
                      list.slips().data(),
                      extended ? list.extended().data() : nullptr,
                      list.next_slips().data(),
                      extended ? list.next_extended().data() : nullptr,
                      &list.shift(0)};
  std::uint32_t next = list.slab_contact_base(slab);
  const PackedSphere* packed = in.packed;
  std::array<std::uint32_t, kChunk> gathered_owner;
  std::array<std::uint32_t, kChunk> gathered_entry;
  std::uint32_t count = 0;
  // Runs without an energy ledger evaluate through the batched kernel when it covers the law
  // (it gives the same bits as evaluate_contact; its lanes are filled here, outside the kernel).
  using Family = BatchFamily<Slots>;
  constexpr bool kBatchable = Family::kBatched && !Energies;
  [[maybe_unused]] BatchPolicies policies;
  [[maybe_unused]] bool uniform = true;
  std::conditional_t<kBatchable, ContactBatch, char> batch;
  // The kernel proposes slips only: a model that keeps an extended history is not batched.
  [[maybe_unused]] const bool batched =
      kBatchable && !extended && batch_covers<Family>(in.table->law(0, 0).policies, in.lever_arm);
  if constexpr (kBatchable) {
    const PairLaw& first = in.table->law(0, 0);
    policies = batch_policies(Family::kKind, first.policies, in.lever_arm);
    uniform = in.table->material_count() == 1;
    if (batched && uniform) {
      const BatchLaw law = batch_law<typename Family::Normal, Family::kKind>(first);
      for (std::uint32_t g = 0; g < kContactBatch; ++g) set_law(batch, g, law);
    }
  }
  const auto flush = [&] {
    if constexpr (kBatchable) {
      if (batched) {
        evaluate_batch<typename Family::Normal, Family::kKind>(in, view, gathered_owner.data(), gathered_entry.data(), count,
                                                force, torque, next, batch, policies, uniform);
        count = 0;
        return;
      }
    }
    for (std::uint32_t g = 0; g < count; ++g) {
      evaluate_pair<Slots, Energies>(in, view, gathered_owner[g], gathered_entry[g], force, torque, t, next);
    }
    count = 0;
  };
  const PairGather gather{view, packed, list.owner_steps().data(), gathered_owner.data(), gathered_entry.data()};
  for (const NeighborList::EntryRun& r : list.runs(slab)) {
    // Only the owners near a periodic face read the shifts.
    const bool shifted = Periodic && r.shifted != 0;
    std::uint32_t k = r.begin;
    while (k < r.end) {
      if (count == kChunk) flush();
      // The distance test over as many entries as fit in the gather buffer.
      const std::uint32_t stop = std::min<std::uint32_t>(r.end, k + (static_cast<std::uint32_t>(kChunk) - count));
      count = shifted ? gather.run<true>(k, stop, r.first_owner, count) : gather.run<false>(k, stop, r.first_owner, count);
      k = stop;
    }
  }
  flush();
  return t;
}


/// The loop for the law kind `Slots`, with or without energy sums and periodic shifts.
template <class Slots>
EnergyTotals pair_loop_for(const PairLoopInput& in, NeighborList& list, std::uint32_t slab, double* force,
                           double* torque) {
  if (list.periodic()) {
    return in.energies ? pair_loop_as<Slots, true, true>(in, list, slab, force, torque)
                       : pair_loop_as<Slots, false, true>(in, list, slab, force, torque);
  }
  return in.energies ? pair_loop_as<Slots, true, false>(in, list, slab, force, torque)
                     : pair_loop_as<Slots, false, false>(in, list, slab, force, torque);
}

}  // namespace

BatchPolicies batch_policies(BatchLawKind kind, const ContactPolicies& p, PairLeverArm arm) noexcept {
  BatchPolicies b;
  b.kind = kind;
  b.lever_arm_radius = arm == PairLeverArm::radius;
  b.radius_velocity = arm == PairLeverArm::radius_velocity;
  b.increment_project = p.tangential_history == TangentialHistory::increment_project;
  b.limit_elastic = p.friction_limit == FrictionLimit::elastic;
  b.clamp_tensile = p.clamp_tensile;
  b.contact_at_zero_overlap = p.contact_at_zero_overlap;
  b.zero_when_unloaded = p.unloaded_slider == UnloadedSlider::zero;
  b.mindlin_total = kind == BatchLawKind::hertz_mindlin && p.mindlin_form == MindlinForm::total;
  return b;
}

BatchLaw batch_law_of(const PairLaw& law) noexcept {
  if (ChuteLaw::holds(law)) return batch_law<LinearNormal, BatchLawKind::linear>(law);
  if (HertzBoxLaw::holds(law)) return batch_law<HertzNormal, BatchLawKind::hertz>(law);
  return batch_law<HertzNormal, BatchLawKind::hertz_mindlin>(law);
}

EnergyTotals run_pair_loop(const PairLoopInput& in, NeighborList& list, std::uint32_t slab, double* force,
                           double* torque) {
  // Every material pair holds the same sub-model types (the model choice is global).
  const PairLaw& law = in.table->law(0, 0);
  if (ChuteLaw::holds(law)) return pair_loop_for<ChuteLaw>(in, list, slab, force, torque);
  if (HertzBoxLaw::holds(law)) return pair_loop_for<HertzBoxLaw>(in, list, slab, force, torque);
  if (LinearRestitutionLaw::holds(law)) return pair_loop_for<LinearRestitutionLaw>(in, list, slab, force, torque);
  if (HertzMindlinLaw::holds(law)) return pair_loop_for<HertzMindlinLaw>(in, list, slab, force, torque);
  if (LinearCohesiveLaw::holds(law)) return pair_loop_for<LinearCohesiveLaw>(in, list, slab, force, torque);
  if (JkrLaw::holds(law)) return pair_loop_for<JkrLaw>(in, list, slab, force, torque);
  return pair_loop_for<DynamicSlots>(in, list, slab, force, torque);
}

}  // namespace dem
