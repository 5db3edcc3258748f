// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <vector>

#include "dem/contact/contact_model.hpp"
#include "dem/materials/material_properties.hpp"
#include "dem/materials/mixing.hpp"

namespace dem {

/// The mixed parameters and the contact law of every material pair, built once before a run
/// (docs/architecture.md, "Materials and mixing"). Symmetric: (a, b) and (b, a) are one entry.
class PairTable {
 public:
  /// Mixes every material pair with `rules`, applies `overrides`, and builds each pair's law
  /// from `choice`. Throws ModelError naming the missing or invalid key and the pair.
  PairTable(const std::vector<MaterialProperties>& materials, const MixingRules& rules,
            const std::vector<PairOverride>& overrides, const ModelChoice& choice);

  /// Number of materials.
  [[nodiscard]] std::size_t material_count() const noexcept { return count_; }
  /// Mixed (and overridden) properties of the pair (a, b).
  [[nodiscard]] const PairProperties& properties(std::size_t a, std::size_t b) const noexcept {
    return properties_[index(a, b)];
  }
  /// Contact law of the pair (a, b); a default-constructed law when the pair never interacts.
  [[nodiscard]] const PairLaw& law(std::size_t a, std::size_t b) const noexcept {
    return laws_[index(a, b)];
  }
  /// False for a pair of two rigid materials (walls never touch each other): it has no law.
  [[nodiscard]] bool interacts(std::size_t a, std::size_t b) const noexcept {
    return !(rigid_[a] && rigid_[b]);
  }
  /// The model choice the laws were built from.
  [[nodiscard]] const ModelChoice& choice() const noexcept { return choice_; }

 private:
  [[nodiscard]] std::size_t index(std::size_t a, std::size_t b) const noexcept {
    return a * count_ + b;
  }
  std::size_t count_;
  ModelChoice choice_;
  std::vector<PairProperties> properties_;
  std::vector<PairLaw> laws_;
  std::vector<bool> rigid_;  ///< per material: MaterialProperties::rigid
};

/// Builds a pair's law from its properties; throws ModelError on an unknown keyword
/// (key "model.<slot>") or a missing property.
PairLaw make_pair_law(const ModelChoice& choice, const PairProperties& properties);

}  // namespace dem
