// SPDX-License-Identifier: MIT
// The committed baselines (cases/baselines/) stay small and lose nothing: every reference trace
// is stored packed, packing is exact on the real traces, every metric computed from a stored
// trace equals the one computed from the plain trace, and the folder keeps to its size budget.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "compare/metrics.hpp"
#include "store/packed_column.hpp"
#include "store/result_cache.hpp"
#include "support/text_file.hpp"

namespace committed_baselines_test {

namespace fs = std::filesystem;

const fs::path kBaselines = fs::path(DEMWB_SOURCE_DIR) / "cases" / "baselines";

/// Each baseline (a case's JSON file, or a stored sweep's folder) and all of them together. The
/// total was 1.5 MB for two reference codes (1.4 MB used); LIGGGHTS' results on seven two-body
/// cases added 0.16 MB, so the whole may take 2 MB. The fluidisation study's sensitivity sweeps
/// (friction, restitution, friction spring, plug speed: about 0.1 MB each, the evidence
/// docs/fluidisation.md cites) brought it to 2.15 MB, so 2.5 MB; the lactose wall-adhesion and
/// friction sweeps and the two flow-zone sweeps to 2.52 MB, so 3 MB: room for a few more such
/// studies at ~0.1 MB each. Each stored sweep still keeps under the 0.3 MB of one baseline.
constexpr std::uintmax_t kMaxBaselineBytes = 300'000;
constexpr std::uintmax_t kMaxTotalBytes = 3'000'000;

/// Bytes of the regular files under `path` (or of `path` itself).
std::uintmax_t bytes_of(const fs::path& path) {
  if (fs::is_regular_file(path)) return fs::file_size(path);
  std::uintmax_t total = 0;
  for (const auto& e : fs::recursive_directory_iterator(path)) {
    if (e.is_regular_file()) total += e.file_size();
  }
  return total;
}

/// The committed case baselines.
std::vector<fs::path> case_baselines() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kBaselines)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// `trace` with every column taken through plain JSON numbers, the form baselines had before
/// they were packed (17 significant digits round-trip a double).
cases::Trace through_plain_json(const cases::Trace& trace) {
  cases::Trace out;
  std::vector<std::vector<double>> columns;
  for (std::size_t c = 0; c < trace.columns().size(); ++c) {
    out.add_column(trace.columns()[c]);
    columns.push_back(nlohmann::json::parse(nlohmann::json(trace.values(c)).dump()).get<std::vector<double>>());
  }
  for (std::size_t r = 0; r < trace.rows(); ++r) {
    std::vector<double> row;
    for (const auto& c : columns) row.push_back(c[r]);
    out.append_row(row);
  }
  return out;
}

TEST(CommittedBaselines, KeepToTheirSizeBudget) {
  std::uintmax_t total = 0;
  for (const auto& e : fs::directory_iterator(kBaselines)) {
    if (e.is_regular_file()) {
      EXPECT_LT(bytes_of(e.path()), kMaxBaselineBytes) << e.path();
      total += bytes_of(e.path());
    }
  }
  if (fs::exists(kBaselines / "sweeps")) {
    for (const auto& e : fs::directory_iterator(kBaselines / "sweeps")) {
      EXPECT_LT(bytes_of(e.path()), kMaxBaselineBytes) << e.path();
      total += bytes_of(e.path());
    }
  }
  EXPECT_LT(total, kMaxTotalBytes);
}

TEST(CommittedBaselines, StoreEveryTracePackedAndExactly) {
  const auto files = case_baselines();
  ASSERT_FALSE(files.empty());
  std::size_t columns_checked = 0;
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const auto raw = nlohmann::ordered_json::parse(support::read_file(file));
    const store::Baseline baseline = store::read_baseline(file);
    for (const auto& [engine, result] : baseline.references) {
      for (const char* which : {"trace", "energy"}) {
        const auto& stored = raw.at("references").at(engine).at(which);
        const cases::Trace& trace = std::string(which) == "trace" ? result.trace : result.energy;
        if (trace.columns().empty()) continue;
        ASSERT_EQ(stored.value("encoding", ""), "demwb-packed-1") << engine << " " << which << " is not packed";
        // Packing the decoded values again gives the stored text: decoding lost nothing. A column
        // stored as "=<name>" repeats an earlier column bit for bit, whose text it must pack to.
        for (std::size_t c = 0; c < trace.columns().size(); ++c) {
          std::string text = stored.at("columns").at(trace.columns()[c]).get<std::string>();
          if (text.starts_with('=')) {
            const std::string source = text.substr(1);
            const auto& names = trace.columns();
            const auto at = std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(c), source);
            ASSERT_NE(at, names.begin() + static_cast<std::ptrdiff_t>(c)) << engine << " " << names[c] << " -> " << source;
            EXPECT_EQ(trace.values(static_cast<std::size_t>(at - names.begin())), trace.values(c)) << names[c];
            text = stored.at("columns").at(source).get<std::string>();
          }
          EXPECT_EQ(store::pack_column(trace.values(c)), text) << engine << " " << trace.columns()[c];
          ++columns_checked;
        }
      }
    }
  }
  EXPECT_GT(columns_checked, 100U);
}

TEST(CommittedBaselines, GiveTheSameMetricsAsTheirPlainTraces) {
  std::size_t metrics_checked = 0;
  for (const auto& file : case_baselines()) {
    SCOPED_TRACE(file.filename().string());
    const store::Baseline baseline = store::read_baseline(file);
    const fs::path case_file = fs::path(DEMWB_SOURCE_DIR) / "cases" / "canonical" / (baseline.case_name + ".toml");
    ASSERT_TRUE(fs::exists(case_file)) << case_file;
    const cases::Scene scene = cases::load_case(case_file);
    for (const auto& [engine, stored] : baseline.references) {
      cases::RunResult plain = stored;
      plain.trace = through_plain_json(stored.trace);
      const auto from_stored = comparison::compute_metrics(scene, stored, nullptr);
      const auto from_plain = comparison::compute_metrics(scene, plain, nullptr);
      ASSERT_EQ(from_stored.size(), from_plain.size());
      for (const auto& [name, value] : from_stored) {
        const auto& other = from_plain.at(name);
        ASSERT_EQ(value.value.has_value(), other.value.has_value()) << engine << " " << name;
        if (value.value) {
          EXPECT_EQ(std::bit_cast<std::uint64_t>(*value.value), std::bit_cast<std::uint64_t>(*other.value))
              << engine << " " << name;
          ++metrics_checked;
        }
        EXPECT_EQ(value.problem, other.problem) << engine << " " << name;
      }
    }
  }
  EXPECT_GT(metrics_checked, 20U);
}

}  // namespace committed_baselines_test
