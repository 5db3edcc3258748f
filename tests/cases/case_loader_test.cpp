// SPDX-License-Identifier: MIT
#include "cases/case_loader.hpp"

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "support/sha256.hpp"
#include "support/text_file.hpp"
#include "case_texts.hpp"

namespace case_loader_test {

using cases::CaseError;
using cases::load_case_text;
using case_texts::error_of;

// A complete case exercising every section; materials deliberately not in alphabetical order.
constexpr std::string_view kFullCase = R"(# Full case used by the loader tests.
[case]
name = "single_collision"
description = "A small sphere hits a large fixed one."
thesis = "§4.3, table 4.2"

[model]
normal = "linear"
damping = "none"

[mixing]
normal_stiffness = "arithmetic"

[materials.steel]
density = 7800
normal_stiffness = 2.0e5

[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5
restitution = 0.8

[[pairs]]
materials = ["glass", "steel"]
normal_stiffness = 1.5e5

[[particles]]
radius = 0.01
material = "glass"
position = [0.0, 0.0, 0.0]
velocity = [4.0, 0.0, 0.0]

[[particles]]
radius = 0.1
effect_radius = 0.11
material = "steel"
position = [0.12, 0.0, 0.0]
fixed = true

[fields]
gravity = [0, 0, -9.81]

[integration]
scheme = "ab4"
timestep = 5e-6
duration = 0.004
startup = "exact"
startup_substeps = 8

[compare]
engines = ["inhouse", "lammps", "analytic"]
pair = [0, 1]
metrics = ["contact_duration", "restitution"]

[compare.tolerances]
contact_duration = { rel = 1e-3 }
restitution = { rel = 1e-6, abs = 1e-9 }
)";

// The smallest valid case: every optional section left out.
constexpr std::string_view kMinimalCase = R"([case]
name = "minimal"

[model]
normal = "linear"

[materials.a]
density = 1000.0
normal_stiffness = 1.0e5

[[particles]]
radius = 0.01
material = "a"
position = [0.0, 0.0, 0.0]

[integration]
scheme = "rk4"
timestep = "auto"
duration = 1.0e-3
)";

/// kMinimalCase with `extra` appended (a further table, or keys of [integration]).
std::string minimal_with(std::string_view extra) {
  return std::string(kMinimalCase) + std::string(extra);
}

/// True when some line contains both `a` and `b`.
bool any_contains(const std::vector<std::string>& lines, std::string_view a, std::string_view b) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
    return line.find(a) != std::string::npos && line.find(b) != std::string::npos;
  });
}

TEST(CaseLoader, LoadsFullCaseIntoExplicitScene) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  EXPECT_EQ(s.name, "single_collision");
  EXPECT_EQ(s.description, "A small sphere hits a large fixed one.");
  EXPECT_EQ(s.thesis_reference, "§4.3, table 4.2");
  EXPECT_EQ(s.model.normal, "linear");
  EXPECT_EQ(s.model.damping, "none");
  EXPECT_EQ(s.model.tangential, "none");
  EXPECT_EQ(s.model.cohesion, "none");
  EXPECT_EQ(s.model.rolling, "none");
  ASSERT_EQ(s.mixing.size(), 1u);
  EXPECT_EQ(s.mixing.at("normal_stiffness"), dem::MixingRule::arithmetic);
  EXPECT_EQ(s.gravity, (cases::Vector3{0.0, 0.0, -9.81}));
}

TEST(CaseLoader, ReadsTheTierFastByDefaultAndRefusesAnUnknownOne) {
  EXPECT_EQ(load_case_text(kMinimalCase, "m.toml").tier, cases::Tier::fast);
  const auto with_tier = [](std::string_view tier) {
    std::string text(kMinimalCase);
    text.insert(text.find("name = \"minimal\"") + std::string_view("name = \"minimal\"\n").size(),
                "tier = " + std::string(tier) + "\n");
    return text;
  };
  EXPECT_EQ(load_case_text(with_tier("\"full\""), "m.toml").tier, cases::Tier::full);
  EXPECT_EQ(load_case_text(with_tier("\"fast\""), "m.toml").tier, cases::Tier::fast);
  const CaseError slow = error_of(with_tier("\"slow\""));
  EXPECT_EQ(slow.key(), "case.tier");
  EXPECT_NE(std::string(slow.what()).find("unknown tier 'slow'"), std::string::npos) << slow.what();
  EXPECT_NE(std::string(slow.what()).find("fast, full"), std::string::npos) << slow.what();
  EXPECT_EQ(error_of(with_tier("1")).key(), "case.tier");
}

TEST(CaseLoader, KeepsMaterialsInFileOrderWithTheirProperties) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "steel");
  EXPECT_DOUBLE_EQ(s.materials[0].density, 7800.0);  // a TOML integer where a number is expected
  EXPECT_EQ(s.materials[0].normal_stiffness, 2.0e5);
  EXPECT_FALSE(s.materials[0].restitution.has_value());
  EXPECT_EQ(s.materials[1].name, "glass");
  EXPECT_EQ(s.materials[1].restitution, 0.8);
  ASSERT_EQ(s.pair_overrides.size(), 1u);
  EXPECT_EQ(s.pair_overrides[0].material_a, 1u);
  EXPECT_EQ(s.pair_overrides[0].material_b, 0u);
  EXPECT_EQ(s.pair_overrides[0].values.normal_stiffness, 1.5e5);
  EXPECT_FALSE(s.pair_overrides[0].values.restitution.has_value());
}

TEST(CaseLoader, ReadsParticlesWithDefaults) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  ASSERT_EQ(s.particles.size(), 2u);
  const cases::ParticleSpec& p = s.particles[0];
  EXPECT_EQ(p.radius, 0.01);
  EXPECT_EQ(p.effect_radius, 0.01);  // defaults to the radius
  EXPECT_EQ(p.material, 1u);
  EXPECT_EQ(p.velocity, (cases::Vector3{4.0, 0.0, 0.0}));
  EXPECT_EQ(p.angular_velocity, (cases::Vector3{0.0, 0.0, 0.0}));
  EXPECT_FALSE(p.fixed);
  const cases::ParticleSpec& q = s.particles[1];
  EXPECT_EQ(q.effect_radius, 0.11);
  EXPECT_EQ(q.material, 0u);
  EXPECT_EQ(q.position, (cases::Vector3{0.12, 0.0, 0.0}));
  EXPECT_TRUE(q.fixed);
}

TEST(CaseLoader, ReadsIntegrationSettingsAndDefaults) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  const cases::IntegrationSpec& i = s.integration;
  EXPECT_EQ(i.scheme, dem::SchemeId::ab4);
  EXPECT_EQ(i.timestep, 5e-6);
  EXPECT_EQ(i.duration, 0.004);
  EXPECT_EQ(i.steps_per_collision, 20.0);
  EXPECT_TRUE(i.rotation);
  EXPECT_EQ(i.startup, dem::StartupPolicy::exact);
  EXPECT_EQ(i.startup_substeps, 8);
  EXPECT_EQ(i.implicit_tolerance, 1e-12);
  EXPECT_EQ(i.implicit_max_iterations, 100);
  EXPECT_EQ(i.leapfrog_start, dem::LeapfrogStart::half_kick);
}

TEST(CaseLoader, DefaultsTracesToMovingParticlesAndTheComparedPair) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  EXPECT_EQ(s.output.trace_every, 1u);
  EXPECT_EQ(s.output.trace_particles, (std::vector<std::size_t>{0}));
  ASSERT_EQ(s.output.trace_pairs.size(), 1u);
  EXPECT_EQ(s.output.trace_pairs[0], (cases::ParticlePair{0, 1}));
  EXPECT_TRUE(s.output.snapshot_times.empty());
}

TEST(CaseLoader, ReadsComparisonWithAnalyticAsDefaultReference) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  const cases::CompareSpec& c = s.compare;
  EXPECT_EQ(c.engines, (std::vector<std::string>{"inhouse", "lammps", "analytic"}));
  EXPECT_EQ(c.reference, "analytic");
  EXPECT_EQ(c.subject, std::optional<std::size_t>(0));
  EXPECT_EQ(c.pair, std::optional<cases::ParticlePair>(cases::ParticlePair{0, 1}));
  EXPECT_EQ(c.metrics, (std::vector<std::string>{"contact_duration", "restitution"}));
  ASSERT_EQ(c.tolerances.size(), 2u);
  EXPECT_EQ(c.tolerances.at("contact_duration").rel, 1e-3);
  EXPECT_EQ(c.tolerances.at("contact_duration").abs, 0.0);
  EXPECT_EQ(c.tolerances.at("restitution").rel, 1e-6);
  EXPECT_EQ(c.tolerances.at("restitution").abs, 1e-9);
}

TEST(CaseLoader, StoresSourcePathTextAndItsSha256) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  EXPECT_EQ(s.source_path, "full.toml");
  EXPECT_EQ(s.source_text, kFullCase);
  EXPECT_EQ(s.source_sha256, support::sha256_hex(kFullCase));
  EXPECT_EQ(s.source_sha256.size(), 64u);
}

TEST(CaseLoader, WarnsAboutPropertyNoSelectedSubModelUses) {
  const cases::Scene s = load_case_text(kFullCase, "full.toml");
  ASSERT_EQ(s.warnings.size(), 1u);
  // restitution sits on line 21, column 15 of kFullCase; damping = "none" never reads it.
  EXPECT_EQ(s.warnings[0].rfind("full.toml:21:15: materials.glass.restitution: ", 0), 0u)
      << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("not used by the selected contact model"), std::string::npos);
}

TEST(CaseLoader, MinimalCaseGetsEveryDefault) {
  const cases::Scene s = load_case_text(kMinimalCase, "minimal.toml");
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_TRUE(s.description.empty());
  EXPECT_EQ(s.model.damping, "none");
  EXPECT_TRUE(s.mixing.empty());
  EXPECT_TRUE(s.pair_overrides.empty());
  EXPECT_EQ(s.gravity, (cases::Vector3{0.0, 0.0, 0.0}));
  EXPECT_FALSE(s.integration.timestep.has_value());  // "auto"
  EXPECT_EQ(s.compare.engines, (std::vector<std::string>{"inhouse"}));
  EXPECT_EQ(s.compare.reference, "inhouse");
  EXPECT_EQ(s.compare.subject, std::optional<std::size_t>(0));
  EXPECT_FALSE(s.compare.pair.has_value());
  EXPECT_TRUE(s.compare.metrics.empty());
  EXPECT_TRUE(s.output.trace_pairs.empty());
  EXPECT_EQ(s.output.trace_particles, (std::vector<std::size_t>{0}));
}

TEST(CaseLoader, ReferenceDefaultsToFirstEngineWhenAnalyticIsNotListed) {
  const cases::Scene s =
      load_case_text(minimal_with("[compare]\nengines = [\"yade\", \"inhouse\"]\n"), "case.toml");
  EXPECT_EQ(s.compare.reference, "yade");
}

TEST(CaseLoader, AcceptsIntegralFloatWhereAnIntegerIsExpected) {
  const cases::Scene s = load_case_text(minimal_with("[output]\ntrace_every = 3.0\n"), "case.toml");
  EXPECT_EQ(s.output.trace_every, 3u);
}

TEST(CaseLoader, AcceptsEverySchemeKeyword) {
  for (const auto& info : dem::scheme_infos()) {
    std::string text(kMinimalCase);
    text.replace(text.find("\"rk4\""), 5, "\"" + std::string(info.keyword) + "\"");
    EXPECT_EQ(load_case_text(text, "case.toml").integration.scheme, info.id) << info.keyword;
  }
}

TEST(CaseLoader, ErrorPointsAtLineAndColumnOfTheOffendingValue) {
  std::string text(kMinimalCase);
  text.replace(text.find("radius = 0.01"), 13, "radius = -2");
  const CaseError e = error_of(text);
  EXPECT_STREQ(e.what(), "case.toml:12:10: particles[0].radius: must be > 0, got -2");
  EXPECT_EQ(e.key(), "particles[0].radius");
  EXPECT_EQ(e.problem(), "must be > 0, got -2");
}

TEST(CaseLoader, MissingKeyPointsAtItsTable) {
  std::string text(kMinimalCase);
  text.erase(text.find("duration = 1.0e-3\n"), 18);
  EXPECT_STREQ(error_of(text).what(), "case.toml:16:1: integration.duration: missing required key");
}

TEST(CaseLoader, ErrorWithoutPositionOmitsLineAndColumn) {
  const CaseError e("x.toml", "compare", "something is wrong");
  EXPECT_STREQ(e.what(), "x.toml: compare: something is wrong");
}

TEST(CaseLoader, UnknownKeyWithoutCloseMatchListsKnownKeys) {
  const CaseError e = error_of(minimal_with("[fields]\nmagnetism = 1.0\n"));
  EXPECT_EQ(e.key(), "fields.magnetism");
  EXPECT_EQ(e.problem(), "unknown key 'magnetism' (known: gravity, fluid)");
}

TEST(CaseLoader, WarnsWhenStartupIsSetForSingleStepScheme) {
  const cases::Scene s = load_case_text(minimal_with("startup = \"rk4\"\n"), "case.toml");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("integration.startup: has no effect: scheme 'rk4' is single-step"),
            std::string::npos)
      << s.warnings[0];
}

TEST(CaseLoader, WarnsWhenRotationIsOffButAParticleSpins) {
  std::string text(kMinimalCase);
  text.replace(text.find("position = [0.0, 0.0, 0.0]"), 26,
               "position = [0.0, 0.0, 0.0]\nangular_velocity = [0.0, 0.0, 5.0]");
  const cases::Scene s = load_case_text(text + "rotation = false\n", "case.toml");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_TRUE(any_contains(s.warnings, "integration.rotation", "particles[0].angular_velocity"))
      << s.warnings[0];
}

TEST(CaseLoader, WarnsAboutUnusedPairPropertyAndMixingRule) {
  const std::string text = minimal_with(
      "[mixing]\nrestitution = \"min\"\n\n[[pairs]]\nmaterials = [\"a\", \"a\"]\n"
      "restitution = 0.5\n");
  const cases::Scene s = load_case_text(text, "case.toml");
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_TRUE(any_contains(s.warnings, "mixing.restitution:", "not used"));
  EXPECT_TRUE(any_contains(s.warnings, "pairs[0].restitution:", "not used"));
  EXPECT_EQ(s.pair_overrides.at(0).values.restitution, 0.5);
}

TEST(CaseLoader, AllowsSlightInitialOverlapBelowOnePercent) {
  const std::string text = minimal_with(
      "\n[[particles]]\nradius = 0.01\nmaterial = \"a\"\nposition = [0.0199, 0.0, 0.0]\n");
  // [[particles]] after [integration] is valid TOML: it appends to the particles array.
  EXPECT_EQ(load_case_text(text, "case.toml").particles.size(), 2u);
}

TEST(CaseLoader, AllowsOverlappingFixedParticles) {
  // Two fixed spheres never interact, so a wall of overlapping fixed spheres is fine.
  const std::string text = minimal_with(
      "\n[[particles]]\nradius = 0.01\nmaterial = \"a\"\nposition = [1.0, 0.0, 0.0]\nfixed = true\n"
      "\n[[particles]]\nradius = 0.01\nmaterial = \"a\"\nposition = [1.005, 0.0, 0.0]\nfixed = true\n");
  EXPECT_EQ(load_case_text(text, "case.toml").particles.size(), 3u);
}

TEST(CaseLoader, LoadCaseReadsFileAndRecordsItsPath) {
  const auto path = std::filesystem::temp_directory_path() / "demwb_case_loader_test.toml";
  support::write_file(path, kMinimalCase);
  const cases::Scene s = cases::load_case(path);
  std::filesystem::remove(path);
  EXPECT_EQ(s.source_path, path.string());
  EXPECT_EQ(s.source_text, kMinimalCase);
}

TEST(CaseLoader, LoadCaseOfMissingFileThrowsCaseError) {
  try {
    static_cast<void>(cases::load_case("/nonexistent/demwb/case.toml"));
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "(file)");
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/demwb/case.toml: (file): ", 0), 0u);
  }
}

TEST(CaseLoader, LoadsEveryCanonicalEnsembleAndStudyCase) {
  std::size_t loaded = 0;
  for (const char* folder : {"canonical", "ensembles", "studies"}) {
    const auto dir = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases" / folder;
    ASSERT_TRUE(std::filesystem::exists(dir)) << dir;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() != ".toml") continue;
      try {
        static_cast<void>(cases::load_case(entry.path()));
        ++loaded;
      } catch (const CaseError& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  EXPECT_GE(loaded, 13U + 4U + 2U);
}

}  // namespace
