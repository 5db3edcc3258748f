// SPDX-License-Identifier: MIT
// Results that outlive a run: RunResult JSON round trip, the reference-result cache and baselines.
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "store/packed_column.hpp"
#include "store/result_cache.hpp"
#include "store/run_result_json.hpp"
#include "store/scene_json.hpp"
#include "support/text_file.hpp"

namespace store_test {

namespace fs = std::filesystem;

/// A fresh, empty directory for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("demwb-store-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// The canonical single collision, loaded from the source tree.
cases::Scene single_collision() {
  return cases::load_case(fs::path(DEMWB_SOURCE_DIR) / "cases" / "canonical" / "single_collision.toml");
}

/// A result with every field set to something distinguishable.
cases::RunResult sample_result() {
  cases::RunResult r;
  r.engine = "lammps";
  r.status = cases::RunStatus::ok;
  r.version = "LAMMPS 29 Sep 2021";
  r.wall_time_s = 0.25;
  r.log_tail = "last line";
  r.conventions["integrator"] = "velocity Verlet";
  r.warnings.push_back("a warning");
  r.exact_metrics["restitution"] = 0.5;
  r.inexpressible_metrics["rupture_separation"] = "breaks at the load-controlled pull-off point";
  r.calibrations.push_back({"tsuji e_in (pair 0-0)", 0.5, 0.4873, {{0.5, 0.513}, {0.4873, 0.5000000001}}, "secant"});
  r.trace.add_column("time");
  r.trace.add_column("p0.x");
  r.trace.append_row({0.0, 0.1 + 0.2});
  r.trace.append_row({1e-6, std::nextafter(1.0, 2.0)});
  r.snapshots.push_back({0.0, {{1.0, 2.0, 3.0}}, {{0.0, 0.0, -1.0}}, {{0.0, 0.0, 0.0}}});
  r.refinement = cases::TimeStepRefinement{2.5e-7, 2, 6, false, {{"restitution", 0.49997}}, {{"restitution", 2.5e-5}}, ""};
  return r;
}

TEST(RunResultJson, RoundTripsEveryFieldAndDoublesExactly) {
  const cases::RunResult r = sample_result();
  const cases::RunResult back = store::run_result_from_json(
      nlohmann::ordered_json::parse(store::run_result_json(r).dump()));
  EXPECT_EQ(back.engine, r.engine);
  EXPECT_EQ(back.status, r.status);
  EXPECT_EQ(back.version, r.version);
  EXPECT_EQ(back.wall_time_s, r.wall_time_s);
  EXPECT_EQ(back.log_tail, r.log_tail);
  EXPECT_EQ(back.conventions, r.conventions);
  EXPECT_EQ(back.warnings, r.warnings);
  EXPECT_EQ(back.exact_metrics, r.exact_metrics);
  EXPECT_EQ(back.inexpressible_metrics, r.inexpressible_metrics);
  ASSERT_EQ(back.calibrations.size(), 1U);
  EXPECT_EQ(back.calibrations[0].parameter, r.calibrations[0].parameter);
  EXPECT_EQ(back.calibrations[0].chosen, r.calibrations[0].chosen);
  EXPECT_EQ(back.calibrations[0].samples, r.calibrations[0].samples);
  EXPECT_EQ(back.calibrations[0].method, r.calibrations[0].method);
  EXPECT_EQ(back.trace.columns(), r.trace.columns());
  ASSERT_EQ(back.trace.rows(), 2U);
  EXPECT_EQ(back.trace.values(1)[0], 0.1 + 0.2);
  EXPECT_EQ(back.trace.values(1)[1], std::nextafter(1.0, 2.0));
  ASSERT_EQ(back.snapshots.size(), 1U);
  EXPECT_EQ(back.snapshots[0].position[0][2], 3.0);
  ASSERT_TRUE(back.refinement.has_value());
  EXPECT_EQ(back.refinement->timestep, 2.5e-7);
  EXPECT_EQ(back.refinement->halvings, 2);
  EXPECT_EQ(back.refinement->limit, 6);
  EXPECT_EQ(back.refinement->metrics, r.refinement->metrics);
  EXPECT_EQ(back.refinement->estimates, r.refinement->estimates);
}

TEST(RunResultJson, StoresAColumnEqualToAnEarlierOneAsAReferenceAndRestoresItExactly) {
  cases::RunResult r = sample_result();
  r.trace = cases::Trace{};
  for (const char* c : {"time", "p0.fx", "c0-1.fn", "c0-1.overlap"}) r.trace.add_column(c);
  for (int k = 0; k < 50; ++k) {
    const double f = std::sin(0.1 * k) * 3.7;
    r.trace.append_row({1e-6 * k, f, f, k == 7 ? std::nextafter(f, 10.0) : f});  // the last differs by 1 ulp once
  }
  const auto j = store::run_result_json(r);
  const auto& columns = j["trace"]["columns"];
  EXPECT_EQ(columns["c0-1.fn"], "=p0.fx");
  EXPECT_NE(columns["c0-1.overlap"].get<std::string>().front(), '=');  // not equal bit for bit
  const cases::RunResult back = store::run_result_from_json(nlohmann::ordered_json::parse(j.dump()));
  for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(back.trace.values(c), r.trace.values(c)) << c;
  // A reference to a missing, later or itself-referring column is refused with the column named.
  for (const char* bad : {"=nowhere", "=c0-1.overlap", "=c0-1.fn"}) {
    auto damaged = j;
    damaged["trace"]["columns"]["c0-1.fn"] = bad;
    try {
      static_cast<void>(store::run_result_from_json(damaged));
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("c0-1.fn"), std::string::npos) << e.what();
    }
  }
}

TEST(RunResultJson, AMissingFieldIsAnErrorNamingIt) {
  auto j = store::run_result_json(sample_result());
  j.erase("version");
  try {
    static_cast<void>(store::run_result_from_json(j));
    FAIL() << "a result without a version was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("version"), std::string::npos) << e.what();
  }
}

TEST(SceneFingerprint, ChangesWithThePhysicsAndNotWithTheFileItCameFrom) {
  const cases::Scene a = single_collision();
  cases::Scene b = a;
  b.source_path = "/somewhere/else.toml";
  EXPECT_EQ(store::scene_fingerprint(a), store::scene_fingerprint(b));
  b.particles[0].velocity[0] *= 1.0 + 1e-15;
  EXPECT_NE(store::scene_fingerprint(a), store::scene_fingerprint(b));
}

TEST(SceneFingerprint, EveryContactPolicyThatChangesAResultChangesIt) {
  // A cache keyed by the fingerprint must never serve one policy's result for another's.
  const cases::Scene a = single_collision();
  const std::string base = store::scene_fingerprint(a);
  std::vector<std::function<void(dem::ModelChoice&)>> changes{
      [](dem::ModelChoice& m) { m.mindlin_form = dem::MindlinForm::incremental; },
      [](dem::ModelChoice& m) { m.mindlin_radius = dem::MindlinRadius::contact_radius; },
      [](dem::ModelChoice& m) { m.unloaded_slider = dem::UnloadedSlider::zero; },
      [](dem::ModelChoice& m) { m.adhesive_dashpot = dem::AdhesiveDashpot::pulloff_cap; },
      [](dem::ModelChoice& m) { m.coulomb_test = dem::CoulombTest::spring; },
      [](dem::ModelChoice& m) { m.constant_torque_form = dem::ConstantTorqueForm::projected; },
      [](dem::ModelChoice& m) { m.contact_at_zero_overlap = true; },
      [](dem::ModelChoice& m) { m.tangential_history = dem::TangentialHistory::increment_project; },
      [](dem::ModelChoice& m) { m.pair_lever_arm = dem::PairLeverArm::radius; },
      [](dem::ModelChoice& m) { m.wall_lever_arm = dem::WallLeverArm::radius; },
      [](dem::ModelChoice& m) { m.friction_limit = dem::FrictionLimit::elastic; },
      [](dem::ModelChoice& m) { m.jkr_rupture = dem::JkrRupture::load; },
      [](dem::ModelChoice& m) { m.clamp_tensile = !m.clamp_tensile; }};
  std::set<std::string> seen{base};
  for (std::size_t k = 0; k < changes.size(); ++k) {
    cases::Scene b = a;
    changes[k](b.model);
    EXPECT_TRUE(seen.insert(store::scene_fingerprint(b)).second) << "change " << k << " left the fingerprint alone";
  }
}

TEST(ResultCache, ReturnsAStoredResultOnlyForTheSameSceneEngineAndVersion) {
  const store::ResultCache cache(scratch("cache"));
  const cases::Scene scene = single_collision();
  const cases::RunResult r = sample_result();
  EXPECT_FALSE(cache.find(scene, "lammps", r.version).hit);
  cache.store(scene, r, r.version);
  const auto found = cache.find(scene, "lammps", r.version);
  ASSERT_TRUE(found.hit) << found.problem;
  EXPECT_EQ(found.problem, "");
  EXPECT_EQ(found.hit->source, "cache");
  EXPECT_EQ(found.hit->trace.values(1)[0], 0.1 + 0.2);
  EXPECT_EQ(found.hit->calibrations.size(), 1U);
  EXPECT_FALSE(cache.find(scene, "lammps", "LAMMPS 2 Aug 2023").hit);
  EXPECT_FALSE(cache.find(scene, "yade", r.version).hit);
  cases::Scene changed = scene;
  changed.integration.timestep = 2.0 * *scene.integration.timestep;
  EXPECT_FALSE(cache.find(changed, "lammps", r.version).hit);
  // Absent is not a problem; only an entry that exists and cannot be trusted is.
  EXPECT_EQ(cache.find(changed, "lammps", r.version).problem, "");
}

TEST(ResultCache, KeepsOnlySuccessfulRunsAndReportsACorruptEntry) {
  const store::ResultCache cache(scratch("corrupt"));
  const cases::Scene scene = single_collision();
  cases::RunResult failed = sample_result();
  failed.status = cases::RunStatus::error;
  cache.store(scene, failed, failed.version);
  EXPECT_FALSE(fs::exists(cache.path_of(scene, "lammps", failed.version)));
  const cases::RunResult ok = sample_result();
  cache.store(scene, ok, ok.version);
  support::write_file(cache.path_of(scene, "lammps", ok.version), "{ not json");
  const auto found = cache.find(scene, "lammps", ok.version);
  EXPECT_FALSE(found.hit);
  EXPECT_NE(found.problem.find("unreadable"), std::string::npos) << found.problem;
}

/// The stored entry of `r` for `scene`, parsed.
nlohmann::ordered_json stored_entry(const store::ResultCache& cache, const cases::Scene& scene, const cases::RunResult& r) {
  return nlohmann::ordered_json::parse(support::read_file(cache.path_of(scene, r.engine, r.version)));
}

TEST(ResultCache, DetectsEveryKindOfTamperingWithAnEntry) {
  const store::ResultCache cache(scratch("tamper"));
  const cases::Scene scene = single_collision();
  const cases::RunResult r = sample_result();
  const fs::path file = cache.path_of(scene, r.engine, r.version);
  using Json = nlohmann::ordered_json;
  // Each edit: what a careless or malicious hand might change. A forged "error" status, a trace
  // scaled by 1 + 1e-5, a forged exact metric, a removed checksum, a checksum recomputed over a
  // result that is not a success.
  const std::vector<std::pair<std::string, std::function<Json(Json)>>> edits = {
      {"trace scaled", [](Json j) {
         // Unpacked, scaled and packed again: a valid column, so only the checksum can tell.
         Json& column = j["result"]["trace"]["columns"]["p0.x"];
         std::vector<double> values = store::unpack_column(column.get<std::string>(), 2);
         values[1] *= 1 + 1e-5;
         column = store::pack_column(values);
         return j;
       }},
      {"exact metric forged", [](Json j) { j["result"]["exact_metrics"]["restitution"] = 0.75; return j; }},
      {"status forged", [](Json j) { j["result"]["status"] = "error"; return j; }},
      {"checksum removed", [](Json j) { j.erase("sha256"); return j; }},
      {"error re-signed", [](Json j) { j["result"]["status"] = "error"; return store::with_checksum(j); }},
      {"engine re-signed", [](Json j) { j["engine"] = "yade"; return store::with_checksum(j); }},
  };
  for (const auto& [what, edit] : edits) {
    cache.store(scene, r, r.version);
    ASSERT_TRUE(cache.find(scene, r.engine, r.version).hit) << what;
    const Json entry = stored_entry(cache, scene, r);
    ASSERT_TRUE(entry.contains("result")) << what;
    support::write_file(file, edit(entry).dump());
    const auto found = cache.find(scene, r.engine, r.version);
    EXPECT_FALSE(found.hit) << what;
    EXPECT_NE(found.problem.find(file.string()), std::string::npos) << what << ": " << found.problem;
  }
}

TEST(ResultCache, WritesEntriesAtomicallyAndLeavesNoTemporaryFiles) {
  const store::ResultCache cache(scratch("atomic"));
  const cases::Scene scene = single_collision();
  const cases::RunResult r = sample_result();
  for (int i = 0; i < 3; ++i) cache.store(scene, r, r.version);
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(cache.dir())) {
    if (!entry.is_regular_file()) continue;
    ++files;
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 1U);
}

TEST(Baseline, RoundTripsAndNamesTheFileWhenUnreadable) {
  const fs::path dir = scratch("baseline");
  store::Baseline b;
  b.case_name = "single_collision";
  b.fingerprint = store::scene_fingerprint(single_collision());
  b.references["lammps"] = sample_result();
  b.inhouse_metrics["restitution"] = 0.9999537;
  store::write_baseline(dir / "single_collision.json", b);
  const store::Baseline back = store::read_baseline(dir / "single_collision.json");
  EXPECT_EQ(back.case_name, b.case_name);
  EXPECT_EQ(back.fingerprint, b.fingerprint);
  EXPECT_EQ(back.inhouse_metrics, b.inhouse_metrics);
  ASSERT_EQ(back.references.count("lammps"), 1U);
  EXPECT_EQ(back.references.at("lammps").calibrations.size(), 1U);
  // An edited baseline fails its checksum and is refused, naming the file.
  auto edited = nlohmann::ordered_json::parse(support::read_file(dir / "single_collision.json"));
  edited["inhouse_metrics"]["restitution"] = 0.99995;
  support::write_file(dir / "edited.json", edited.dump(1));
  try {
    static_cast<void>(store::read_baseline(dir / "edited.json"));
    FAIL() << "an edited baseline was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("edited.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sha256"), std::string::npos) << e.what();
  }
  support::write_file(dir / "broken.json", "[]");
  try {
    static_cast<void>(store::read_baseline(dir / "broken.json"));
    FAIL() << "a malformed baseline was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json"), std::string::npos) << e.what();
  }
}

}  // namespace
