// SPDX-License-Identifier: MIT
// End-to-end tests of the tiers (`demwb suite|gate --tier fast|full`): in the fast tier a
// full-tier case runs its in-house side and takes its reference results from the committed
// baseline, which must fit the case and the input the driver writes for it now; a missing or
// stale baseline, or stored ensemble, fails the gate and names the command that renews it.
// Runs the real LAMMPS.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "store/result_cache.hpp"
#include "support/text_file.hpp"

namespace tier_e2e_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

/// `text` with `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The canonical single collision as a full-tier case on the core, the closed form and LAMMPS.
std::string full_tier_collision() {
  std::string text = support::read_file(canonical("single_collision"));
  text = replaced(text, "[case]\n", "[case]\ntier = \"full\"\n");
  text = replaced(text, "engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\", \"liggghts\"]",
                  "engines = [\"inhouse\", \"analytic\", \"lammps\"]");
  return replaced(text, "matched = [\"lammps\", \"yade\", \"liggghts\"]", "matched = []");
}

/// Runs `demwb gate` on the suite `suite` with baselines in `baselines` and the given tier.
demwb_e2e::Outcome gate(const fs::path& suite, const fs::path& baselines, const fs::path& out,
                        const std::string& tier = "") {
  std::vector<std::string> args{"gate", suite.string(), "-o", out.string(), "--no-cache", "--baselines",
                                baselines.string(), "--baseline", baselines.string()};
  if (!tier.empty()) args.insert(args.end(), {"--tier", tier});
  return demwb(args);
}

std::string source_of(const fs::path& out, const std::string& engine) {
  const Json results = Json::parse(support::read_file(out / "results.json"));
  return results["cases"][0]["engines"][engine].value("source", std::string("?"));
}

TEST(Tiers, AFullTierCaseInTheFastTierComparesAgainstItsBaselineWhileItFitsCaseAndDeck) {
  const fs::path root = scratch("tier_full_case");
  const fs::path suite = root / "suite";
  const fs::path baselines = root / "baselines";
  const fs::path case_file = suite / "single_collision.toml";
  support::write_file(case_file, full_tier_collision());
  fs::create_directories(baselines);
  const std::string refresh = "demwb refresh " + case_file.string() + " --write-baselines";

  // No baseline yet: the fast tier cannot stand in for LAMMPS, and says how to make one.
  const auto none = gate(suite, baselines, root / "none");
  EXPECT_EQ(none.exit_code, 1) << none.out << none.err;
  EXPECT_NE(none.out.find("is in the full tier and this is a fast-tier run"), std::string::npos) << none.out;
  EXPECT_NE(none.out.find(refresh), std::string::npos) << none.out;

  const auto made = demwb({"refresh", case_file.string(), "--write-baselines", "--baselines", baselines.string(),
                           "--no-cache", "-o", (root / "refresh").string()});
  ASSERT_EQ(made.exit_code, 0) << made.out << made.err;
  const store::Baseline stored = store::read_baseline(baselines / "single_collision.json");
  ASSERT_EQ(stored.inputs.count("lammps"), 1u);
  EXPECT_EQ(stored.inputs.at("lammps").size(), 64u);

  // With it, the fast tier passes: the core and the closed form ran, LAMMPS is the stored result.
  const auto fast = gate(suite, baselines, root / "fast");
  EXPECT_EQ(fast.exit_code, 0) << fast.out << fast.err;
  EXPECT_NE(fast.out.find("lammps not run (a full-tier case in the fast tier); compared against its committed baseline"),
            std::string::npos)
      << fast.out;
  EXPECT_EQ(source_of(root / "fast", "lammps"), "baseline");
  EXPECT_EQ(source_of(root / "fast", "inhouse"), "run");
  EXPECT_EQ(Json::parse(support::read_file(root / "fast" / "results.json"))["tier"], "fast");
  EXPECT_NE(support::read_file(root / "fast" / "report.md").find("tier `full`"), std::string::npos);

  // The full tier runs LAMMPS itself.
  const auto full = gate(suite, baselines, root / "full", "full");
  EXPECT_EQ(full.exit_code, 0) << full.out << full.err;
  EXPECT_EQ(source_of(root / "full", "lammps"), "run");

  // A baseline made from another deck than the driver writes now is stale.
  store::Baseline other_deck = stored;
  other_deck.inputs["lammps"] = std::string(64, '0');
  store::write_baseline(baselines / "single_collision.json", other_deck);
  const auto deck = gate(suite, baselines, root / "deck");
  EXPECT_EQ(deck.exit_code, 1) << deck.out << deck.err;
  EXPECT_NE(deck.out.find("was made from another input deck than the driver writes now"), std::string::npos)
      << deck.out;
  EXPECT_NE(deck.out.find(refresh), std::string::npos) << deck.out;

  // So is one made for another version of the case.
  store::write_baseline(baselines / "single_collision.json", stored);
  support::write_file(case_file, replaced(full_tier_collision(), "duration = 8.0e-4", "duration = 8.1e-4"));
  const auto edited = gate(suite, baselines, root / "edited");
  EXPECT_EQ(edited.exit_code, 1) << edited.out << edited.err;
  EXPECT_NE(edited.out.find("was made for another version of this case"), std::string::npos) << edited.out;
}

TEST(Tiers, AFastTierCaseRunsItsReferenceCodesInEitherTier) {
  const fs::path root = scratch("tier_fast_case");
  std::string text = replaced(full_tier_collision(), "tier = \"full\"", "tier = \"fast\"");
  support::write_file(root / "suite" / "single_collision.toml", text);
  fs::create_directories(root / "baselines");  // empty: nothing to stand in
  const auto fast = gate(root / "suite", root / "baselines", root / "out");
  EXPECT_EQ(fast.exit_code, 0) << fast.out << fast.err;
  EXPECT_EQ(source_of(root / "out", "lammps"), "run");
}

TEST(Tiers, StoredEnsemblesAreReadInTheFastTierRunAfreshInTheFullTierAndFailTheGateWhenStale) {
  // A suite with sibling ensembles/ and sweeps/ folders holding one two-engine sweep, as cases/
  // is laid out: the JKR agglomerate of cases/ensembles shrunk to 8 spheres, core against LAMMPS.
  const fs::path root = scratch("tier_ensembles");
  std::string text = support::read_file(canonical("single_collision"));
  text = replaced(text, "engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\", \"liggghts\"]", "engines = [\"inhouse\", \"analytic\"]");
  text = replaced(text, "matched = [\"lammps\", \"yade\", \"liggghts\"]", "matched = []");
  support::write_file(root / "suite" / "single_collision.toml", text);
  const std::string agglomerate = support::read_file(std::string(DEMWB_SOURCE_DIR) + "/cases/ensembles/agglomerate_jkr_lammps.toml");
  support::write_file(root / "ensembles" / "small_jkr.toml", replaced(agglomerate, "count = 125", "count = 8"));
  const std::string sweep = R"([sweep]
name = "tiny"
description = "An 8-sphere JKR agglomerate, core against LAMMPS, two seeds."
case = "../ensembles/small_jkr.toml"
seeds = [1, 2]
engines = ["inhouse", "lammps"]
metrics = ["kappa_vol", "fragments"]

[[parameters]]
key = "materials.jkr_benchmark.surface_energy"
values = [121.5]
)";
  const fs::path sweep_file = root / "sweeps" / "tiny.toml";
  support::write_file(sweep_file, sweep);
  fs::create_directories(root / "baselines");

  const auto missing = gate(root / "suite", root / "baselines", root / "missing");
  EXPECT_EQ(missing.exit_code, 1) << missing.out << missing.err;
  EXPECT_NE(missing.out.find("FAIL stored ensemble tiny: no stored results"), std::string::npos) << missing.out;
  EXPECT_NE(missing.out.find("demwb refresh --sweep " + sweep_file.string()), std::string::npos) << missing.out;

  const auto stored = demwb({"refresh", "--sweep", sweep_file.string(), "-o", (root / "refresh").string()});
  ASSERT_EQ(stored.exit_code, 0) << stored.out << stored.err;
  for (const char* file : {"sweep.csv", "sweep.json", "report.md"}) {
    EXPECT_TRUE(fs::exists(root / "baselines" / "sweeps" / "tiny" / file)) << file;
  }

  const auto fast = gate(root / "suite", root / "baselines", root / "fast");
  EXPECT_EQ(fast.exit_code, 0) << fast.out << fast.err;
  const Json fast_results = Json::parse(support::read_file(root / "fast" / "results.json"));
  ASSERT_EQ(fast_results["ensembles"].size(), 1u);
  EXPECT_TRUE(fast_results["ensembles"][0]["current"].get<bool>());
  EXPECT_NE(support::read_file(root / "fast" / "report.md").find("## Cross-code ensembles (stored)"), std::string::npos);
  EXPECT_FALSE(fs::exists(root / "fast" / "ensembles"));

  const auto full = gate(root / "suite", root / "baselines", root / "full", "full");
  EXPECT_EQ(full.exit_code, 0) << full.out << full.err;
  EXPECT_TRUE(fs::exists(root / "full" / "ensembles" / "tiny" / "sweep.csv"));
  EXPECT_NE(support::read_file(root / "full" / "report.md").find("## Cross-code ensembles (run now, full tier)"),
            std::string::npos);
  // The fresh sweep gives the stored figures (same cases, same seeds).
  EXPECT_EQ(support::read_file(root / "full" / "ensembles" / "tiny" / "sweep.csv"),
            support::read_file(root / "baselines" / "sweeps" / "tiny" / "sweep.csv"));

  support::write_file(sweep_file, sweep + "# edited after its results were stored\n");
  const auto stale = gate(root / "suite", root / "baselines", root / "stale");
  EXPECT_EQ(stale.exit_code, 1) << stale.out << stale.err;
  EXPECT_NE(stale.out.find("FAIL stored ensemble tiny: stale"), std::string::npos) << stale.out;
}

TEST(Tiers, AnUnknownTierIsAUsageError) {
  const auto r = demwb({"suite", "canonical", "--tier", "slow", "-o", scratch("tier_slow").string()});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--tier must be 'fast' or 'full', not 'slow'"), std::string::npos) << r.err;
}

}  // namespace tier_e2e_test
