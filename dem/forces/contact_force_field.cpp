// SPDX-License-Identifier: MIT
#include "dem/forces/contact_force_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "dem/core/balanced_for.hpp"
#include "dem/core/model_error.hpp"
#include "dem/core/parallel_for.hpp"
#include "dem/neighbors/interaction_reach.hpp"
#include "dem/particles/spatial_order.hpp"

namespace dem {
namespace {

/// Spheres per chunk of the per-sphere loop: chunks, not threads, group the energy sums, so the
/// sums are the same for any thread count.
constexpr std::uint32_t kSphereChunk = 4096;

/// Spheres per chunk as the threads share out the opening pass (kick, drift, packing), and the
/// wall and field pass when it keeps no energy sums.
constexpr std::int64_t kSphereShare = 512;

/// True when some sub-model of the choice reads history beyond the tangential slip: rolling
/// slip (rolling resistance), the largest overlap (hysteretic loading), the JKR neck, the last
/// normal (TangentialHistory::yade_rotate), or — for the energy ledger only — a Mindlin law's
/// last stiffness.
bool needs_extended_history(const ModelChoice& c, bool track_energy) {
  return c.rolling != "none" || c.normal == "hysteretic" || c.cohesion == "jkr" ||
         c.tangential_history == TangentialHistory::yade_rotate ||
         (track_energy && (c.tangential == "mindlin" || c.tangential == "mindlin_8g"));
}

/// Default Verlet skin: a tenth of the smallest body diameter.
double default_skin(const ParticleProperties& props) {
  double smallest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < props.radius.size(); ++i) smallest = std::min(smallest, props.radius[i]);
  return std::isfinite(smallest) ? 0.2 * smallest : 1.0;
}

/// A history assembled from a list entry's slip and extended record.
ContactHistory assemble(const Vec3& slip, std::uint32_t active, std::span<const ExtendedHistory> ext,
                        std::size_t k) noexcept {
  if (active == 0) return {};
  return history_of(slip, ext.empty() ? nullptr : &ext[k]);
}

/// Stores the history an evaluation proposes into a list entry.
template <class Entry>
void store(Entry& e, std::span<ExtendedHistory> ext, std::size_t k, const ContactHistory& h) noexcept {
  e.active = 1;
  e.slip = h.tangential_slip;
  if (!ext.empty()) ext[k] = extended_of(h);
}

/// Adds one contact's energies to a running sum.
void add_energies(EnergyTotals& t, const ContactOutcome& c) noexcept {
  t.elastic += c.elastic_energy;
  t.cohesive += c.cohesive_energy;
  t.friction += c.dissipated_friction;
  t.adhesion += c.dissipated_adhesion;
  t.plastic += c.dissipated_plastic;
  t.stiffness += c.stiffness_change;
}

/// The geometry g of sphere p moved along its normal to twice the reach `reach` of its wall:
/// where a contact ends with nothing acting.
ContactGeometry beyond_reach(ContactGeometry g, const SphereState& p, double reach) noexcept {
  g.distance = 2.0 * reach;
  g.overlap = p.radius - g.distance;
  g.effect_overlap = p.effect_radius - g.distance;
  return g;
}

}  // namespace

ContactForceField::ContactForceField(const ParticleProperties& props, const PairTable& table,
                                     ForceFieldSetup setup)
    : props_(props), table_(table), setup_(std::move(setup)), motion_of_(props.size(), -1) {
  const auto n = props.size();
  if (n > kMaxSpheres) {
    throw ModelError("particles", fmt::format("{} spheres exceed the neighbour list's limit of {}", n, kMaxSpheres));
  }
  still_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) still_[i] = props.fixed[i];
  for (std::size_t k = 0; k < setup_.motions.size(); ++k) {
    motion_of_[setup_.motions[k].particle] = static_cast<std::int32_t>(k);
    still_[setup_.motions[k].particle] = 0;
  }
  motion_position_.resize(setup_.motions.size());
  motion_velocity_.resize(setup_.motions.size());
  for (std::size_t w = 0; w < setup_.walls.size(); ++w) {
    const Wall& wall = setup_.walls[w];
    if (wall.mesh == kNoMesh) continue;
    if (wall.shape != WallShape::triangle || wall.mesh >= setup_.meshes.size() ||
        w < setup_.meshes[wall.mesh].first_wall ||
        w - setup_.meshes[wall.mesh].first_wall >= setup_.meshes[wall.mesh].facets.size()) {
      throw ModelError("walls", fmt::format("wall {} names mesh {}, which does not list it as a facet", w, wall.mesh));
    }
  }
  half_reach_ = half_reaches(props, table);
  contact_spheres_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    contact_spheres_[i] = {props.radius[k], props.effect_radius[k], props.inverse_mass[k], props.charge[k]};
  }
  classes_ = size_classes({half_reach_.data(), n});
  extended_history_ = needs_extended_history(table.choice(), setup_.track_energy);
  if (!(setup_.neighbors.skin > 0.0)) setup_.neighbors.skin = default_skin(props);

  const PeriodicBox& box = setup_.box;
  double largest = 0.0;
  for (const double h : classes_.max_half_reach) largest = std::max(largest, h);
  const double cutoff = 2.0 * largest + setup_.neighbors.skin;
  constexpr const char* kAxis = "xyz";
  for (int k = 0; k < 3; ++k) {
    if (!box.periodic[k]) continue;
    const double length = box.hi[k] - box.lo[k];
    if (!(length >= 2.0 * cutoff)) {
      throw ModelError("domain.periodic",
                       fmt::format("the periodic box is {:.6g} m long along {}, shorter than twice the "
                                   "longest listed pair distance {:.6g} m (largest interaction reach "
                                   "{:.6g} m plus skin {:.6g} m): a pair would meet more than one image",
                                   length, kAxis[k], cutoff, 2.0 * largest, setup_.neighbors.skin));
    }
    for (std::size_t w = 0; w < setup_.walls.size(); ++w) {
      if (setup_.walls[w].shape != WallShape::plane) {
        throw ModelError("walls", fmt::format("wall {} is bounded; bounded walls have no periodic images, "
                                              "so a periodic domain takes plane walls only",
                                              w));
      }
      if (setup_.walls[w].normal[k] != 0.0) {
        throw ModelError("walls", fmt::format("wall {} has a normal component along the periodic axis {}; "
                                              "a plane wall must be parallel to every periodic axis",
                                              w, kAxis[k]));
      }
    }
  }
  packed_.resize(n);
  if (box.any()) wrap_offset_ = Vec3Array::Zero(3, static_cast<Eigen::Index>(n));
  const auto cols = static_cast<Eigen::Index>(n);
  force_ = Vec3Array::Zero(3, cols);
  torque_ = Vec3Array::Zero(3, cols);
  committed_force_ = Vec3Array::Zero(3, cols);
  committed_torque_ = Vec3Array::Zero(3, cols);
  built_position_ = Vec3Array::Zero(3, cols);
}

SphereState ContactForceField::sphere(const KinematicState& s, std::uint32_t i) const noexcept {
  const PackedSphere& x = packed_[i];
  const std::int32_t m = motion_of_[i];
  return SphereState{Vec3(x.x, x.y, x.z),
                     m >= 0 ? motion_velocity_[static_cast<std::size_t>(m)] : Vec3(s.velocity.col(i)),
                     s.angular_velocity.col(i),
                     props_.radius[i],
                     props_.effect_radius[i],
                     props_.inverse_mass[i],
                     props_.charge[i]};
}

bool ContactForceField::plan_mesh_contacts(std::uint32_t i, const SphereState& p, double t, MeshPlan& plan) const {
  const std::uint32_t first = wall_list_.begin(i);
  const std::uint32_t end = wall_list_.begin(i + 1);
  const std::span<const WallEntry> entries = wall_list_.entries();
  bool any = false;
  for (std::uint32_t k = first; k < end && !any; ++k) any = setup_.walls[entries[k].wall].mesh != kNoMesh;
  if (!any) return false;
  plan.role.assign(end - first, FacetRole::other);
  bool new_contact = false;
  for (std::uint32_t k = first; k < end; ++k) {
    const Wall& wall = setup_.walls[entries[k].wall];
    if (wall.mesh == kNoMesh || !wall.present(t)) continue;
    if (wall_frame(wall, p.position, t).distance > wall_reach_of(i, entries[k].wall)) continue;
    const bool counted = facet_counts(setup_.walls, setup_.meshes, entries[k].wall, p.position, t);
    plan.role[k - first] = counted ? FacetRole::counted : FacetRole::skipped;
    new_contact = new_contact || (counted && entries[k].active == 0);
  }
  if (!new_contact) return true;
  // A contact that passes from facet to facet (rolling over a seam, sliding past a corner) keeps
  // its tangential spring and neck: per mesh, the facets that count the sphere anew take over the
  // committed histories of the neighbouring facets that stopped counting it. A mesh's facets are
  // consecutive walls, so its candidates are consecutive too.
  plan.history.resize(end - first);
  const std::span<const ExtendedHistory> ext = wall_list_.extended();
  for (std::uint32_t k = first; k < end;) {
    const std::uint32_t mesh = setup_.walls[entries[k].wall].mesh;
    std::uint32_t run_end = k + 1;
    while (run_end < end && setup_.walls[entries[run_end].wall].mesh == mesh) ++run_end;
    if (mesh != kNoMesh) hand_over(first, k, run_end, p, t, plan, ext);
    k = run_end;
  }
  return true;
}

void ContactForceField::hand_over(std::uint32_t first, std::uint32_t begin, std::uint32_t end, const SphereState& p,
                                  double t, MeshPlan& plan, std::span<const ExtendedHistory> ext) const {
  const std::span<const WallEntry> entries = wall_list_.entries();
  plan.receivers.clear();
  plan.donors.clear();
  for (std::uint32_t j = begin; j < end; ++j) {
    const FacetRole role = plan.role[j - first];
    if (role == FacetRole::counted && entries[j].active == 0) plan.receivers.push_back(j);
    if (role == FacetRole::skipped && entries[j].active != 0) plan.donors.push_back(j);
  }
  // Each donor (in candidate order) hands over to the receiver that shares a corner with it and
  // whose nearest point lies nearest its own: the facet the contact point moved onto, not another
  // facet the sphere happens to come within reach of in the same step.
  const MeshTopology& mesh = setup_.meshes[setup_.walls[entries[begin].wall].mesh];
  const auto corners = [&](std::uint32_t k) { return mesh.facets[entries[k].wall - mesh.first_wall]; };
  const auto nearest = [&](std::uint32_t k) {
    const WallFrame f = wall_frame(setup_.walls[entries[k].wall], p.position, t);
    return Vec3(p.position - f.distance * f.normal);
  };
  for (const std::uint32_t d : plan.donors) {
    const auto dc = corners(d);
    const Vec3 from = nearest(d);
    std::int64_t best = -1;
    double best_d2 = 0.0;
    for (const std::uint32_t r : plan.receivers) {
      if (plan.role[r - first] != FacetRole::counted) continue;  // taken by an earlier donor
      const auto rc = corners(r);
      const bool neighbours = std::any_of(dc.begin(), dc.end(), [&](std::uint32_t c) {
        return c == rc[0] || c == rc[1] || c == rc[2];
      });
      if (!neighbours) continue;
      const double d2 = (nearest(r) - from).squaredNorm();
      if (best < 0 || d2 < best_d2) {
        best = r;
        best_d2 = d2;
      }
    }
    if (best < 0) continue;
    const auto r = static_cast<std::uint32_t>(best);
    plan.role[r - first] = FacetRole::continues;
    plan.history[r - first] = assemble(entries[d].slip, entries[d].active, ext, d);
    plan.role[d - first] = FacetRole::handed_over;
  }
}

double ContactForceField::wall_reach_of(std::uint32_t i, std::uint32_t w) const noexcept {
  return wall_reach(table_.law(props_.material[i], setup_.walls[w].material), props_.radius[i],
                    props_.effect_radius[i]);
}

double ContactForceField::pack(const KinematicState& state) {
  const double t = state.time;
  const auto n = static_cast<std::int64_t>(packed_.size());
  const double* position = state.position.data();
  const double* built = built_position_.data();
  const double* offset = wrap_offset_.size() > 0 ? wrap_offset_.data() : nullptr;
  const double* h = half_reach_.data();
  PackedSphere* out = packed_.data();
  double* force = force_.data();
  double* torque = torque_.data();
  const int threads = std::max(setup_.threads, 1);
  double worst = parallel_max(threads, n, 0.0, [&](std::int64_t i) {
    double x = position[3 * i];
    double y = position[3 * i + 1];
    double z = position[3 * i + 2];
    if (offset != nullptr) {
      x -= offset[3 * i];
      y -= offset[3 * i + 1];
      z -= offset[3 * i + 2];
    }
    out[i] = {x, y, z, h[i]};
    const double dx = x - built[3 * i];
    const double dy = y - built[3 * i + 1];
    const double dz = z - built[3 * i + 2];
    // The evaluation's sums start from zero (cleared here, in the same pass over the spheres).
    for (int k = 0; k < 3; ++k) {
      force[3 * i + k] = 0.0;
      torque[3 * i + k] = 0.0;
    }
    return dx * dx + dy * dy + dz * dz;
  });
  return pack_motions(t, worst);
}

double ContactForceField::pack_motions(double t, double worst) {
  if (setup_.motions.empty()) return worst;
  for (std::size_t m = 0; m < setup_.motions.size(); ++m) {
    motion_position_[m] = setup_.motions[m].position(t);
    motion_velocity_[m] = setup_.motions[m].velocity(t);
  }
  // A sphere under prescribed motion is where its motion says, whatever the integrator did.
  const bool wrapped = wrap_offset_.size() > 0;
  for (std::size_t m = 0; m < setup_.motions.size(); ++m) {
    const std::uint32_t i = setup_.motions[m].particle;
    Vec3 x = motion_position_[m];
    if (wrapped) x -= wrap_offset_.col(i);
    packed_[i] = {x[0], x[1], x[2], half_reach_[i]};
    worst = std::max(worst, (x - built_position_.col(i)).squaredNorm());
  }
  return worst;
}

double ContactForceField::kick_drift_pack(KinematicState& state, const Accelerations& acc, double kick,
                                          double drift, bool rotation) {
  state.time += drift;
  const auto n = static_cast<std::int64_t>(packed_.size());
  double* const x = state.position.data();
  double* const u = state.velocity.data();
  double* const w = state.angular_velocity.data();
  // a and α: as stored by the last step, or, when it owes its closing kick, derived from the
  // forces it committed exactly as its accelerations' pass derived them (zero when fixed).
  const bool derive = owed_.active;
  const double close = owed_.kick;
  // With the weights owed as well, the committed forces lack m g, added here as the field pass
  // would have added it (f + m g, then divided by m).
  const bool add_weights = derive && owed_.weights;
  const double g0 = setup_.fields.gravity[0];
  const double g1 = setup_.fields.gravity[1];
  const double g2 = setup_.fields.gravity[2];
  const double* const stored_a = derive ? nullptr : acc.linear.data();
  const double* const stored_alpha = derive ? nullptr : acc.angular.data();
  const double* const committed_f = committed_force_.data();
  const double* const committed_t = committed_torque_.data();
  const double* const inverse_inertia = props_.inverse_inertia.data();
  const std::uint8_t* const fixed = props_.fixed.data();
  const double* const built = built_position_.data();
  const double* const offset = wrap_offset_.size() > 0 ? wrap_offset_.data() : nullptr;
  const double* const h = half_reach_.data();
  PackedSphere* const out = packed_.data();
  double* const force = force_.data();
  double* const torque = torque_.data();
  const bool gravity_only = setup_.fields.gravity_only();
  const int threads = std::max(setup_.threads, 1);
  // One component of one sphere: the owed closing kick and the opening kick of its velocity and
  // spin, then the drift; returns the new coordinate.
  const auto advance = [=](std::int64_t e, double a, double alpha, bool mobile) {
    double v = u[e];
    if (derive) v += close * a;
    v += kick * a;
    u[e] = v;
    if (rotation) {
      double spin = w[e];
      if (derive) spin += close * alpha;
      w[e] = spin + kick * alpha;
    }
    double p = x[e];
    if (mobile) {
      p += drift * v;
      x[e] = p;
    }
    return p;
  };
  // Balanced chunks, not a static split: on two cores of unequal speed the faster takes on more.
  const double worst = balanced_max(threads, n, kSphereShare, 0.0, [=, this](std::int64_t i) {
    // Component by component in scalars: with the three as small arrays, GCC kept them on the
    // stack and stored and reloaded them in mixed widths, stalling on store forwarding.
    const std::int64_t c = 3 * i;
    const bool mobile = fixed[i] == 0;
    double a0 = 0.0, a1 = 0.0, a2 = 0.0;
    double b0 = 0.0, b1 = 0.0, b2 = 0.0;
    if (!derive) {
      a0 = stored_a[c];
      a1 = stored_a[c + 1];
      a2 = stored_a[c + 2];
      b0 = stored_alpha[c];
      b1 = stored_alpha[c + 1];
      b2 = stored_alpha[c + 2];
    } else if (mobile) {
      // As the accelerations' pass derived them from these forces (zero when fixed).
      const double m = inertia_mass(i, gravity_only);
      double f0 = committed_f[c];
      double f1 = committed_f[c + 1];
      double f2 = committed_f[c + 2];
      if (add_weights) {
        f0 += m * g0;
        f1 += m * g1;
        f2 += m * g2;
      }
      a0 = f0 / m;
      a1 = f1 / m;
      a2 = f2 / m;
      b0 = inverse_inertia[i] * committed_t[c];
      b1 = inverse_inertia[i] * committed_t[c + 1];
      b2 = inverse_inertia[i] * committed_t[c + 2];
    }
    double px = advance(c, a0, b0, mobile);
    double py = advance(c + 1, a1, b1, mobile);
    double pz = advance(c + 2, a2, b2, mobile);
    if (offset != nullptr) {
      px -= offset[c];
      py -= offset[c + 1];
      pz -= offset[c + 2];
    }
    out[i] = {px, py, pz, h[i]};
    // The evaluation's sums start from zero (cleared here, in the same pass over the spheres).
    for (int k = 0; k < 3; ++k) {
      force[c + k] = 0.0;
      torque[c + k] = 0.0;
    }
    const double dx = px - built[c];
    const double dy = py - built[c + 1];
    const double dz = pz - built[c + 2];
    return dx * dx + dy * dy + dz * dz;
  });
  owed_.active = false;
  return pack_motions(state.time, worst);
}

bool ContactForceField::verlet_step(KinematicState& state, Accelerations& acc, double dt, bool rotation) {
  // An owed kick belongs to the same scheme: the rotation flag cannot change between steps.
  double worst = 0.0;
  {
    const ScopedSeconds timer(timing_.other);
    worst = kick_drift_pack(state, acc, 0.5 * dt, dt, rotation);
  }
  weigh(0.5, 0.5);
  // Forces see v(t + Δt/2), as in LAMMPS; the closing half kick rides on the last pass, or is owed.
  if (defer_close_) {
    // Its field pass would only add the weights: the next opening pass adds them instead.
    const bool weights = weights_may_be_owed();
    evaluate_packed(state, dt, nullptr, true, FoldedKick{}, worst, weights);
    owed_ = {true, 0.5 * dt, rotation, weights};
    ++deferred_kicks_;
    if (weights) ++deferred_weights_;
  } else {
    evaluate_packed(state, dt, &acc, true,
                    FoldedKick{state.velocity.data(), state.angular_velocity.data(), 0.5 * dt, rotation}, worst);
  }
  return true;
}

void ContactForceField::store_and_kick(Accelerations* out, const FoldedKick& kick, Eigen::Index c, const Vec3& a,
                                       const Vec3& alpha) noexcept {
  if (out != nullptr) {
    out->linear.col(c) = a;
    out->angular.col(c) = alpha;
  }
  if (kick.velocity == nullptr) return;
  double* u = kick.velocity + 3 * c;
  for (Eigen::Index k = 0; k < 3; ++k) u[k] += kick.kick * a[k];
  if (!kick.rotation) return;
  double* w = kick.angular_velocity + 3 * c;
  for (Eigen::Index k = 0; k < 3; ++k) w[k] += kick.kick * alpha[k];
}

void ContactForceField::settle(KinematicState& state, Accelerations& acc) {
  if (!owed_.active) return;
  const auto n = static_cast<Eigen::Index>(packed_.size());
  acc.linear.resize(3, n);
  acc.angular.resize(3, n);
  const bool gravity_only = setup_.fields.gravity_only();
  // The kick the last step's accelerations' pass would have given.
  const FoldedKick kick{state.velocity.data(), state.angular_velocity.data(), owed_.kick, owed_.rotation};
  for (Eigen::Index c = 0; c < n; ++c) {
    if (props_.fixed[static_cast<std::size_t>(c)] != 0) {
      store_and_kick(&acc, kick, c, Vec3::Zero(), Vec3::Zero());
      continue;
    }
    // The owed field pass: the committed forces become what that pass would have left.
    if (owed_.weights) committed_force_.col(c) += setup_.fields.weight(props_.mass[c]);
    const SphereAcceleration a = acceleration_of(committed_force_, committed_torque_, c, gravity_only);
    store_and_kick(&acc, kick, c, a.linear, a.angular);
  }
  owed_.active = false;
}

void ContactForceField::build_wall_list(double time, std::span<const std::uint32_t> new_of_old) {
  wall_list_.build(
      packed_, props_.fixed, setup_.walls, time, setup_.neighbors.skin,
      [this](std::uint32_t i, std::uint32_t w) { return wall_reach_of(i, w); }, extended_history_,
      new_of_old);
}

void ContactForceField::rebuild(const KinematicState& state, std::span<const std::uint32_t> new_of_old) {
  const ScopedSeconds timer(timing_.neighbor_build);
  const int threads = std::max(setup_.threads, 1);
  const auto n = static_cast<std::int64_t>(packed_.size());
  if (setup_.box.any()) {
    // Wrap: images are chosen afresh at every build, so centres lie in the box, give or take
    // the half skin they may move before the next build. A centre is where the last packing
    // took it from: the state, or the sphere's prescribed motion (as pack_motions).
    const Vec3 length = setup_.box.length();
    parallel_for(threads, n, [&](std::int64_t i) {
      const std::int32_t m = motion_of_.empty() ? -1 : motion_of_[static_cast<std::size_t>(i)];
      const Vec3 x = m >= 0 ? motion_position_[static_cast<std::size_t>(m)] : Vec3(state.position.col(i));
      const auto image = setup_.box.image_of(x);
      double p[3];
      for (int k = 0; k < 3; ++k) {
        const double offset = setup_.box.periodic[static_cast<std::size_t>(k)] ? image[static_cast<std::size_t>(k)] * length[k] : 0.0;
        wrap_offset_(k, i) = offset;
        p[k] = x[k] - offset;
      }
      packed_[static_cast<std::size_t>(i)] = {p[0], p[1], p[2], half_reach_[i]};
    });
  }
  list_.build({packed_, still_, classes_.of, classes_.max_half_reach, &setup_.box,
               setup_.neighbors.skin, threads, extended_history_},
              new_of_old);
  build_wall_list(state.time, new_of_old);
  parallel_for(threads, n, [&](std::int64_t i) {
    const PackedSphere& s = packed_[static_cast<std::size_t>(i)];
    built_position_.col(i) = Vec3(s.x, s.y, s.z);
  });
  built_time_ = state.time;
  built_ = true;
}

void ContactForceField::evaluate(const KinematicState& state, double elapsed, Accelerations& out,
                                 bool commit, const FoldedKick& kick) {
  if (owed_.active) throw std::logic_error("ContactForceField: an evaluation while a closing kick is owed (settle first)");
  double worst = 0.0;
  {
    const ScopedSeconds timer(timing_.other);
    worst = pack(state);
  }
  evaluate_packed(state, elapsed, &out, commit, kick, worst);
}

void ContactForceField::evaluate_packed(const KinematicState& state, double elapsed, Accelerations* out,
                                        bool commit, const FoldedKick& kick, double worst, bool owe_weights) {
  const double half_skin = 0.5 * setup_.neighbors.skin;
  double wall_travel = 0.0;
  for (const Wall& w : setup_.walls) {
    wall_travel = std::max(wall_travel, w.velocity.norm() * std::abs(state.time - built_time_));
  }
  // Verlet criterion (thesis B.2): rebuild once some sphere or wall has moved half the skin.
  if (!built_ || worst > half_skin * half_skin || wall_travel > half_skin) rebuild(state, {});
  if (commit && !observations_.empty()) {
    const ScopedSeconds timer(timing_.other);
    observe(state, elapsed);
  }
  if (setup_.track_energy) {
    const auto cols = static_cast<Eigen::Index>(packed_.size());
    damping_force_.setZero(3, cols);
    field_force_.setZero(3, cols);
  }
  {
    const ScopedSeconds timer(timing_.pair_loop);
    run_pairs(state, elapsed, commit);
  }
  if (!owe_weights) {
    const ScopedSeconds timer(timing_.sphere_loop);
    run_walls_and_fields(state, elapsed, out, commit, kick);
  }
  if (setup_.track_energy) {
    // Unstated weights: the trapezoid rule over commits (a scheme that books no exact work).
    const bool stated = weight_now_ >= 0.0;
    add_weighted_forces(stated ? weight_now_ : (commit ? 0.5 : 0.0), stated ? weight_next_ : (commit ? 0.5 : 0.0));
    weight_now_ = -1.0;
  }
  if (!commit) return;
  std::swap(force_, committed_force_);
  std::swap(torque_, committed_torque_);
  ledger_.elastic = totals_.elastic;
  ledger_.cohesive = totals_.cohesive;
  // Energy a removed wall took away is work of the boundary, not an integration error.
  ledger_.boundary_work -= totals_.removed;
  potential_booked_ -= totals_.removed;
  ledger_.dissipated_friction += totals_.friction;
  ledger_.dissipated_adhesion += totals_.adhesion;
  ledger_.dissipated_plastic += totals_.plastic;
  ledger_.stiffness_change += totals_.stiffness;
}

void ContactForceField::weigh(double now, double next) noexcept {
  weight_now_ = now;
  weight_next_ = next;
}

void ContactForceField::add_weighted_forces(double now, double next) {
  const auto add = [&](WorkSums& s, double w) {
    if (w == 0.0) return;
    s.force += w * force_;
    s.torque += w * torque_;
    s.damping += w * damping_force_;
    s.field += w * field_force_;
    s.wall_power += w * totals_.wall_power;
    s.wall_damping_power += w * totals_.wall_damping_power;
  };
  add(step_sums_, now);
  add(next_sums_, next);
}

void ContactForceField::restart_work(double start_weight) {
  const auto cols = static_cast<Eigen::Index>(packed_.size());
  step_sums_.clear(cols);
  next_sums_.clear(cols);
  weigh(start_weight, 0.0);  // the step "under way" is the first one
}

void ContactForceField::reset_potential(double gravitational) noexcept {
  potential_booked_ = ledger_.elastic + ledger_.cohesive + gravitational;
  lost_booked_ = ledger_.booked_losses();
}

void ContactForceField::book_step(const Vec3Array& velocity_before, const Vec3Array& angular_before,
                                  const KinematicState& after, double dt, bool rotation,
                                  double gravitational) noexcept {
  if (!setup_.track_energy) return;
  // Work of each force over the step: its weighted sum over the evaluations times the mean of
  // the velocities at the step's ends. For a scheme that states its weights this is exactly the
  // change of ½mu² + ½Iω² the forces on a mobile sphere cause: u_{n+1} − u_n = Δt Σ w F/m.
  double mobile = 0.0;   // all forces on mobile spheres
  double driven = 0.0;   // forces on driven (or frozen) spheres, torques on spheres whose spin is held
  double damping = 0.0;  // dashpots, on every sphere
  double field = 0.0;    // drag, pressure gradient, pull
  const WorkSums& s = step_sums_;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(packed_.size()); ++i) {
    const Vec3 u = 0.5 * (velocity_before.col(i) + after.velocity.col(i));
    const Vec3 w = 0.5 * (angular_before.col(i) + after.angular_velocity.col(i));
    damping += s.damping.col(i).dot(u);
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) {
      driven += s.force.col(i).dot(u) + s.torque.col(i).dot(w);
      continue;
    }
    mobile += s.force.col(i).dot(u);
    // With rotation integrated the torques change ½Iω²; held, ω acts as a prescribed spin whose
    // driver takes the torques' work.
    if (rotation) {
      mobile += s.torque.col(i).dot(w);
    } else {
      driven += s.torque.col(i).dot(w);
    }
    field += s.field.col(i).dot(u);
  }
  // A moving wall works on its contacts with F·v_wall; the dashpots' own work is on the
  // relative motion, so the walls' share leaves their sum.
  const double dashpots = (damping - s.wall_damping_power) * dt;  // ≤ 0 for a passive dashpot
  const double boundary = (s.wall_power - driven) * dt;
  const double fluid = field * dt;
  ledger_.dissipated_damping -= dashpots;
  ledger_.fluid_work += fluid;
  ledger_.boundary_work += boundary;
  // What is left is the work of springs, cohesion, friction and weight: what they should have
  // stored or dissipated instead; the difference is the energy the integration created.
  const double rest = mobile * dt - fluid - boundary - dashpots;
  const double potential = ledger_.elastic + ledger_.cohesive + gravitational;
  const double lost = ledger_.booked_losses();
  ledger_.integration_error += rest + (potential - potential_booked_) + (lost - lost_booked_);
  potential_booked_ = potential;
  lost_booked_ = lost;
  std::swap(step_sums_, next_sums_);
  next_sums_.clear(static_cast<Eigen::Index>(packed_.size()));
}

void ContactForceField::run_pairs(const KinematicState& state, double elapsed, bool commit) {
  const SlabPartition& slabs = list_.slabs();
  const std::uint32_t count = slabs.count();
  slab_totals_.assign(count, EnergyTotals{});
  const PairLoopInput in{packed_.data(),
                         state.velocity.data(),
                         state.angular_velocity.data(),
                         contact_spheres_.data(),
                         props_.material.data(),
                         setup_.motions.empty() ? nullptr : motion_of_.data(),
                         motion_velocity_.data(),
                         &table_,
                         setup_.pair_lever_arm,
                         elapsed,
                         commit,
                         setup_.track_energy,
                         setup_.track_energy ? damping_force_.data() : nullptr};
  double* force = force_.data();
  double* torque = torque_.data();
  const auto run_slab = [&](std::uint32_t s) {
    slab_totals_[s] = run_pair_loop(in, list_, s, force, torque);
  };

  const int threads = std::max(setup_.threads, 1);
  if (count == 1) {
    run_slab(0);
  } else {
    // Even slabs, then odd ones: two slabs of one colour never share a sphere. Each thread starts
    // on the run of slabs a static split gives it, the same every step, and so on the spheres the
    // opening pass gives it (slab-major order): handing slabs out one by one moved them between
    // threads from step to step and with them their spheres' cache lines (2 threads: loop time
    // ×0.65–0.77). A thread done with its run takes slabs from the far end of the other's, so a
    // core the host slows does not hold the faster one at the barrier (docs/performance.md).
    for (std::uint32_t colour = 0; colour < 2; ++colour) {
      const auto half = static_cast<std::int64_t>((count - colour + 1) / 2);
      balanced_for(threads, half, std::int64_t{1},
                   [&](std::int64_t h) { run_slab(colour + 2 * static_cast<std::uint32_t>(h)); });
    }
  }
  if (commit) list_.finish_commit();
  totals_ = EnergyTotals{};
  for (const EnergyTotals& t : slab_totals_) totals_ += t;
}

void ContactForceField::run_walls_and_fields(const KinematicState& state, double elapsed,
                                             Accelerations* out, bool commit, const FoldedKick& kick) {
  const auto n = static_cast<std::uint32_t>(packed_.size());
  const auto cols = static_cast<Eigen::Index>(n);
  if (out != nullptr) {
    out->linear.resize(3, cols);
    out->angular.resize(3, cols);
  }
  const bool track = setup_.track_energy;
  // The energy sums are grouped by kSphereChunk spheres, whatever the thread count; without them
  // (no ledger: every sum stays zero) the threads share out chunks of kSphereShare, which split
  // 10,000 spheres evenly where three chunks of 4,096 could not.
  const auto chunk_size = track ? kSphereChunk : static_cast<std::uint32_t>(kSphereShare);
  const std::uint32_t chunks = std::max<std::uint32_t>(1, (n + chunk_size - 1) / chunk_size);
  chunk_totals_.assign(chunks, EnergyTotals{});
  if (!setup_.meshes.empty() && mesh_plans_.size() < chunks) mesh_plans_.resize(chunks);
  chunk_totals_[0] = totals_;  // the running sums continue from the pair loop's
  const std::span<WallEntry> wall_entries = wall_list_.entries();
  const std::span<ExtendedHistory> wall_ext = wall_list_.extended();
  const WallLeverArm lever = setup_.wall_lever_arm;
  const double t_now = state.time;
  const int threads = std::max(setup_.threads, 1);
  const bool gravity_only = setup_.fields.gravity_only();

  const bool finishes = out != nullptr || kick.velocity != nullptr;
  balanced_for(threads, chunks, 1U, [&](std::uint32_t chunk) {
    EnergyTotals& sums = chunk_totals_[chunk];
    const std::uint32_t end = std::min(n, (chunk + 1) * chunk_size);
    for (std::uint32_t i = chunk * chunk_size; i < end; ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      if (props_.fixed[i] != 0) {
        if (finishes) store_and_kick(out, kick, c, Vec3::Zero(), Vec3::Zero());
        continue;
      }
      // Sphere–wall contacts: the wall is an infinite-mass partner (m* = m, R* = r).
      const std::uint32_t wall_begin = wall_list_.begin(i);
      const std::uint32_t wall_end = wall_list_.begin(i + 1);
      if (wall_begin < wall_end) {
        const SphereState p = sphere(state, i);
        MeshPlan* plan = nullptr;
        if (!mesh_plans_.empty() && plan_mesh_contacts(i, p, t_now, mesh_plans_[chunk])) plan = &mesh_plans_[chunk];
        for (std::uint32_t k = wall_begin; k < wall_end; ++k) {
          WallEntry& e = wall_entries[k];
          const Wall& wall = setup_.walls[e.wall];
          ContactGeometry g = wall_geometry(p, wall, t_now, lever);
          const bool removed = !wall.present(t_now);
          const double reach = wall_reach_of(i, e.wall);
          const FacetRole role = plan != nullptr ? plan->role[k - wall_begin] : FacetRole::other;
          const bool skipped = role == FacetRole::skipped || role == FacetRole::handed_over;
          if (removed || skipped || g.distance > reach) {
            // A spring another facet continues (MeshPlan) neither ends nor is booked here.
            if (commit && track && e.active != 0 && role != FacetRole::handed_over) {
              // A contact of the last commit that ends here. Beyond reach, the ledger books what its
              // springs still held (the evaluation adds no force: nothing acts there); under a
              // removed wall, what they held leaves with the wall. A mesh facet whose contact
              // passes to a neighbour ends as if its sphere had left: placed beyond reach.
              if (skipped) g = beyond_reach(g, p, reach);
              const ContactOutcome o = evaluate_contact(table_.law(props_.material[i], wall.material), g,
                                                        assemble(e.slip, e.active, wall_ext, k), elapsed);
              if (removed && o.interacting) sums.removed += o.elastic_energy + o.cohesive_energy;
              if (!removed && !o.interacting) add_energies(sums, o);
            }
            if (commit) e.active = 0;
            continue;
          }
          const PairLaw& law = table_.law(props_.material[i], wall.material);
          const ContactOutcome o = evaluate_contact(law, g,
                                                    role == FacetRole::continues ? plan->history[k - wall_begin]
                                                                                 : assemble(e.slip, e.active, wall_ext, k),
                                                    elapsed);
          if (!o.interacting) {
            if (commit) e.active = 0;
            if (track) add_energies(sums, o);  // a neck that broke, springs that let go
            continue;
          }
          force_.col(c) += o.force_on_p;
          torque_.col(c) += o.torque_on_p;
          if (track) {
            add_energies(sums, o);
            damping_force_.col(c) += o.damping_force * g.normal;
            sums.wall_power += o.force_on_p.dot(wall.velocity);
            sums.wall_damping_power += o.damping_force * g.normal.dot(wall.velocity);
          }
          if (commit) store(e, wall_ext, k, o.history);
        }
      }
      // External fields and accelerations of the mobile spheres.
      if (gravity_only) {
        force_.col(c) += setup_.fields.weight(props_.mass[c]);
      } else {
        const FieldInput in{state.position.col(c), state.velocity.col(c), props_.radius[c],
                            props_.density[c], props_.mass[c], t_now};
        force_.col(c) += setup_.fields.force(in);
        if (track) field_force_.col(c) = setup_.fields.work_force(in);
      }
      // With the closing kick owed, kick_drift_pack derives a and α from these forces instead.
      if (finishes) {
        const SphereAcceleration a = acceleration_of(force_, torque_, c, gravity_only);
        store_and_kick(out, kick, c, a.linear, a.angular);
      }
    }
  });
  totals_ = EnergyTotals{};
  for (const EnergyTotals& t : chunk_totals_) totals_ += t;
}

void ContactForceField::trial(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, false, FoldedKick{});
}

void ContactForceField::commit(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, true, FoldedKick{});
}

void ContactForceField::commit_and_kick(KinematicState& state, double elapsed, Accelerations& out, double kick,
                                        bool rotation) {
  evaluate(state, elapsed, out, true,
           FoldedKick{state.velocity.data(), state.angular_velocity.data(), kick, rotation});
}

void ContactForceField::watch(const std::vector<ContactObservation>& contacts) {
  observations_ = contacts;
}

void ContactForceField::observe(const KinematicState& state, double elapsed) {
  for (auto& o : observations_) {
    o.normal_force = 0.0;
    o.interacting = false;
    if (o.wall) {
      const Wall& wall = setup_.walls[o.q];
      const ContactGeometry g = wall_geometry(sphere(state, o.p), wall, state.time, setup_.wall_lever_arm);
      o.overlap = g.overlap;
      if (props_.fixed[o.p] != 0 || !wall.present(state.time) || g.distance > wall_reach_of(o.p, o.q)) continue;
      if (!facet_counts(setup_.walls, setup_.meshes, o.q, sphere(state, o.p).position, state.time)) continue;
      const std::int64_t k = wall_list_.find(o.p, o.q);
      const ContactHistory h = k >= 0 ? wall_list_.history(static_cast<std::size_t>(k)) : ContactHistory{};
      const ContactOutcome c = evaluate_contact(table_.law(props_.material[o.p], wall.material), g, h, elapsed);
      o.normal_force = c.interacting ? c.normal_force : 0.0;
      o.interacting = c.interacting;
      continue;
    }
    bool p_owns = true;
    const std::int64_t k = list_.find(o.p, o.q, p_owns);
    const std::uint32_t owner = p_owns ? o.p : o.q;
    const std::uint32_t partner = p_owns ? o.q : o.p;
    const SphereState p = sphere(state, owner);
    SphereState q = sphere(state, partner);
    if (k >= 0) {
      q.position -= list_.shift(list_.partners()[static_cast<std::size_t>(k)] >> kPartnerBits);
    } else {
      q.position -= setup_.box.minimum_image_shift(p.position - q.position);
    }
    const ContactGeometry g = pair_geometry(p, q, setup_.pair_lever_arm);
    o.overlap = g.overlap;
    if (k < 0) continue;  // not listed: beyond reach
    const ContactOutcome c = evaluate_contact(table_.law(props_.material[owner], props_.material[partner]), g,
                                              list_.history(static_cast<std::size_t>(k)), elapsed);
    o.normal_force = c.interacting ? c.normal_force : 0.0;
    o.interacting = c.interacting;
  }
}

ContactHistory ContactForceField::pair_history(std::uint32_t i, std::uint32_t j) const noexcept {
  bool i_owns = true;
  const std::int64_t k = list_.find(i, j, i_owns);
  if (k < 0) return {};
  ContactHistory h = list_.history(static_cast<std::size_t>(k));
  if (!i_owns) h.tangential_slip = -h.tangential_slip;
  return h;
}

std::size_t ContactForceField::interacting_pairs() const noexcept {
  std::size_t count = 0;
  for (const std::uint32_t c : list_.contacts()) count += c != kNoContact ? 1 : 0;
  return count;
}

std::size_t ContactForceField::touching_pairs() const noexcept {
  std::size_t count = 0;
  const std::span<const std::uint32_t> contacts = list_.contacts();
  const std::span<const PartnerCode> partners = list_.partners();
  const std::span<const ExtendedHistory> ext = list_.extended();
  for (std::uint32_t i = 0; i < list_.sphere_count(); ++i) {
    for (std::uint32_t k = list_.begin(i); k < list_.begin(i + 1); ++k) {
      if (contacts[k] == kNoContact) continue;
      if (!ext.empty() && ext[contacts[k]].attached != 0) {
        ++count;
        continue;
      }
      const std::uint32_t j = partners[k] & kPartnerMask;
      const Vec3& shift = list_.shift(partners[k] >> kPartnerBits);
      const Vec3 d(packed_[i].x - (packed_[j].x - shift[0]), packed_[i].y - (packed_[j].y - shift[1]),
                   packed_[i].z - (packed_[j].z - shift[2]));
      if (contact_spheres_[i].radius + contact_spheres_[j].radius - d.norm() > 0.0) ++count;
    }
  }
  return count;
}

std::vector<std::uint32_t> ContactForceField::spatial_order(const KinematicState& state) const {
  const double cell = 2.0 * classes_.max_half_reach.front() + setup_.neighbors.skin;
  const std::span<const std::uint32_t> slabs = list_.slabs().all();
  return morton_order(state.position, setup_.box, cell, slabs.size() == packed_.size() ? slabs : std::span<const std::uint32_t>{});
}

std::size_t ContactForceField::bytes() const noexcept {
  const auto matrix = [](const Vec3Array& a) { return static_cast<std::size_t>(a.size()) * sizeof(double); };
  return motion_of_.capacity() * sizeof(std::int32_t) + still_.capacity() + classes_.of.capacity() +
         contact_spheres_.capacity() * sizeof(ContactSphere) +
         static_cast<std::size_t>(half_reach_.size()) * sizeof(double) +
         packed_.capacity() * sizeof(PackedSphere) + matrix(wrap_offset_) +
         matrix(built_position_) + matrix(force_) + matrix(torque_) + matrix(committed_force_) +
         matrix(committed_torque_) + matrix(damping_force_) + matrix(field_force_) +
         4 * (matrix(step_sums_.force) + matrix(next_sums_.force)) + list_.bytes() + wall_list_.bytes() +
         (slab_totals_.capacity() + chunk_totals_.capacity()) * sizeof(EnergyTotals);
}

void ContactForceField::permute(std::span<const std::uint32_t> order, const KinematicState& state) {
  const std::vector<std::uint32_t> new_of_old = inverse_permutation(order);
  const auto reorder = [&order](auto& values) {
    const auto old = values;
    for (std::size_t k = 0; k < order.size(); ++k) values[k] = old[order[k]];
  };
  reorder(motion_of_);
  reorder(still_);
  reorder(classes_.of);
  reorder(contact_spheres_);
  if (wrap_offset_.size() > 0) dem::permute(wrap_offset_, order);
  {
    const ScalarArray old = half_reach_;
    for (std::size_t k = 0; k < order.size(); ++k) {
      half_reach_[static_cast<Eigen::Index>(k)] = old[static_cast<Eigen::Index>(order[k])];
    }
  }
  dem::permute(committed_force_, order);
  dem::permute(committed_torque_, order);
  for (WorkSums* w : {&step_sums_, &next_sums_}) {
    for (Vec3Array* a : w->arrays()) {
      if (a->cols() == static_cast<Eigen::Index>(order.size())) dem::permute(*a, order);
    }
  }
  for (PrescribedMotion& m : setup_.motions) m.particle = new_of_old[m.particle];
  if (!built_ || list_.sphere_count() != packed_.size()) {
    pack(state);
    rebuild(state, new_of_old);
    return;
  }
  // The list is renumbered, not searched again: it stays valid against the (renumbered) centres
  // of its build, and a reorder right after a build — where Simulation places them — gives
  // exactly the list a new search would.
  const ScopedSeconds timer(timing_.neighbor_build);
  dem::permute(built_position_, order);
  pack(state);
  list_.permute(packed_, setup_.box, new_of_old, std::max(setup_.threads, 1));
  build_wall_list(state.time, new_of_old);
}

}  // namespace dem
