// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace cases {

/// One mixed property of a material pair and where its value came from.
struct MixedValue {
  std::string key;
  double value;
  std::string origin;  ///< e.g. "harmonic mix" or "[[pairs]] override"
};

/// The mixed properties of one material pair (a ≤ b), for reports (docs/architecture.md, "Materials
/// and mixing").
struct MixedPair {
  std::string material_a;
  std::string material_b;
  std::vector<MixedValue> values;
};

/// Mixed and overridden properties of every material pair of the scene that can meet (two rigid
/// materials cannot), in material order.
std::vector<MixedPair> mixed_pairs(const Scene& scene);

}  // namespace cases
