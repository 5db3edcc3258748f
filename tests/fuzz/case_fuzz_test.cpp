// SPDX-License-Identifier: MIT
// Fuzz test of the case loader (issue 14, item 7): every case file of cases/canonical/ and
// cases/ensembles/ (and the malformed ones of tests/data/bad_cases/) mutated in seeded,
// deterministic ways and loaded with cases::load_case_text. Loading must return a sane scene or
// throw cases::CaseError with a one-line message; any other exception, a crash, a hang (a
// watchdog aborts) or a sanitizer report fails. A scene small enough is also run briefly through
// the in-house engine (its trace must have the rows and columns the output estimate counted) and
// written as a LAMMPS deck and a YADE script (no injected `shell` line).
//
// Environment: DEMWB_FUZZ_CASES (inputs, default 3000), DEMWB_FUZZ_SEED (default 14),
// DEMWB_FUZZ_ONLY (replay the one input of that index), DEMWB_FUZZ_KEEP=1 (keep every input's
// text in the temporary directory, not only failing ones), DEMWB_FUZZ_TIMEOUT_S (per input,
// default 60). Inputs slower than a second are listed. A long run:
//   DEMWB_FUZZ_CASES=100000 tests/fuzz_tests --gtest_filter='CaseFuzz.Mutated*'
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "case_mutator.hpp"
#include "cases/case_loader.hpp"
#include "cases/output_budget.hpp"
#include "reference/common/engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/scene_support.hpp"
#include "reference/yade/script_writer.hpp"
#include "scene_sanity.hpp"
#include "support/text_file.hpp"

namespace case_fuzz_test {

namespace fs = std::filesystem;

/// Most particle-steps of a scene the test runs through the in-house engine.
constexpr double kRunBudget = 20'000.0;
/// Widest scene (extent of the centres over the smallest radius) the test runs.
constexpr double kMaxSpread = 1.0e4;
/// Inputs taking longer than this [s] are listed (not a failure: the watchdog judges hangs).
constexpr double kSlowInput = 1.0;
/// Most failing inputs reported in detail before the test stops.
constexpr std::size_t kMaxReported = 10;
/// Name the mutated texts are loaded under.
const std::string kFile = "fuzz.toml";

/// An unsigned setting from the environment, or `fallback`.
std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  if (v == nullptr || *v == '\0') return fallback;
  return std::stoull(v);
}

/// The .toml files of `dir`, sorted.
std::vector<fs::path> tomls(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::exists(dir)) return out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".toml") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The seed texts: every case file of the library (canonical and ensemble cases; sweep files are
/// not case files), then every malformed case file.
std::vector<std::string> corpus(std::size_t& good) {
  const fs::path root(DEMWB_SOURCE_DIR);
  std::vector<std::string> out;
  for (const char* dir : {"cases/canonical", "cases/ensembles"}) {
    for (const fs::path& file : tomls(root / dir)) {
      static_cast<void>(cases::load_case(file));  // a seed that does not load is a broken library
      out.push_back(support::read_file(file));
    }
  }
  good = out.size();
  for (const fs::path& file : tomls(fs::path(DEMWB_TEST_DATA_DIR) / "bad_cases")) out.push_back(support::read_file(file));
  return out;
}

/// Aborts the process when one input takes longer than the timeout: a hang is a failure.
class Watchdog {
 public:
  explicit Watchdog(std::chrono::seconds timeout) : timeout_(timeout), thread_([this] { watch(); }) {}
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
  ~Watchdog() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  /// Input `index` starts now; `dump` is where its text was saved.
  void start(std::uint64_t index, std::string dump) {
    const std::lock_guard<std::mutex> lock(mutex_);
    index_ = index;
    dump_ = std::move(dump);
    started_ = std::chrono::steady_clock::now();
    busy_ = true;
  }
  /// The input finished.
  void stop() {
    const std::lock_guard<std::mutex> lock(mutex_);
    busy_ = false;
  }

 private:
  /// The watching thread: wakes five times a second and aborts on an input past the timeout.
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_) {
      wake_.wait_for(lock, std::chrono::milliseconds(200));
      if (busy_ && std::chrono::steady_clock::now() - started_ > timeout_) {
        std::cerr << "fuzz input " << index_ << " ran for more than " << timeout_.count() << " s (a hang); its text: "
                  << dump_ << std::endl;
        std::abort();
      }
    }
  }
  std::chrono::seconds timeout_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool busy_ = false;
  std::uint64_t index_ = 0;
  std::string dump_;
  std::chrono::steady_clock::time_point started_;
  std::thread thread_;
};

/// Where the text of input `index` is saved while it runs (for a crash or a hang) or kept when
/// it fails.
fs::path dump_path(std::uint64_t seed, std::uint64_t index) {
  return fs::temp_directory_path() / fmt::format("demwb_fuzz_{}_{}_{}.toml", ::getpid(), seed, index);
}

/// Extent of the scene's sphere centres over its smallest radius, along the widest axis. The core
/// cuts space into up to 65536 slabs of the longest pair, and walks them all at every force
/// evaluation: spheres 1e300 m apart are fine but slow, so such scenes are not run.
double spread(const cases::Scene& scene) {
  double widest = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 3; ++k) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const cases::ParticleSpec& p : scene.particles) {
      lo = std::min(lo, p.position[k]);
      hi = std::max(hi, p.position[k]);
      smallest = std::min(smallest, p.radius);
    }
    widest = std::max(widest, hi - lo);
  }
  return widest / smallest;
}

/// What the run through the engines found; empty when nothing is wrong.
std::vector<std::string> run_problems(const cases::Scene& scene, bool& ran) {
  std::vector<std::string> out;
  ran = false;
  if (!scene.stages.empty()) return out;  // stages run in prepare/, not here
  const cases::OutputEstimate e = cases::estimate_output(scene);
  if (!std::isfinite(e.timestep)) return out;
  if (static_cast<double>(e.steps) * static_cast<double>(scene.particles.size()) > kRunBudget) return out;
  if (!(spread(scene) < kMaxSpread)) return out;
  ran = true;
  try {
    const cases::RunResult r = reference::InhouseEngine{}.run(scene, reference::RunOptions{});
    if (r.trace.rows() != e.trace_rows || r.trace.columns().size() != e.trace_columns) {
      out.push_back(fmt::format("the in-house trace has {} rows × {} columns; the estimate counted {} × {}",
                                r.trace.rows(), r.trace.columns().size(), e.trace_rows, e.trace_columns));
    }
    if (r.snapshots.size() > e.snapshots) {
      out.push_back(fmt::format("{} snapshots; the estimate counted {}", r.snapshots.size(), e.snapshots));
    }
  } catch (const std::exception&) {
    // An engine may refuse a scene (no analytic past states, no contact for "auto"): not a crash.
  }
  const auto injected = [](const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      const auto first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line.compare(first, 5, "shell") == 0) return true;
    }
    return false;
  };
  // The writers are called as the engines call them: only for a scene the engine supports.
  try {
    if (reference::LammpsEngine{}.supports(scene).supported()) {
      reference::lammps::DeckSettings settings;
      settings.timestep = e.timestep;
      settings.steps = e.steps;
      const std::string deck = reference::lammps::write_deck(scene, settings);
      if (injected(deck)) out.emplace_back("the LAMMPS deck holds a `shell` line");
    }
  } catch (const std::exception&) {
    // LAMMPS cannot express every model: not a crash.
  }
  try {
    const reference::yade::YadeRunPlan plan = reference::yade::make_run_plan(reference::PreparedScene(scene));
    if (reference::yade::unsupported_scene_features(scene).empty() && plan.model.reasons.empty()) {
      const std::string script = reference::yade::write_yade_script(scene, plan);
      if (injected(script)) out.emplace_back("the YADE script holds a `shell` line");
    }
  } catch (const std::exception&) {
    // YADE cannot express every model: not a crash.
  }
  return out;
}

TEST(CaseFuzz, TheCorpusHoldsEveryCanonicalAndEnsembleCase) {
  std::size_t good = 0;
  const auto texts = corpus(good);
  const fs::path root(DEMWB_SOURCE_DIR);
  ASSERT_GT(good, 0U) << "no seed case found under " << root;
  EXPECT_EQ(good, tomls(root / "cases/canonical").size() + tomls(root / "cases/ensembles").size());
  EXPECT_GT(texts.size(), good);
}

TEST(CaseFuzz, MutationsAreDeterministicAndChangeTheText) {
  std::size_t good = 0;
  const std::vector<std::string> texts = corpus(good);
  const fuzz::CaseMutator a(texts, good, 7);
  const fuzz::CaseMutator b(texts, good, 7);
  std::size_t changed = 0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    const fuzz::Mutant m = a.mutant(k);
    EXPECT_EQ(m.text, b.mutant(k).text) << k;
    EXPECT_FALSE(m.steps.empty());
    if (m.text != texts[m.seed_file]) ++changed;
  }
  EXPECT_GT(changed, 180U);
  EXPECT_NE(a.mutant(0).text, fuzz::CaseMutator(texts, good, 8).mutant(0).text);
}

TEST(CaseFuzz, MutatedCasesLoadSanelyOrFailWithACaseError) {
  const std::uint64_t count = env_or("DEMWB_FUZZ_CASES", 3000);
  const std::uint64_t seed = env_or("DEMWB_FUZZ_SEED", 14);
  const std::uint64_t only = env_or("DEMWB_FUZZ_ONLY", UINT64_MAX);
  const bool keep = env_or("DEMWB_FUZZ_KEEP", 0) != 0;
  std::size_t good = 0;
  const std::vector<std::string> texts = corpus(good);
  const fuzz::CaseMutator mutator(texts, good, seed);
  Watchdog watchdog(std::chrono::seconds(env_or("DEMWB_FUZZ_TIMEOUT_S", 60)));
  std::size_t inputs = 0;
  std::size_t loaded = 0;
  std::size_t refused = 0;
  std::size_t runs = 0;
  std::size_t failed = 0;
  const auto begin = std::chrono::steady_clock::now();
  for (std::uint64_t k = only == UINT64_MAX ? 0 : only; k < count || k == only; ++k) {
    const fuzz::Mutant m = mutator.mutant(k);
    const fs::path dump = dump_path(seed, k);
    {
      std::ofstream(dump, std::ios::binary) << m.text;
    }
    watchdog.start(k, dump.string());
    const auto started = std::chrono::steady_clock::now();
    ++inputs;
    std::vector<std::string> problems;
    try {
      const cases::Scene scene = cases::load_case_text(m.text, kFile);
      ++loaded;
      problems = fuzz::scene_problems(scene);
      bool ran = false;
      for (std::string& p : run_problems(scene, ran)) problems.push_back(std::move(p));
      runs += ran ? 1 : 0;
    } catch (const cases::CaseError& e) {
      ++refused;
      problems = fuzz::error_problems(e, kFile);
    } catch (const std::exception& e) {
      problems.push_back(fmt::format("threw {} instead of cases::CaseError: {}", typeid(e).name(), e.what()));
    } catch (...) {
      problems.emplace_back("threw something that is not a std::exception");
    }
    watchdog.stop();
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (took > kSlowInput) {
      std::cout << fmt::format("fuzz: input {} took {:.2f} s ({})\n", k, took, fmt::join(m.steps, "; "));
    }
    if (problems.empty()) {
      if (!keep) fs::remove(dump);
      if (k == only) break;
      continue;
    }
    ++failed;
    std::string report =
        fmt::format("input {} (seed {}, corpus text {}, kept in {}):", k, seed, m.seed_file, dump.string());
    for (const std::string& s : m.steps) report += "\n  mutation: " + s;
    for (const std::string& p : problems) report += "\n  problem: " + p;
    ADD_FAILURE() << report;
    if (failed >= kMaxReported || k == only) break;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::cout << fmt::format("fuzz: {} inputs (seed {}) in {:.1f} s: {} loaded ({} run through the engines), {} "
                           "refused with a CaseError, {} failed\n",
                           inputs, seed, seconds, loaded, runs, refused, failed);
  EXPECT_EQ(failed, 0U);
}

}  // namespace
