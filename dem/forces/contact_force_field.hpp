// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/integrators/force_evaluator.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// The state of one watched pair at the last committed evaluation (for traces and metrics).
struct PairObservation {
  std::uint32_t p;
  std::uint32_t q;
  double overlap;        ///< body overlap δ [m] (negative when apart)
  double normal_force;   ///< normal force [N], repulsive positive; 0 when not in contact
  bool in_contact;
};

/// Forces on every sphere from pair contacts and uniform gravity; the ForceEvaluator the
/// integrators call. Holds the committed contact history.
class ContactForceField final : public ForceEvaluator {
 public:
  /// The field for spheres `props` with pair laws `table` and gravity g [m/s²]. Both are
  /// referenced, not copied, and must outlive the field.
  ContactForceField(const ParticleProperties& props, const PairTable& table, const Vec3& gravity);

  void trial(const KinematicState& state, double elapsed, Accelerations& out) override;
  void commit(const KinematicState& state, double elapsed, Accelerations& out) override;

  /// Pairs whose overlap and normal force are recorded at every commit.
  void watch_pairs(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs);
  /// Watched pairs at the last commit, in the order given to watch_pairs.
  [[nodiscard]] const std::vector<PairObservation>& observations() const noexcept {
    return observations_;
  }
  /// Total force on each sphere at the last commit [N] (contacts plus m g on mobile spheres).
  [[nodiscard]] const Vec3Array& forces() const noexcept { return committed_force_; }
  /// Total contact torque on each sphere at the last commit [N·m].
  [[nodiscard]] const Vec3Array& torques() const noexcept { return committed_torque_; }
  /// Committed history of every interacting pair.
  [[nodiscard]] const ContactHistoryTable& history() const noexcept { return history_; }
  /// Elastic energy stored in all contacts at the last commit [J].
  [[nodiscard]] double elastic_energy() const noexcept { return committed_elastic_energy_; }

 private:
  void evaluate(const KinematicState& state, double elapsed, Accelerations& out, bool record);
  void observe(std::uint32_t i, std::uint32_t j, const ContactGeometry& g,
               const ContactOutcome& c);

  const ParticleProperties& props_;
  const PairTable& table_;
  Vec3 gravity_;
  ContactHistoryTable history_;       // committed
  ContactHistoryTable next_history_;  // produced by the latest evaluation
  Vec3Array force_;
  Vec3Array torque_;
  double elastic_energy_ = 0.0;
  Vec3Array committed_force_;
  Vec3Array committed_torque_;
  double committed_elastic_energy_ = 0.0;
  std::vector<PairObservation> observations_;
};

}  // namespace dem
