// SPDX-License-Identifier: MIT
#include "cases/mixed_pairs.hpp"

#include <string>

namespace cases {

std::vector<MixedPair> mixed_pairs(const Scene& scene) {
  std::vector<MixedPair> out;
  const auto& mats = scene.materials;
  for (std::size_t a = 0; a < mats.size(); ++a) {
    for (std::size_t b = a; b < mats.size(); ++b) {
      if (mats[a].rigid && mats[b].rigid) continue;  // two rigid walls never touch
      const dem::PairProperties mixed = dem::mix_properties(mats[a], mats[b], scene.mixing);
      const dem::PairProperties* override_values = nullptr;
      for (const auto& o : scene.pair_overrides) {
        if ((o.material_a == a && o.material_b == b) || (o.material_a == b && o.material_b == a)) {
          override_values = &o.values;
        }
      }
      MixedPair pair{mats[a].name, mats[b].name, {}};
      for (const auto& spec : dem::property_specs()) {
        if (spec.pair_field == nullptr) continue;
        if (override_values != nullptr && (*override_values).*spec.pair_field) {
          pair.values.push_back(
              {std::string(spec.key), *((*override_values).*spec.pair_field), "[[pairs]] override"});
        } else if (const auto& v = mixed.*spec.pair_field) {
          pair.values.push_back({std::string(spec.key), *v,
                                 std::string(dem::to_string(dem::rule_for(scene.mixing, spec))) +
                                     " mix"});
        }
      }
      out.push_back(std::move(pair));
    }
  }
  return out;
}

}  // namespace cases
