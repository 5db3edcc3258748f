// SPDX-License-Identifier: MIT
#include "dem/contact/pair_table.hpp"

#include <string>
#include <string_view>

#include "dem/contact/registry.hpp"
#include "dem/core/model_error.hpp"

namespace dem {
namespace {

/// The alternative of `Variant` whose keyword is `keyword`, built from the pair properties.
template <class Variant, std::size_t I = 0>
Variant make_alternative(Slot slot, std::string_view keyword, const PairProperties& p) {
  if constexpr (I == std::variant_size_v<Variant>) {
    throw ModelError("model." + std::string(to_string(slot)),
                     "unknown " + std::string(to_string(slot)) + " model '" +
                         std::string(keyword) + "'");
  } else {
    using Model = std::variant_alternative_t<I, Variant>;
    if (Model::kKeyword == keyword) return Model::from_pair(p);
    return make_alternative<Variant, I + 1>(slot, keyword, p);
  }
}

/// Keyword chosen for `slot` in `choice`.
const std::string& keyword_of(const ModelChoice& choice, Slot slot) {
  switch (slot) {
    case Slot::normal: return choice.normal;
    case Slot::damping: return choice.damping;
    case Slot::tangential: return choice.tangential;
    case Slot::cohesion: return choice.cohesion;
    case Slot::rolling: return choice.rolling;
  }
  return choice.normal;
}

/// Throws ModelError (key "model.<slot>") when a chosen keyword is not in the registry, or when
/// two chosen sub-models cannot work together.
void check_keywords(const ModelChoice& choice) {
  for (const Slot slot : all_slots()) {
    const std::string& keyword = keyword_of(choice, slot);
    if (find_sub_model(slot, keyword) == nullptr) {
      throw ModelError("model." + std::string(to_string(slot)),
                       "unknown " + std::string(to_string(slot)) + " model '" + keyword +
                           "' (known: " + sub_model_keywords(slot) + ")");
    }
  }
  // JKR and DMT are adhesive corrections of Hertz contact mechanics (eq 3.34;
  // docs/physics-cohesion.md).
  if ((choice.cohesion == "jkr" || choice.cohesion == "dmt") && choice.normal != "hertz") {
    throw ModelError("model.cohesion", "cohesion = '" + choice.cohesion +
                                           "' extends Hertz contact mechanics and needs normal = "
                                           "'hertz' (got '" + choice.normal + "')");
  }
}

}  // namespace

PairLaw make_pair_law(const ModelChoice& choice, const PairProperties& properties) {
  check_keywords(choice);
  return PairLaw{
      make_alternative<NormalModel>(Slot::normal, choice.normal, properties),
      make_alternative<DampingModel>(Slot::damping, choice.damping, properties),
      make_alternative<TangentialModel>(Slot::tangential, choice.tangential, properties),
      make_alternative<CohesionModel>(Slot::cohesion, choice.cohesion, properties),
      make_alternative<RollingModel>(Slot::rolling, choice.rolling, properties),
      ContactPolicies{choice.clamp_tensile, choice.friction_limit, choice.jkr_rupture,
                      choice.contact_at_zero_overlap, choice.tangential_history, choice.mindlin_radius,
                      choice.unloaded_slider, choice.adhesive_dashpot, choice.mindlin_form, choice.coulomb_test,
                      choice.constant_torque_form},
  };
}

PairTable::PairTable(const std::vector<MaterialProperties>& materials, const MixingRules& rules,
                     const std::vector<PairOverride>& overrides, const ModelChoice& choice)
    : count_(materials.size()), choice_(choice) {
  check_keywords(choice_);
  properties_.resize(count_ * count_);
  for (std::size_t a = 0; a < count_; ++a) {
    for (std::size_t b = a; b < count_; ++b) {
      const PairProperties mixed = mix_properties(materials[a], materials[b], rules);
      properties_[index(a, b)] = mixed;
      properties_[index(b, a)] = mixed;
    }
  }
  for (const auto& o : overrides) {
    apply_overrides(properties_[index(o.material_a, o.material_b)], o.values);
    properties_[index(o.material_b, o.material_a)] = properties_[index(o.material_a, o.material_b)];
  }
  laws_.reserve(count_ * count_);
  rigid_.reserve(count_);
  for (const auto& m : materials) rigid_.push_back(m.rigid);
  for (std::size_t a = 0; a < count_; ++a) {
    for (std::size_t b = 0; b < count_; ++b) {
      if (!interacts(a, b)) {
        // Two rigid bodies (walls) never touch: no law, and no property is required of the pair.
        laws_.emplace_back();
        continue;
      }
      try {
        laws_.push_back(make_pair_law(choice_, properties_[index(a, b)]));
      } catch (const ModelError& e) {
        throw ModelError(e.key(), std::string(e.what()) + ": missing for the pair " +
                                      materials[a].name + "–" + materials[b].name +
                                      " (set it on both materials or in a [[pairs]] entry)");
      }
    }
  }
}

}  // namespace dem
