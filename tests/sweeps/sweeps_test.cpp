// SPDX-License-Identifier: MIT
// Sweep files, the case text of a sweep run, and the statistics over seeds.
#include <cmath>

#include <gtest/gtest.h>

#include "../small_agglomerate.hpp"
#include "cases/case_loader.hpp"
#include "support/text_file.hpp"
#include "sweeps/case_override.hpp"
#include "sweeps/seed_statistics.hpp"
#include "sweeps/sweep_spec.hpp"

namespace sweeps_test {

namespace fs = std::filesystem;

/// The key a CaseError names, or "(no error)".
template <typename F>
std::string error_key(F&& f) {
  try {
    f();
  } catch (const cases::CaseError& e) {
    return e.key();
  }
  return "(no error)";
}

TEST(CaseOverride, ReplacesNumbersAndSeedsEveryPopulation) {
  const std::string base = test_support::small_agglomerate(8, 1);
  const std::string text = sweeps::override_case(
      base, "small.toml", {{"materials.m.cohesive_stiffness", 250.0}, {"stages[0].pull", 3.5}, {"populations[0].count", 27}}, 42);
  const cases::Scene s = cases::load_case_text(text, "small.toml");
  EXPECT_EQ(s.materials[0].cohesive_stiffness, 250.0);
  EXPECT_EQ(std::get<cases::FormationStageSpec>(s.stages[0].action).pull, 3.5);
  EXPECT_EQ(s.particles.size(), 27U);
  // Seed 42 gives the particles a seed-42 population gives directly.
  std::string direct = test_support::small_agglomerate(27, 42);
  const cases::Scene d = cases::load_case_text(
      sweeps::override_case(direct, "small.toml", {{"materials.m.cohesive_stiffness", 250.0}, {"stages[0].pull", 3.5}}, std::nullopt),
      "small.toml");
  ASSERT_EQ(d.particles.size(), s.particles.size());
  for (std::size_t i = 0; i < d.particles.size(); ++i) EXPECT_EQ(d.particles[i].radius, s.particles[i].radius);
  // Untouched values survive the round trip exactly.
  EXPECT_EQ(s.materials[0].normal_stiffness, 1e5);
  EXPECT_EQ(*s.integration.timestep, 2e-5);
}

TEST(CaseOverride, NamesTheKeyThatCannotBeSwept) {
  const std::string base = test_support::small_agglomerate(8, 1);
  const auto key_of = [&](const std::string& key, double v) {
    return error_key([&] { static_cast<void>(sweeps::override_case(base, "small.toml", {{key, v}}, std::nullopt)); });
  };
  EXPECT_EQ(key_of("materials.m.cohesive_stifness", 1.0), "materials.m.cohesive_stifness");
  EXPECT_EQ(key_of("stages[5].pull", 1.0), "stages[5].pull");
  EXPECT_EQ(key_of("model.normal", 1.0), "model.normal");          // a string, not a number
  EXPECT_EQ(key_of("populations[0].count", 2.5), "populations[0].count");  // an integer
  EXPECT_EQ(key_of("stages[x].pull", 1.0), "stages[x].pull");
  EXPECT_EQ(key_of("materials.m.cohesive_stiffness", 1.0), "(no error)");
}

TEST(CaseOverride, FixedSettingsReplaceValuesOfTheirOwnKind) {
  const std::string base = test_support::small_agglomerate(8, 1);
  const std::vector<sweeps::FixedSetting> fixed{{"integration.scheme", std::string("rk4")},
                                                {"materials.m.cohesive_stiffness", 300.0}};
  const cases::Scene s = cases::load_case_text(sweeps::override_case(base, "small.toml", {}, std::nullopt, fixed),
                                               "small.toml");
  EXPECT_EQ(s.integration.scheme, dem::SchemeId::rk4);
  EXPECT_EQ(s.materials[0].cohesive_stiffness, 300.0);
  // A swept value is applied after the fixed ones.
  const cases::Scene swept = cases::load_case_text(
      sweeps::override_case(base, "small.toml", {{"materials.m.cohesive_stiffness", 400.0}}, std::nullopt,
                            {{"materials.m.cohesive_stiffness", 300.0}}),
      "small.toml");
  EXPECT_EQ(swept.materials[0].cohesive_stiffness, 400.0);
  const auto key_of = [&](const sweeps::FixedSetting& f) {
    return error_key([&] { static_cast<void>(sweeps::override_case(base, "small.toml", {}, std::nullopt, {f})); });
  };
  EXPECT_EQ(key_of({"model.normal", 2.0}), "model.normal");                          // a string, not a number
  EXPECT_EQ(key_of({"materials.m.density", std::string("heavy")}), "materials.m.density");  // a number
  EXPECT_EQ(key_of({"model.normal", true}), "model.normal");                         // not a boolean
  EXPECT_EQ(key_of({"model.mindlin_frm", std::string("total")}), "model.mindlin_frm");  // absent: never added
}

TEST(SweepSpec, SetHoldsKeysAtOneValueAndMayNotAlsoBeSwept) {
  const fs::path dir = fs::temp_directory_path() / "demwb-sweep-spec-set";
  support::write_file(dir / "small.toml", test_support::small_agglomerate());
  const std::string head = "[sweep]\nname = \"x\"\ncase = \"small.toml\"\nseeds = [1]\n";
  const std::string axis = "[[parameters]]\nkey = \"a.b\"\nvalues = [1.0]\n";
  const sweeps::SweepSpec spec = sweeps::load_sweep_text(
      head + "set = { \"model.damping\" = \"tsuji\", \"integration.rotation\" = false, \"c.d\" = 2 }\n" + axis,
      dir / "set.toml");
  ASSERT_EQ(spec.fixed.size(), 3U);
  EXPECT_EQ(spec.fixed[0].key, "model.damping");
  EXPECT_EQ(std::get<std::string>(spec.fixed[0].value), "tsuji");
  EXPECT_EQ(std::get<bool>(spec.fixed[1].value), false);
  EXPECT_EQ(std::get<double>(spec.fixed[2].value), 2.0);
  const auto fails = [&](const std::string& text) {
    return error_key([&] { static_cast<void>(sweeps::load_sweep_text(text, dir / "bad.toml")); }) != "(no error)";
  };
  EXPECT_TRUE(fails(head + "set = { \"a.b\" = 3.0 }\n" + axis));          // also an axis
  EXPECT_TRUE(fails(head + "set = { \"m\" = [1, 2] }\n" + axis));          // not a single value
  EXPECT_TRUE(fails(head + "set = { \"bad key\" = 1 }\n" + axis));        // not a dotted key
  EXPECT_TRUE(fails(head + "set = 3\n" + axis));                           // not a table
  EXPECT_TRUE(fails(head + "set = { \"populations[0].seed\" = 7 }\n" + axis));  // the sweep's seeds do that
  EXPECT_TRUE(fails(head + "set = { model.damping = \"tsuji\" }\n" + axis));  // unquoted: a nested table
}

TEST(SweepSpec, ExpandsTheMatrixFirstAxisSlowest) {
  const fs::path dir = fs::temp_directory_path() / "demwb-sweep-spec";
  support::write_file(dir / "small.toml", test_support::small_agglomerate());
  const sweeps::SweepSpec spec = sweeps::load_sweep_text(R"(
[sweep]
name = "m"
case = "small.toml"
seeds = [1, 2, 3]
[[parameters]]
key = "a.b"
values = [1.0, 2.0]
[[parameters]]
key = "c[0].d"
label = "d"
values = [10.0, 20.0, 30.0]
)",
                                                         dir / "m.toml");
  EXPECT_EQ(spec.axes[0].label, "b");
  const auto points = sweeps::expand(spec);
  ASSERT_EQ(points.size(), 6U);
  EXPECT_EQ(points[0].values, (std::vector<double>{1.0, 10.0}));
  EXPECT_EQ(points[2].values, (std::vector<double>{1.0, 30.0}));
  EXPECT_EQ(points[3].values, (std::vector<double>{2.0, 10.0}));
  EXPECT_EQ(points[5].index, 5U);
}

TEST(SweepSpec, LinkedKeysMoveWithTheirAxis) {
  const fs::path dir = fs::temp_directory_path() / "demwb-sweep-linked";
  support::write_file(dir / "small.toml", test_support::small_agglomerate());
  const std::string head = R"(
[sweep]
name = "m"
case = "small.toml"
seeds = [1]
[[parameters]]
key = "a.b"
values = [1.0, 2.0, 3.0]
)";
  const std::string other = "[[parameters]]\nkey = \"e.f\"\nvalues = [7.0, 8.0]\n";
  const sweeps::SweepSpec spec = sweeps::load_sweep_text(
      head + "with = [{ key = \"integration.duration\", values = [0.3, 0.2, 0.1] }]\n" + other, dir / "m.toml");
  const auto points = sweeps::expand(spec);
  ASSERT_EQ(points.size(), 6U);
  // Point 3 is a.b = 2 (its second value) with e.f = 8: the duration is the second linked value.
  EXPECT_EQ(points[3].positions, (std::vector<std::size_t>{1, 1}));
  using Overrides = std::vector<std::pair<std::string, double>>;
  EXPECT_EQ(sweeps::point_overrides(spec, points[3]),
            (Overrides{{"a.b", 2.0}, {"integration.duration", 0.2}, {"e.f", 8.0}}));
  EXPECT_EQ(sweeps::point_overrides(spec, points[4]),
            (Overrides{{"a.b", 3.0}, {"integration.duration", 0.1}, {"e.f", 7.0}}));
  const auto key_of = [&](const std::string& text) {
    return error_key([&] { static_cast<void>(sweeps::load_sweep_text(text, dir / "bad.toml")); });
  };
  EXPECT_EQ(key_of(head + "with = [{ key = \"x.y\", values = [0.3, 0.2] }]\n"), "parameters[0].with[0].values");
  EXPECT_EQ(key_of(head + "with = [{ key = \"a.b\", values = [1.0, 2.0, 3.0] }]\n"), "parameters[0].with");
  EXPECT_EQ(key_of(head + "with = [{ key = \"e.f\", values = [1.0, 2.0, 3.0] }]\n" + other), "parameters[1].key");
  EXPECT_EQ(key_of(head + "with = [{ key = \"x y\", values = [1.0, 2.0, 3.0] }]\n"), "parameters[0].with[0].key");
}

TEST(SweepSpec, BadSweepFilesNameTheirKey) {
  const fs::path dir = fs::temp_directory_path() / "demwb-sweep-spec-bad";
  support::write_file(dir / "small.toml", test_support::small_agglomerate());
  const auto key_of = [&](const std::string& text) {
    return error_key([&] { static_cast<void>(sweeps::load_sweep_text(text, dir / "bad.toml")); });
  };
  const std::string head = "[sweep]\nname = \"x\"\ncase = \"small.toml\"\n";
  const std::string axis = "[[parameters]]\nkey = \"a.b\"\nvalues = [1.0]\n";
  EXPECT_EQ(key_of(head + "seeds = [1, 1]\n" + axis), "sweep.seeds[1]");
  EXPECT_EQ(key_of(head + "seeds = []\n" + axis), "sweep.seeds");
  EXPECT_EQ(key_of("[sweep]\nname = \"x\"\ncase = \"none.toml\"\nseeds = [1]\n" + axis), "sweep.case");
  EXPECT_EQ(key_of(head + "seeds = [1]\n[[parameters]]\nkey = \"a.b\"\nvalues = []\n"), "parameters[0].values");
  EXPECT_EQ(key_of(head + "seeds = [1]\n" + axis + axis), "parameters[1].key");
  EXPECT_EQ(key_of(head + "seeds = [1]\n[[parameters]]\nkey = \"a b\"\nvalues = [1.0]\n"), "parameters[0].key");
  EXPECT_EQ(key_of(head + "seeds = [1]\n[[parameters]]\nkey = \"a.b\"\nvalues = [0.0]\nscale = \"log\"\n"),
            "parameters[0].values");
  EXPECT_EQ(key_of(head + "seeds = [1]\nmetrics = [\"kappa\"]\n" + axis), "sweep.metrics[0]");
  EXPECT_EQ(key_of(head + "seeds = [1]\ntimeout = 0\n" + axis), "sweep.timeout");
  EXPECT_EQ(key_of(head + "seeds = [1]\ntimeout = -5.0\n" + axis), "sweep.timeout");
  EXPECT_EQ(key_of(head + "seeds = [1]\ntimeout = \"long\"\n" + axis), "sweep.timeout");
  EXPECT_EQ(key_of(head + "seeds = [1]\n" + axis), "(no error)");
  EXPECT_FALSE(sweeps::load_sweep_text(head + "seeds = [1]\n" + axis, dir / "ok.toml").timeout_s);
  EXPECT_EQ(sweeps::load_sweep_text(head + "seeds = [1]\ntimeout = 3000\n" + axis, dir / "ok.toml").timeout_s, 3000.0);
}

TEST(SeedStatistics, MeanAndStandardErrorOfTheMean) {
  const std::vector<double> v{0.2, 0.4, 0.9};
  const sweeps::SeedStatistics s = sweeps::seed_statistics(v);
  EXPECT_EQ(s.count, 3U);
  EXPECT_NEAR(s.mean, 0.5, 1e-15);
  // s.d. = √((0.09 + 0.01 + 0.16)/2) = √0.13; SE = s.d./√3.
  ASSERT_TRUE(s.standard_error);
  EXPECT_NEAR(*s.standard_error, std::sqrt(0.13 / 3.0), 1e-15);
  EXPECT_FALSE(sweeps::seed_statistics(std::vector<double>{0.3}).standard_error);
  EXPECT_EQ(sweeps::seed_statistics(std::vector<double>{}).count, 0U);
  // Two ensembles 3 combined standard errors apart.
  const sweeps::SeedStatistics a{4, 1.0, 0.3};
  const sweeps::SeedStatistics b{4, 2.5, 0.4};
  EXPECT_NEAR(*sweeps::separation(a, b), 1.5 / 0.5, 1e-12);
  EXPECT_FALSE(sweeps::separation(a, sweeps::SeedStatistics{1, 2.0, std::nullopt}));
}

}  // namespace
