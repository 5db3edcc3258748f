// SPDX-License-Identifier: MIT
// sweep.csv rows, their trip between MPI ranks, and the sweep report's figures.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "support/text_file.hpp"
#include "sweeps/sweep_report.hpp"
#include "sweeps/sweep_rows.hpp"

namespace sweep_rows_test {

namespace fs = std::filesystem;

/// How the report writes a separation above 2.
std::string fmt_separation(double z) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "**%.2f**", z);
  return buf;
}

/// A 3 × 2 sweep over two made-up keys, seeds 1 and 2.
sweeps::SweepSpec spec_3x2() {
  sweeps::SweepSpec s;
  s.name = "grid";
  s.seeds = {1, 2};
  s.axes = {{"a.x", "x (m)", {1.0, 10.0, 100.0}, true}, {"a.y", "μ", {0.5, 0.25}, false}};
  return s;
}

TEST(SweepRows, SurviveTheTripBetweenRanksExactly) {
  const double awkward = std::nextafter(0.1, 1.0);
  std::vector<sweeps::SweepRun> runs{
      {3, {{1, 2, "inhouse", "ok", {awkward, std::nullopt, 1e-300, -0.0}, "kappa_damage: no contacts"}}, 1.25},
      {0, {{0, 1, "lammps", "error", {std::nullopt}, "crashed, \"quoted\"\nline"}}, 0.0}};
  const auto back = sweeps::decode_runs(sweeps::encode_runs(runs));
  ASSERT_EQ(back.size(), 2U);
  EXPECT_EQ(back[0].job, 3U);
  EXPECT_EQ(back[0].seconds, 1.25);
  const auto& r = back[0].rows.at(0);
  EXPECT_EQ(r.point, 1U);
  EXPECT_EQ(r.seed, 2U);
  EXPECT_EQ(r.engine, "inhouse");
  ASSERT_EQ(r.values.size(), 4U);
  EXPECT_EQ(*r.values[0], awkward);  // bit for bit
  EXPECT_FALSE(r.values[1].has_value());
  EXPECT_EQ(*r.values[2], 1e-300);
  EXPECT_EQ(back[1].rows.at(0).reason, "crashed, \"quoted\"\nline");
  EXPECT_THROW(static_cast<void>(sweeps::decode_runs("[{\"job\": 1}]")), std::runtime_error);
  EXPECT_THROW(static_cast<void>(sweeps::decode_runs("not json")), std::runtime_error);
}

TEST(SweepRows, CsvHasOneColumnPerAxisAndMetricAndQuotesReasons) {
  const auto spec = spec_3x2();
  const auto points = sweeps::expand(spec);
  std::vector<sweeps::SweepRow> rows{{4, 1, "inhouse", "ok", {0.5, std::nullopt}, ""},
                                     {5, 2, "yade", "error", {std::nullopt, std::nullopt}, "a, b"}};
  EXPECT_EQ(sweeps::sweep_csv(spec, points, {"kappa_vol", "fragments"}, rows),
            "point,a.x,a.y,seed,engine,status,kappa_vol,fragments,reason\n"
            "4,100,0.5,1,inhouse,ok,0.5,,\n"
            "5,100,0.25,2,yade,error,,,\"a, b\"\n");
  const auto errors = sweeps::error_rows(2, 7, {"inhouse", "lammps"}, 3, "no formation");
  ASSERT_EQ(errors.size(), 2U);
  EXPECT_EQ(errors[1].engine, "lammps");
  EXPECT_EQ(errors[1].status, "error");
  EXPECT_EQ(errors[1].values.size(), 3U);
}

TEST(SweepRows, PointStatisticsTakeOnePointAndEngine) {
  std::vector<sweeps::SweepRow> rows{{0, 1, "inhouse", "ok", {1.0}, ""}, {0, 2, "inhouse", "ok", {3.0}, ""},
                                     {0, 3, "inhouse", "error", {std::nullopt}, "x"}, {0, 1, "lammps", "ok", {9.0}, ""},
                                     {1, 1, "inhouse", "ok", {7.0}, ""}};
  const auto s = sweeps::point_statistics(rows, 0, "inhouse", 0);
  EXPECT_EQ(s.count, 2U);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(*s.standard_error, 1.0);  // s.d. √2, over √2
  EXPECT_EQ(sweeps::point_statistics(rows, 0, "lammps", 0).count, 1U);
  EXPECT_EQ(sweeps::point_statistics(rows, 2, "inhouse", 0).count, 0U);
}

TEST(SweepReport, CurveFamiliesHoldTheOtherAxesAtTheirMiddle) {
  sweeps::SweepSpec s;
  s.axes = {{"k", "k", {1, 2, 3}, false}, {"e", "e", {4}, false}, {"m", "m", {5, 6, 7}, false}};
  const auto families = sweeps::curve_families(s);
  ASSERT_EQ(families.size(), 2U);  // the single-valued axis gives none
  EXPECT_EQ(families[0].x_axis, 0U);
  EXPECT_EQ(families[0].family, std::optional<std::size_t>(2));
  EXPECT_EQ(families[1].x_axis, 2U);
  EXPECT_EQ(families[1].family, std::optional<std::size_t>(0));  // wraps round
  EXPECT_EQ(families[0].held, (std::vector<std::size_t>{1, 0, 1}));
  EXPECT_EQ(sweeps::point_at(s, {2, 0, 1}), 7U);
  EXPECT_EQ(sweeps::expand(s)[7].values, (std::vector<double>{3, 4, 6}));
}

TEST(SweepReport, TablesEngineComparisonAndFigures) {
  const auto spec = spec_3x2();
  const auto points = sweeps::expand(spec);
  const std::vector<std::string> engines{"inhouse", "lammps"};
  const std::vector<std::string> metrics{"kappa_vol", "kappa_damage", "cohesive_work"};
  std::vector<sweeps::SweepRow> rows;
  for (const auto& p : points) {
    for (const std::uint64_t seed : spec.seeds) {
      const double base = 0.1 * static_cast<double>(p.index + 1);
      const double jitter = seed == 1 ? 0.01 : -0.01;
      rows.push_back({p.index, seed, "inhouse", "ok", {base + jitter, base / 2 + jitter, 1e-6 * p.values[0]}, ""});
      // lammps agrees except at point 4, where it is far off.
      const double shift = p.index == 4 ? 0.5 : 0.0;
      rows.push_back({p.index, seed, "lammps", "ok", {base + shift - jitter, base / 2 + jitter, 1e-6 * p.values[0]}, ""});
    }
  }
  const fs::path dir = fs::temp_directory_path() / ("sweep_report_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  sweeps::write_sweep_report({spec, points, engines, metrics, rows, "demwb sweep grid.toml", 12.5, 2}, dir);
  const std::string md = support::read_file(dir / "report.md");
  EXPECT_NE(md.find("on 2 MPI ranks"), std::string::npos);
  EXPECT_NE(md.find("## inhouse"), std::string::npos);
  EXPECT_NE(md.find("## lammps"), std::string::npos);
  EXPECT_NE(md.find("0.1 ± 0.01 (n = 2)"), std::string::npos) << md;
  // Point 4: Δ = 0.5 against a combined standard error of √(0.01² + 0.01²).
  EXPECT_NE(md.find(fmt_separation(0.5 / std::sqrt(2e-4))), std::string::npos) << md;
  // Against x (a curve per y), against y (a curve per x), and damage against cohesive work.
  for (const char* png : {"kappa_vol_vs_x.png", "kappa_damage_vs_x.png", "kappa_vol_vs_y.png",
                          "kappa_damage_vs_cohesive_work.png"}) {
    EXPECT_TRUE(fs::exists(dir / "plots" / png)) << png << "\n" << md;
    EXPECT_NE(md.find(std::string("(plots/") + png + ")"), std::string::npos) << png;
  }
  // The data beside a figure hold the means and their error bars.
  const std::string dat = support::read_file(dir / "plots" / "kappa_vol_vs_x.dat");
  EXPECT_NE(dat.find("# lammps, μ = 0.25"), std::string::npos) << dat;  // files named by key, curves by label
  fs::remove_all(dir);
}

}  // namespace
