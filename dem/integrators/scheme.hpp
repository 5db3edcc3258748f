// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dem/integrators/force_evaluator.hpp"
#include "dem/integrators/scheme_id.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// Counters a scheme keeps for reports.
struct SchemeDiagnostics {
  std::uint64_t force_evaluations = 0;
  std::uint64_t implicit_iterations = 0;
  std::uint64_t unconverged_steps = 0;  ///< implicit steps that hit the iteration limit
  std::uint64_t startup_steps = 0;      ///< steps taken by the RK4 start-up
};

/// A time-integration scheme. Contract of `step`: on entry `acc` holds the committed
/// accelerations at `state`; on exit `state` is advanced by `dt` and `acc` holds the
/// accelerations committed at the new state (the last commit of the step).
class Scheme {
 public:
  virtual ~Scheme() = default;
  /// Advances one step.
  virtual void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) = 0;
  /// Weight of the forces committed before the first step in that step's velocity change
  /// (ForceEvaluator::weigh).
  [[nodiscard]] virtual double start_weight() const noexcept { return 0.5; }
  /// True when the scheme states every evaluation's weight (ForceEvaluator::weigh), so that an
  /// energy ledger's work equals its change of kinetic energy to round-off.
  [[nodiscard]] virtual bool books_work_exactly() const noexcept { return false; }
  /// Number of past states a multi-step scheme needs for an exact start (0 if none).
  [[nodiscard]] virtual std::size_t past_states_needed() const noexcept { return 0; }
  /// Supplies exact past states, most recent (t = −Δt) first; used with StartupPolicy::exact.
  virtual void set_past(const std::vector<KinematicState>& past, ForceEvaluator& f, double dt);
  /// Counters so far.
  [[nodiscard]] const SchemeDiagnostics& diagnostics() const noexcept { return diagnostics_; }
  /// The spheres the scheme advances (a fixed sphere never drifts, whatever its velocity: LAMMPS
  /// `fix freeze` keeps a frozen atom's velocity for its contacts) and the OpenMP threads of
  /// its per-sphere passes. `props` must outlive the scheme.
  void bind(const ParticleProperties& props, int threads) noexcept {
    props_ = &props;
    threads_ = threads < 1 ? 1 : threads;
  }
  /// Follows a reorder of the spheres (place k receives the sphere that was at order[k]): a
  /// scheme that remembers past states reorders them too.
  virtual void permute(std::span<const std::uint32_t> order);

 protected:
  /// True when sphere i is fixed (never drifts); false when unbound.
  [[nodiscard]] bool is_fixed(std::size_t i) const noexcept {
    return props_ != nullptr && props_->fixed[i] != 0;
  }
  SchemeDiagnostics diagnostics_;
  const ParticleProperties* props_ = nullptr;
  int threads_ = 1;
};

/// Creates the scheme `id` with `settings`.
std::unique_ptr<Scheme> make_scheme(SchemeId id, const SchemeSettings& settings);

}  // namespace dem
