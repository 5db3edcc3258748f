// SPDX-License-Identifier: MIT
// The committed hopper sweep (cases/baselines/sweeps/hopper_beverloo/, run outside CI): its flow
// rates, read back from sweep.csv, fit Beverloo's law with C and k in the ranges measured for
// spheres, on every engine it ran. Its freshness (fingerprint) is CommittedSweeps' check.
#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_file.hpp"
#include "sweeps/sweep_report.hpp"
#include "sweeps/sweep_spec.hpp"

namespace stored_beverloo_test {

namespace fs = std::filesystem;

const fs::path kSource = DEMWB_SOURCE_DIR;

/// The fields of one sweep.csv line (quoted fields unquoted).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else {
        quoted = !quoted;
      }
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

/// sweep.csv's rows, for a sweep of `axes` axes and `metrics` metrics.
std::vector<sweeps::SweepRow> read_rows(const fs::path& csv, std::size_t axes, std::size_t metrics) {
  std::istringstream in(support::read_file(csv));
  std::string line;
  std::getline(in, line);  // the header
  std::vector<sweeps::SweepRow> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = split_csv(line);
    EXPECT_EQ(f.size(), 1 + axes + 3 + metrics + 1) << line;
    if (f.size() != 1 + axes + 3 + metrics + 1) continue;
    sweeps::SweepRow r{std::stoul(f[0]), std::stoull(f[1 + axes]), f[2 + axes], f[3 + axes], {}, f.back()};
    for (std::size_t m = 0; m < metrics; ++m) {
      const std::string& v = f[4 + axes + m];
      r.values.push_back(v.empty() ? std::nullopt : std::optional<double>(std::stod(v)));
    }
    rows.push_back(r);
  }
  return rows;
}

TEST(StoredBeverloo, TheCommittedHopperSweepFitsBeverloosLawOnEveryEngineItRan) {
  const sweeps::SweepSpec spec = sweeps::load_sweep(kSource / "cases/sweeps/hopper_beverloo.toml");
  ASSERT_TRUE(spec.beverloo.has_value());
  // The core and a reference code: Beverloo's law on both, not on the core alone.
  ASSERT_NE(std::find(spec.engines.begin(), spec.engines.end(), "lammps"), spec.engines.end());
  ASSERT_NE(std::find(spec.engines.begin(), spec.engines.end(), "inhouse"), spec.engines.end());
  const auto points = sweeps::expand(spec);
  const std::vector<sweeps::SweepRow> rows =
      read_rows(kSource / "cases/baselines/sweeps/hopper_beverloo/sweep.csv", spec.axes.size(), spec.metrics.size());
  ASSERT_EQ(rows.size(), points.size() * spec.seeds.size() * spec.engines.size());
  for (const auto& r : rows) EXPECT_EQ(r.status, "ok") << r.engine << " point " << r.point << ": " << r.reason;
  const sweeps::SweepResults results{spec, points, spec.engines, spec.metrics, rows, "", 0.0, 1};
  const std::vector<sweeps::EngineBeverloo> fits = sweeps::beverloo_fits(results);
  ASSERT_EQ(fits.size(), spec.engines.size());
  ASSERT_FALSE(fits.empty());
  for (const auto& e : fits) {
    SCOPED_TRACE(e.engine);
    ASSERT_TRUE(e.fit.has_value()) << e.problem;
    EXPECT_EQ(e.fit->points, 4U);
    // Spheres through a round orifice: C 0.5–0.7 and k 1–3 (Beverloo 1961; Nedderman's review).
    EXPECT_GE(e.fit->c, 0.5);
    EXPECT_LE(e.fit->c, 0.7);
    EXPECT_GE(e.fit->k, 1.0);
    EXPECT_LE(e.fit->k, 3.0);
    // A settled monodisperse bed: ρ_b between random loose and random close packing × 2500 kg/m³.
    EXPECT_GT(e.bulk_density, 0.55 * 2500.0);
    EXPECT_LT(e.bulk_density, 0.64 * 2500.0);
    // The law describes the four rates (it is not a line through scattered points).
    EXPECT_LT(e.fit->largest_misfit, 0.1);
  }
}

}  // namespace stored_beverloo_test
