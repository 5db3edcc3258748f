// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <unordered_map>

#include "dem/core/vector.hpp"

namespace dem {

/// State a contact carries from step to step. A law receives the committed value and returns the
/// new one; the integrator decides when to commit it (docs/architecture.md, "The contact model").
struct ContactHistory {
  Vec3 tangential_slip = Vec3::Zero();  ///< ς, integrated tangential displacement [m] (eq 3.9)
  Vec3 rolling_slip = Vec3::Zero();     ///< integrated rolling displacement [m]
  double max_overlap = 0.0;             ///< largest overlap of this contact so far [m] (eq 3.20)
  bool attached = false;                ///< a JKR neck has formed and not yet broken
  /// Contact normal at the last evaluation (TangentialHistory::yade_rotate turns ς by its
  /// change); zero for a new contact.
  Vec3 normal = Vec3::Zero();
  /// Tangential stiffness k_t at the last evaluation [N/m], kept by the Mindlin laws (whose k_t
  /// follows the overlap) so that the energy ledger can book what the stiffness change does to
  /// the spring's energy; zero for a new contact, and not kept between steps in runs without a ledger
  /// (unless the model keeps the extended history for another reason).
  double tangential_stiffness = 0.0;
};

/// Key of an unordered particle pair: the lower index in the high 32 bits.
[[nodiscard]] constexpr std::uint64_t pair_key(std::uint32_t i, std::uint32_t j) noexcept {
  const std::uint64_t lo = i < j ? i : j;
  const std::uint64_t hi = i < j ? j : i;
  return (lo << 32U) | hi;
}

/// Contact history of every interacting pair (or particle–wall pair), keyed by `pair_key`.
using ContactHistoryTable = std::unordered_map<std::uint64_t, ContactHistory>;

}  // namespace dem
