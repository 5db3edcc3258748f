// SPDX-License-Identifier: MIT
// Mixing rules, pair table symmetry, overrides, rigid partners and missing-parameter errors.
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

/// An elastic material with E, ν, a friction coefficient and the linear springs.
dem::MaterialProperties elastic(const char* name, double e, double nu, double mu) {
  dem::MaterialProperties m = material(name, 1e5, 0.5);
  m.youngs_modulus = e;
  m.poisson_ratio = nu;
  m.friction = mu;
  m.tangential_stiffness = 3e5;
  m.rolling_stiffness = 2e3;
  m.cohesive_stiffness = 40.0;
  return m;
}

TEST(RigidMixing, DropsTheRigidBodysComplianceFromEStarAndGStar) {
  dem::MaterialProperties glass = elastic("glass", 6.3e10, 0.23, 0.5);
  dem::MaterialProperties wall = elastic("steel", 2.1e11, 0.29, 0.1);
  wall.rigid = true;
  for (const auto& p : {dem::mix_properties(glass, wall, {}), dem::mix_properties(wall, glass, {})}) {
    // Eq 3.13 and 3.25 with the rigid term removed, written out independently.
    EXPECT_DOUBLE_EQ(*p.effective_modulus, 6.3e10 / (1.0 - 0.23 * 0.23));
    EXPECT_DOUBLE_EQ(*p.effective_shear_modulus, 6.3e10 / (2.0 * 1.23) / (2.0 - 0.23));
    // A rigid side is infinitely stiff: the harmonic 2ab/(a + b) tends to 2a for every body spring.
    EXPECT_DOUBLE_EQ(*p.normal_stiffness, 2e5);
    EXPECT_DOUBLE_EQ(*p.tangential_stiffness, 6e5);
    EXPECT_DOUBLE_EQ(*p.rolling_stiffness, 4e3);
    // Surface properties mix as always: the lower friction governs; cohesion is not compliance.
    EXPECT_DOUBLE_EQ(*p.friction, 0.1);
    EXPECT_DOUBLE_EQ(*p.cohesive_stiffness, 40.0);
    EXPECT_DOUBLE_EQ(*p.restitution, 0.5);
  }
  // The same wall without `rigid` mixes both compliances (eq 3.13).
  wall.rigid = false;
  const auto compliant = dem::mix_properties(glass, wall, {});
  EXPECT_DOUBLE_EQ(*compliant.effective_modulus, dem::effective_modulus(6.3e10, 0.23, 2.1e11, 0.29));
  EXPECT_LT(*compliant.effective_modulus, 6.3e10 / (1.0 - 0.23 * 0.23));
  EXPECT_DOUBLE_EQ(*compliant.normal_stiffness, 1e5);
}

/// A rigid wall material with a density and nothing else (no elastic constants).
dem::MaterialProperties bare_rigid_wall() {
  dem::MaterialProperties wall;
  wall.name = "steel";
  wall.density = 7800.0;
  wall.rigid = true;
  return wall;
}

TEST(RigidMixing, TakesNoElasticValueFromTheRigidMaterialAndNeedsNone) {
  const dem::MaterialProperties glass = elastic("glass", 1e8, 0.3, 0.5);
  dem::MaterialProperties wall = bare_rigid_wall();
  wall.friction = 0.2;
  const auto p = dem::mix_properties(glass, wall, {});
  EXPECT_DOUBLE_EQ(*p.effective_modulus, 1e8 / 0.91);
  EXPECT_DOUBLE_EQ(*p.normal_stiffness, 2e5);
  EXPECT_DOUBLE_EQ(*p.friction, 0.2);
  EXPECT_FALSE(p.restitution.has_value());  // set by one side only: not mixed
  // Two rigid bodies get no elastic values at all.
  const auto none = dem::mix_properties(wall, wall, {});
  EXPECT_FALSE(none.effective_modulus.has_value());
  EXPECT_FALSE(none.normal_stiffness.has_value());
  EXPECT_DOUBLE_EQ(*none.friction, 0.2);
}

TEST(RigidMixing, PairTableBuildsTheRigidLawAndSkipsRigidPairs) {
  const dem::MaterialProperties glass = elastic("glass", 1e8, 0.3, 0.5);
  const dem::MaterialProperties wall = bare_rigid_wall();
  dem::ModelChoice choice;
  choice.normal = "hertz";
  const dem::PairTable t({glass, wall}, {}, {}, choice);
  EXPECT_TRUE(t.interacts(0, 1));
  EXPECT_TRUE(t.interacts(0, 0));
  EXPECT_FALSE(t.interacts(1, 1));  // no law is required of wall against wall
  EXPECT_DOUBLE_EQ(std::get<dem::HertzNormal>(t.law(1, 0).normal).effective_modulus, 1e8 / 0.91);
  EXPECT_DOUBLE_EQ(std::get<dem::HertzNormal>(t.law(0, 0).normal).effective_modulus,
                   dem::effective_modulus(1e8, 0.3, 1e8, 0.3));
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
