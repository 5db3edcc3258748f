// SPDX-License-Identifier: MIT
// Section readers for the case's identity and its contact model: [case], [model], [mixing],
// [materials.NAME] and [[pairs]].
#include <algorithm>
#include <array>
#include <span>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cases/excerpt.hpp"
#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/names.hpp"
#include "cases/suggestion.hpp"
#include "dem/contact/registry.hpp"
#include "dem/materials/mixing.hpp"

namespace cases::loader {
namespace {

constexpr auto kCaseKeys = std::to_array<std::string_view>({"name", "description", "thesis", "tier"});

constexpr std::array kMixingRules{dem::MixingRule::harmonic, dem::MixingRule::arithmetic,
                                  dem::MixingRule::geometric, dem::MixingRule::min,
                                  dem::MixingRule::max};

/// Keys of [model] that name policies rather than sub-models.
constexpr auto kPolicyKeys = std::to_array<std::string_view>(
    {"clamp_tensile", "friction_limit", "jkr_rupture", "wall_lever_arm", "pair_lever_arm", "tangential_history",
     "mindlin_radius", "unloaded_slider", "adhesive_dashpot", "mindlin_form", "coulomb_test",
     "constant_torque_form"});

/// Reads the optional policy `key` of [model] into `field`: `names` lists its keywords (the
/// admissible values an error names), `parse` maps one to its enumerator, `what` says what it is.
template <class Enum, std::size_t N, class Parse>
void read_policy(const Table& model, std::string_view key, const std::array<std::string_view, N>& names, Parse parse,
                 std::string_view what, Enum& field) {
  if (const auto v = model.find(key)) field = *parse(v->keyword(names, what));
}

/// Reads the named policies of [model] (all optional; docs/case-format.md, the policy table).
void read_policies(const Table& model, dem::ModelChoice& choice) {
  if (const auto v = model.find("clamp_tensile")) choice.clamp_tensile = v->boolean();
  using Names = std::string_view;
  read_policy(model, "friction_limit",
              std::to_array<Names>({"total", "elastic", "elastic_damping", "jkr_shifted", "total_plus_pulloff"}),
              dem::parse_friction_limit, "friction-limit policy", choice.friction_limit);
  read_policy(model, "jkr_rupture", std::to_array<Names>({"displacement", "load"}), dem::parse_jkr_rupture,
              "JKR rupture policy", choice.jkr_rupture);
  read_policy(model, "wall_lever_arm", std::to_array<Names>({"contact_point", "radius", "yade_incident"}),
              dem::parse_wall_lever_arm, "wall lever-arm policy", choice.wall_lever_arm);
  read_policy(model, "pair_lever_arm",
              std::to_array<Names>({"contact_point", "radius", "radius_velocity", "yade_incident"}),
              dem::parse_pair_lever_arm, "pair lever-arm policy", choice.pair_lever_arm);
  read_policy(model, "tangential_history",
              std::to_array<Names>({"project_rescale", "increment_project", "yade_rotate"}),
              dem::parse_tangential_history, "tangential-history rule", choice.tangential_history);
  read_policy(model, "mindlin_radius", std::to_array<Names>({"overlap", "contact_radius"}), dem::parse_mindlin_radius,
              "Mindlin-radius policy", choice.mindlin_radius);
  read_policy(model, "unloaded_slider", std::to_array<Names>({"cap", "zero"}), dem::parse_unloaded_slider,
              "unloaded-slider policy", choice.unloaded_slider);
  read_policy(model, "mindlin_form", std::to_array<Names>({"total", "incremental"}), dem::parse_mindlin_form,
              "Mindlin-form policy", choice.mindlin_form);
  read_policy(model, "coulomb_test", std::to_array<Names>({"total", "spring"}), dem::parse_coulomb_test,
              "Coulomb-test policy", choice.coulomb_test);
  read_policy(model, "constant_torque_form", std::to_array<Names>({"tangent", "projected"}),
              dem::parse_constant_torque_form, "constant-torque form", choice.constant_torque_form);
  read_policy(model, "adhesive_dashpot", std::to_array<Names>({"clamp", "pulloff_cap"}), dem::parse_adhesive_dashpot,
              "adhesive-dashpot policy", choice.adhesive_dashpot);
}

/// The member of `choice` (const or not) holding the keyword of `slot`.
template <class Choice>
auto& keyword_field(Choice& choice, dem::Slot slot) {
  switch (slot) {
    case dem::Slot::normal: return choice.normal;
    case dem::Slot::damping: return choice.damping;
    case dem::Slot::tangential: return choice.tangential;
    case dem::Slot::cohesion: return choice.cohesion;
    case dem::Slot::rolling: return choice.rolling;
  }
  return choice.normal;
}

/// Registry keywords of `slot`.
std::vector<std::string_view> keywords_of(dem::Slot slot) {
  std::vector<std::string_view> out;
  for (const auto& row : dem::sub_models(slot)) out.push_back(row.keyword);
  return out;
}

/// Keyword of every mixing rule.
std::vector<std::string_view> rule_keywords() {
  std::vector<std::string_view> out;
  for (const auto rule : kMixingRules) out.push_back(dem::to_string(rule));
  return out;
}

/// Where a property lives in the raw material values (null for pair-only properties).
constexpr auto kMaterialField = [](const dem::PropertySpec& spec) { return spec.material_field; };
/// Where a property lives in the mixed pair values (null for material-only properties).
constexpr auto kPairField = [](const dem::PropertySpec& spec) { return spec.pair_field; };

/// `first`, then the key of every property that `field_of` finds a field for.
template <class FieldOf>
std::vector<std::string_view> property_keys(std::vector<std::string_view> first, FieldOf field_of) {
  for (const auto& spec : dem::property_specs()) {
    if (field_of(spec) != nullptr) first.push_back(spec.key);
  }
  return first;
}

/// Keys a [mixing] table accepts: properties with both a material and a pair field.
std::vector<std::string_view> mixable_keys() {
  std::vector<std::string_view> out;
  for (const auto& spec : dem::property_specs()) {
    if (spec.material_field != nullptr && spec.pair_field != nullptr) out.push_back(spec.key);
  }
  return out;
}

/// The value of a material or pair property, inside `range`.
double property_value(const Value& value, const dem::ValueRange& range) {
  const double v = value.number();
  if (!range.contains(v)) value.fail(fmt::format("must be in {}, got {}", range.describe(), v));
  return v;
}

/// Warning text for a property that the selected contact model never reads.
std::string unused_property_message(const dem::ModelChoice& choice) {
  return "not used by the selected contact model (" + describe_model(choice) +
         "); it has no effect";
}

/// Reads every property of `table` that `field_of` places in `target`, range-checked; warns
/// about each one the selected contact model never reads.
template <class Target, class FieldOf>
void read_properties(const Table& table, Target& target, FieldOf field_of,
                     const dem::ModelChoice& choice) {
  const auto used = used_properties(choice);
  for (const auto& spec : dem::property_specs()) {
    const auto field = field_of(spec);
    if (field == nullptr) continue;
    if (const auto value = table.find(spec.key)) {
      target.*field = property_value(*value, spec.range);
      if (!used.contains(spec.key)) value->warn(unused_property_message(choice));
    }
  }
}

/// One [materials.NAME] table.
dem::MaterialProperties read_material(const std::string& name, const Value& entry,
                                      const dem::ModelChoice& choice) {
  if (!is_identifier(name, true)) {
    entry.fail(fmt::format("material name '{}' may contain only letters, digits and '_' (at most {} characters)",
                           excerpt(name, kMaxNameLength), kMaxNameLength));
  }
  const Table table = entry.table();
  table.allow_only(property_keys({"density"}, kMaterialField));
  dem::MaterialProperties material;
  material.name = name;
  const Value density = table.require("density");
  material.density = property_value(density, dem::density_range());
  if (material.density > kMaxDensity) {
    density.fail(fmt::format("must be at most {:g} kg/m³ (denser than an atomic nucleus), got {}", kMaxDensity,
                             material.density));
  }
  read_properties(table, material, kMaterialField, choice);
  return material;
}

/// One [[pairs]] entry.
dem::PairOverride read_pair_override(const Table& table, const Scene& scene) {
  table.allow_only(property_keys({"materials"}, kPairField));
  const Value names = table.require("materials");
  const std::vector<Value> items = names.elements();
  if (items.size() != 2) {
    names.fail(fmt::format("expected an array of 2 material names, got {} element{}", items.size(),
                           items.size() == 1 ? "" : "s"));
  }
  dem::PairOverride pair{material_index(items[0], scene), material_index(items[1], scene), {}};
  read_properties(table, pair.values, kPairField, scene.model);
  return pair;
}

}  // namespace

const std::string& slot_keyword(const dem::ModelChoice& choice, dem::Slot slot) {
  return keyword_field(choice, slot);
}

std::set<std::string_view> used_properties(const dem::ModelChoice& choice) {
  std::set<std::string_view> used;
  for (const dem::Slot slot : dem::all_slots()) {
    if (const auto* row = dem::find_sub_model(slot, slot_keyword(choice, slot))) {
      used.insert(row->properties.begin(), row->properties.end());
    }
  }
  // Material-level inputs of derived pair properties.
  if (used.contains("effective_modulus") || used.contains("effective_shear_modulus")) {
    used.insert({"youngs_modulus", "poisson_ratio"});
  }
  if (used.contains("cohesive_stiffness")) used.insert("interaction_ratio");
  return used;
}

std::string describe_model(const dem::ModelChoice& choice) {
  std::string out;
  for (const dem::Slot slot : dem::all_slots()) {
    if (!out.empty()) out += ", ";
    out += fmt::format("{} = {}", dem::to_string(slot), slot_keyword(choice, slot));
  }
  return out;
}

std::size_t material_index(const Value& name, const Scene& scene) {
  const std::string text = name.string();
  if (const auto index = find_material(scene, text)) return *index;
  std::vector<std::string_view> known;
  for (const auto& m : scene.materials) known.push_back(m.name);
  name.fail(fmt::format("unknown material '{}'{} (defined: {})", excerpt(text), did_you_mean(text, known),
                        join(known)));
}

void read_case_section(const Table& root, Scene& scene) {
  const Table section = root.require("case", "table [case]").table();
  section.allow_only(kCaseKeys);
  const Value name = section.require("name");
  scene.name = name.string();
  if (!is_identifier(scene.name, false)) {
    name.fail(
        fmt::format("'{}' may contain only lowercase letters a-z, digits 0-9 and '_' (at most {} characters)",
                    excerpt(scene.name, kMaxNameLength), kMaxNameLength));
  }
  if (const auto v = section.find("description")) scene.description = v->string();
  if (const auto v = section.find("thesis")) scene.thesis_reference = v->string();
  if (const auto v = section.find("tier")) {
    static constexpr auto kTiers = std::to_array<std::string_view>({"fast", "full"});
    scene.tier = *parse_tier(v->keyword(kTiers, "tier"));
  }
}

void read_model(const Table& root, Scene& scene) {
  const Table model = root.require("model", "table [model]").table();
  std::vector<std::string_view> keys;
  for (const dem::Slot slot : dem::all_slots()) keys.push_back(dem::to_string(slot));
  keys.insert(keys.end(), kPolicyKeys.begin(), kPolicyKeys.end());
  model.allow_only(keys);
  read_policies(model, scene.model);
  for (const dem::Slot slot : dem::all_slots()) {
    const std::string_view name = dem::to_string(slot);
    const auto value = slot == dem::Slot::normal ? model.require(name) : model.find(name);
    keyword_field(scene.model, slot) =
        value ? value->keyword(keywords_of(slot), fmt::format("{} model", name)) : "none";
  }
}

void read_mixing(const Table& root, Scene& scene) {
  const auto section = root.find("mixing");
  if (!section) return;
  const Table mixing = section->table();
  mixing.allow_only(mixable_keys());
  const auto used = used_properties(scene.model);
  for (const auto& [key, value] : mixing.entries()) {
    const std::string rule = value.keyword(rule_keywords(), "mixing rule");
    scene.mixing[key] = *dem::parse_mixing_rule(rule);
    if (!used.contains(key)) value.warn(unused_property_message(scene.model));
  }
}

void read_materials(const Table& root, Scene& scene) {
  const Table materials = root.require("materials", "table [materials.NAME]").table();
  const auto entries = materials.entries();
  if (entries.empty()) materials.fail("must define at least one material ([materials.NAME])");
  if (entries.size() > kMaxMaterials) {
    materials.fail(fmt::format("defines {} materials, more than the limit of {}", entries.size(), kMaxMaterials));
  }
  for (const auto& [name, entry] : entries) {
    scene.materials.push_back(read_material(name, entry, scene.model));
  }
}

void read_pairs(const Table& root, Scene& scene) {
  const auto section = root.find("pairs");
  if (!section) return;
  std::map<std::pair<std::size_t, std::size_t>, std::string> seen;  // unordered pair → key
  for (const Value& entry : section->elements()) {
    const Table table = entry.table();
    const dem::PairOverride pair = read_pair_override(table, scene);
    const auto [it, inserted] =
        seen.emplace(std::minmax(pair.material_a, pair.material_b), entry.key());
    if (!inserted) {
      table.fail("materials", fmt::format("the pair {}–{} is already overridden by {}",
                                          scene.materials[pair.material_a].name,
                                          scene.materials[pair.material_b].name, it->second));
    }
    scene.pair_overrides.push_back(pair);
  }
}

}  // namespace cases::loader
