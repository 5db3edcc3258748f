// SPDX-License-Identifier: MIT
// End-to-end tests of `demwb gate`: a failing comparison, a drifted in-house metric, and engines
// that crashed or are missing must all give a failing exit and name what failed.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "store/result_cache.hpp"
#include "support/text_file.hpp"

namespace gate_e2e_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

/// `baseline` signed as the workbench signs baselines.
std::string signed_baseline(const Json& baseline) { return store::with_checksum(baseline).dump(1); }

/// A suite folder holding the canonical single collision with one tolerance replaced, on the core
/// and the closed form alone (the rows under test; the canonical gate test runs the reference codes).
fs::path strict_suite(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = demwb_e2e::canonical_text_unmatched("single_collision", R"(["inhouse", "analytic"])");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const fs::path dir = scratch(name);
  support::write_file(dir / "single_collision.toml", text);
  return dir;
}

/// A results.json of one case whose rows have the given statuses (engine "lammps" unless named).
Json results_with_rows(const std::vector<std::pair<std::string, std::string>>& engine_status) {
  Json doc;
  doc["case"] = "hand_made";
  doc["engines"] = Json::object();
  doc["comparisons"] = Json::array();
  for (const auto& [engine, status] : engine_status) {
    doc["comparisons"].push_back({{"metric", "contact_duration"},
                                  {"engine", engine},
                                  {"reference", "analytic"},
                                  {"value", nullptr},
                                  {"reference_value", 6.4e-4},
                                  {"tolerance", {{"rel", 1e-3}}},
                                  {"status", status},
                                  {"note", engine + " did not produce a result"}});
  }
  return doc;
}

TEST(DemwbGate, AnImpossibleToleranceFailsTheGateAndNamesTheRow) {
  const fs::path suite = strict_suite("gate_strict", "contact_duration = { rel = 1.0e-3 }",
                                      "contact_duration = { rel = 1.0e-12 }");
  const auto r = demwb({"gate", suite.string(), "-o", scratch("gate_strict_out").string(), "--no-cache"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("FAIL single_collision: contact_duration inhouse vs analytic: fail"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("— FAIL"), std::string::npos) << r.out;
}

TEST(DemwbGate, TheUnchangedCaseOnTheSameEnginesPasses) {
  // Same suite shape and engines as the test above, with the case's own tolerances: the
  // failure above is the tolerance's doing, not the set-up's.
  const fs::path suite = strict_suite("gate_same", "contact_duration = { rel = 1.0e-3 }",
                                      "contact_duration = { rel = 1.0e-3 }");
  const auto r = demwb({"gate", suite.string(), "-o", scratch("gate_same_out").string(), "--no-cache"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("— PASS"), std::string::npos) << r.out;
}

TEST(DemwbGate, AnInhouseMetricThatDriftedFromAnEditedBaselineFails) {
  const fs::path run = scratch("gate_drift_run");
  ASSERT_EQ(demwb({"run", canonical("single_collision"), "--engine", "inhouse", "--engine", "analytic", "-o",
                   run.string()})
                .exit_code,
            0);
  const Json results = Json::parse(support::read_file(run / "results.json"));
  const double now = results["engines"]["inhouse"]["metrics"]["contact_duration"];
  Json baseline;
  baseline["case"] = "single_collision";
  baseline["fingerprint"] = "made by the test";
  baseline["references"] = Json::object();
  baseline["inhouse_metrics"] = {{"contact_duration", now * 1.01}};  // 1 % off, tolerance 0.1 %
  const fs::path file = scratch("gate_drift_baseline") / "single_collision.json";
  support::write_file(file, signed_baseline(baseline));
  const auto r = demwb({"gate", run.string(), "--baseline", file.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("in-house contact_duration drifted from the baseline"), std::string::npos) << r.out;

  baseline["inhouse_metrics"] = {{"contact_duration", now}};
  support::write_file(file, signed_baseline(baseline));
  const auto same = demwb({"gate", run.string(), "--baseline", file.string()});
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;

  // Edited by hand without its checksum: refused, never read as a baseline that agrees.
  Json edited = Json::parse(signed_baseline(baseline));
  edited["inhouse_metrics"]["contact_duration"] = now * 1.01;
  support::write_file(file, edited.dump(1));
  const auto tampered = demwb({"gate", run.string(), "--baseline", file.string()});
  EXPECT_EQ(tampered.exit_code, 1) << tampered.out << tampered.err;
  EXPECT_NE(tampered.out.find("the drift check cannot use its baseline"), std::string::npos) << tampered.out;
  EXPECT_NE(tampered.out.find("does not match its sha256"), std::string::npos) << tampered.out;
}

TEST(DemwbGate, AOneEngineCaseDriftsByItsOwnTolerances) {
  // One engine, so no comparison rows: the drift check must still use the case's tolerance
  // (here 1e-6), not the default (1e-3) that a 1e-5 drift would pass.
  const fs::path dir = scratch("gate_one_engine");
  std::string text = support::read_file(canonical("single_collision"));
  const auto at = text.find("contact_duration = { rel = 1.0e-3 }");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("contact_duration = { rel = 1.0e-3 }").size(), "contact_duration = { rel = 1.0e-6 }");
  for (const auto& [old, now] : std::vector<std::pair<std::string, std::string>>{
           {"engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\", \"liggghts\"]", "engines = [\"inhouse\"]"},
           {"matched = [\"lammps\", \"yade\", \"liggghts\"]", "matched = []"},
           {"reference = \"analytic\"", "reference = \"inhouse\""}}) {
    const auto where = text.find(old);
    ASSERT_NE(where, std::string::npos) << old;
    text.replace(where, old.size(), now);
  }
  support::write_file(dir / "single_collision.toml", text);
  const fs::path run = dir / "run";
  ASSERT_EQ(demwb({"run", (dir / "single_collision.toml").string(), "-o", run.string()}).exit_code,
            0);
  const Json results = Json::parse(support::read_file(run / "results.json"));
  ASSERT_TRUE(results["comparisons"].empty());
  EXPECT_EQ(results["tolerances"]["contact_duration"]["rel"], 1e-6);
  const double now = results["engines"]["inhouse"]["metrics"]["contact_duration"];
  Json baseline;
  baseline["case"] = "single_collision";
  baseline["fingerprint"] = "made by the test";
  baseline["references"] = Json::object();
  baseline["inhouse_metrics"] = {{"contact_duration", now * (1.0 + 1e-5)}};
  support::write_file(dir / "baseline.json", signed_baseline(baseline));
  const auto r = demwb({"gate", run.string(), "--baseline", (dir / "baseline.json").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("in-house contact_duration drifted from the baseline"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no comparison between engines (one engine)"), std::string::npos) << r.out;
}

TEST(DemwbGate, ErrorAndMissingNeverPass) {
  const fs::path dir = scratch("gate_statuses");
  support::write_file(dir / "results.json", results_with_rows({{"lammps", "error"}, {"yade", "missing"}}).dump(2));
  const auto r = demwb({"gate", dir.string(), "--baseline", (dir / "none.json").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("FAIL hand_made: contact_duration lammps vs analytic: error"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FAIL hand_made: contact_duration yade vs analytic: missing"), std::string::npos) << r.out;

  // --allow-missing lets the missing engine through, never the crashed one.
  const auto allowed = demwb({"gate", dir.string(), "--allow-missing", "--baseline", (dir / "none.json").string()});
  EXPECT_EQ(allowed.exit_code, 1) << allowed.out;
  EXPECT_NE(allowed.out.find("lammps vs analytic: error"), std::string::npos) << allowed.out;
  EXPECT_EQ(allowed.out.find("yade vs analytic: missing"), std::string::npos) << allowed.out;

  support::write_file(dir / "results.json", results_with_rows({{"yade", "missing"}}).dump(2));
  EXPECT_EQ(demwb({"gate", dir.string(), "--baseline", (dir / "none.json").string()}).exit_code, 1);
  EXPECT_EQ(demwb({"gate", dir.string(), "--allow-missing", "--baseline", (dir / "none.json").string()}).exit_code,
            0);
}

TEST(DemwbGate, AReferenceCodeThatIsNotInstalledIsMissingAndFailsTheGate) {
  // No lmp in PATH and no baselines to fall back on: LAMMPS is `missing` in the table.
  const fs::path out = scratch("gate_no_lammps");
  const fs::path empty_baselines = scratch("gate_no_baselines");
  fs::create_directories(empty_baselines);
  const auto r = demwb({"compare", canonical("single_collision"), "--engines", "inhouse,analytic,lammps", "--no-cache",
                        "--baselines", empty_baselines.string(), "-o", out.string()},
                       {{"PATH", "/nonexistent"}});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("| contact_duration | lammps |"), std::string::npos) << r.out;
  const auto g = demwb({"gate", out.string(), "--baseline", (empty_baselines / "none.json").string()});
  EXPECT_EQ(g.exit_code, 1) << g.out;
  EXPECT_NE(g.out.find("lammps vs analytic: missing"), std::string::npos) << g.out;
}

}  // namespace

namespace gate_e2e_test {

TEST(DemwbGate, WhereAReferenceIsNotInstalledItsCommittedBaselineStandsInWithAWarning) {
  // No lmp in PATH: LAMMPS comes from cases/baselines/single_collision.json (YADE, found at its
  // Debian path, still runs).
  const fs::path out = scratch("gate_from_baselines");
  const auto r = demwb({"compare", canonical("single_collision"), "--no-cache", "-o", out.string()},
                       {{"PATH", "/nonexistent"}});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const Json results = Json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(results["engines"]["lammps"]["source"], "baseline");
  EXPECT_EQ(results["engines"]["lammps"]["status"], "ok");
  EXPECT_NE(results.dump().find("is not installed here: using its committed baseline"), std::string::npos);
  const auto g = demwb({"gate", out.string()});
  EXPECT_EQ(g.exit_code, 0) << g.out;
  EXPECT_NE(g.out.find("note: single_collision: lammps not installed; compared against its committed baseline"),
            std::string::npos)
      << g.out;
}

}  // namespace
