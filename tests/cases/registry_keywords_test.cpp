// SPDX-License-Identifier: MIT
// The loader reads model keywords from the contact-model registry: every registered sub-model
// must be accepted without the loader naming any of them.
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/contact/registry.hpp"
#include "dem/materials/material_properties.hpp"

namespace registry_keywords_test {

/// A value inside `range` (for filling in every property a sub-model might need).
double value_inside(const dem::ValueRange& range) {
  for (const double candidate : {0.5, 1.0, 2.0, range.min + 1.0, range.min * 2.0}) {
    if (range.contains(candidate)) return candidate;
  }
  return range.max;
}

/// Every property with a material field set on material "a"; pair-only properties set in a
/// [[pairs]] entry, so that any sub-model finds what it needs.
std::string all_properties() {
  std::string material = "[materials.a]\ndensity = 1000.0\n";
  std::string pair;
  for (const auto& spec : dem::property_specs()) {
    const std::string line = fmt::format("{} = {}\n", spec.key, value_inside(spec.range));
    if (spec.material_field != nullptr) {
      material += line;
    } else {
      pair += line;
    }
  }
  if (!pair.empty()) material += "\n[[pairs]]\nmaterials = [\"a\", \"a\"]\n" + pair;
  return material;
}

/// A case choosing `keyword` for `slot` (and `hertz` as the normal model when `slot` is another:
/// every other sub-model works with it, and JKR and DMT need it).
std::string case_with(dem::Slot slot, std::string_view keyword) {
  std::string model = fmt::format("{} = \"{}\"\n", dem::to_string(slot), keyword);
  if (slot != dem::Slot::normal) model += "normal = \"hertz\"\n";
  return "[case]\nname = \"registry\"\n\n[model]\n" + model + "\n" + all_properties() +
         "\n[[particles]]\nradius = 0.01\nmaterial = \"a\"\nposition = [0.0, 0.0, 0.0]\n"
         "\n[integration]\nscheme = \"rk4\"\ntimestep = 1.0e-5\nduration = 1.0e-3\n";
}

/// Keyword the scene chose for `slot`.
const std::string& chosen(const dem::ModelChoice& model, dem::Slot slot) {
  switch (slot) {
    case dem::Slot::normal: return model.normal;
    case dem::Slot::damping: return model.damping;
    case dem::Slot::tangential: return model.tangential;
    case dem::Slot::cohesion: return model.cohesion;
    case dem::Slot::rolling: return model.rolling;
  }
  return model.normal;
}

TEST(CaseLoader, AcceptsEveryRegisteredSubModelKeywordInEverySlot) {
  for (const dem::Slot slot : dem::all_slots()) {
    ASSERT_FALSE(dem::sub_models(slot).empty()) << dem::to_string(slot);
    for (const auto& row : dem::sub_models(slot)) {
      const std::string text = case_with(slot, row.keyword);
      try {
        const cases::Scene scene = cases::load_case_text(text, "registry.toml");
        EXPECT_EQ(chosen(scene.model, slot), row.keyword);
      } catch (const cases::CaseError& e) {
        ADD_FAILURE() << dem::to_string(slot) << " = " << row.keyword << ": " << e.what();
      }
    }
  }
}

TEST(CaseLoader, UnknownModelKeywordListsTheRegistryKeywords) {
  try {
    static_cast<void>(
        cases::load_case_text(case_with(dem::Slot::damping, "no_such_model"), "registry.toml"));
    FAIL() << "no error";
  } catch (const cases::CaseError& e) {
    EXPECT_EQ(e.key(), "model.damping");
    EXPECT_NE(std::string(e.what()).find(dem::sub_model_keywords(dem::Slot::damping)),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
