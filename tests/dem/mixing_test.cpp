// SPDX-License-Identifier: MIT
// Mixing rules, pair table symmetry, overrides and missing-parameter errors.
#include <gtest/gtest.h>

#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"
#include "dem/materials/mixing.hpp"

namespace mixing_test {

dem::MaterialProperties material(const char* name, double k, double e) {
  dem::MaterialProperties m;
  m.name = name;
  m.density = 1000.0;
  m.normal_stiffness = k;
  m.restitution = e;
  return m;
}

TEST(MixingRules, AreSymmetricAndIdempotent) {
  for (const auto rule : {dem::MixingRule::harmonic, dem::MixingRule::arithmetic, dem::MixingRule::geometric,
                          dem::MixingRule::min, dem::MixingRule::max}) {
    EXPECT_DOUBLE_EQ(dem::mix_values(rule, 2.0, 8.0), dem::mix_values(rule, 8.0, 2.0));
    EXPECT_EQ(dem::mix_values(rule, 3.7, 3.7), 3.7);
    EXPECT_EQ(dem::parse_mixing_rule(dem::to_string(rule)), rule);
  }
  EXPECT_DOUBLE_EQ(dem::mix_values(dem::MixingRule::harmonic, 2.0, 8.0), 3.2);
  EXPECT_DOUBLE_EQ(dem::mix_values(dem::MixingRule::geometric, 2.0, 8.0), 4.0);
}

TEST(MixingRules, DefaultsAreHarmonicStiffnessAndGeometricRestitution) {
  const auto p = dem::mix_properties(material("a", 1e5, 0.25), material("b", 4e5, 1.0), {});
  EXPECT_DOUBLE_EQ(*p.normal_stiffness, 1.6e5);
  EXPECT_DOUBLE_EQ(*p.restitution, 0.5);
}

TEST(MixingRules, CaseChoiceReplacesTheDefault) {
  const dem::MixingRules rules{{"normal_stiffness", dem::MixingRule::min}};
  const auto p = dem::mix_properties(material("a", 1e5, 0.5), material("b", 4e5, 0.5), rules);
  EXPECT_DOUBLE_EQ(*p.normal_stiffness, 1e5);
}

TEST(PairTable, IsSymmetricAndAppliesOverrides) {
  dem::PairProperties o;
  o.normal_stiffness = 7e5;
  dem::ModelChoice choice;
  choice.damping = "restitution";
  const dem::PairTable t({material("a", 1e5, 0.5), material("b", 4e5, 0.8)}, {}, {{1, 0, o}}, choice);
  EXPECT_DOUBLE_EQ(*t.properties(0, 1).normal_stiffness, 7e5);
  EXPECT_DOUBLE_EQ(*t.properties(1, 0).normal_stiffness, 7e5);
  EXPECT_DOUBLE_EQ(*t.properties(0, 0).normal_stiffness, 1e5);
  EXPECT_DOUBLE_EQ(std::get<dem::LinearNormal>(t.law(1, 0).normal).stiffness, 7e5);
  EXPECT_DOUBLE_EQ(std::get<dem::RestitutionDamping>(t.law(1, 1).damping).restitution, 0.8);
}

TEST(PairTable, MissingPropertyNamesTheKeyAndThePair) {
  dem::MaterialProperties a = material("glass", 1e5, 0.5);
  dem::MaterialProperties b = material("steel", 1e5, 0.5);
  b.restitution.reset();
  dem::ModelChoice choice;
  choice.damping = "restitution";
  try {
    const dem::PairTable t({a, b}, {}, {}, choice);
    FAIL() << "expected ModelError";
  } catch (const dem::ModelError& e) {
    EXPECT_EQ(e.key(), "restitution");
    EXPECT_NE(std::string(e.what()).find("glass–steel"), std::string::npos) << e.what();
  }
}

TEST(PairTable, UnknownKeywordNamesTheSlot) {
  dem::ModelChoice choice;
  choice.normal = "hooke";
  try {
    const dem::PairTable t({material("a", 1e5, 0.5)}, {}, {}, choice);
    FAIL() << "expected ModelError";
  } catch (const dem::ModelError& e) {
    EXPECT_EQ(e.key(), "model.normal");
    EXPECT_NE(std::string(e.what()).find("linear"), std::string::npos) << e.what();
  }
}

}  // namespace
