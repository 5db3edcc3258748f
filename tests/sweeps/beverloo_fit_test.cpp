// SPDX-License-Identifier: MIT
// Beverloo's law: the fit recovers C and k from rates the law itself gives, refuses data it cannot
// fit, and a hopper sweep's report tables and plots it per engine.
#include <cmath>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_file.hpp"
#include "sweeps/beverloo_fit.hpp"
#include "sweeps/sweep_report.hpp"

namespace beverloo_fit_test {

constexpr double kGrain = 2e-3;
constexpr double kBulk = 1450.0;
constexpr double kG = 9.81;

TEST(BeverlooFit, RecoversCAndKFromTheLawsOwnRates) {
  std::vector<double> d;
  std::vector<double> w;
  for (const double n : {5.0, 6.0, 7.0, 8.0}) {
    d.push_back(n * kGrain);
    // W = 0.58 · 1450 · √9.81 · (D − 1.4 d)^2.5, written out for D = n d.
    w.push_back(0.58 * kBulk * std::sqrt(kG) * std::pow((n - 1.4) * kGrain, 2.5));
  }
  const auto fit = sweeps::fit_beverloo(d, w, kBulk, kG, kGrain);
  ASSERT_TRUE(fit.has_value());
  EXPECT_NEAR(fit->c, 0.58, 1e-12);
  EXPECT_NEAR(fit->k, 1.4, 1e-10);
  EXPECT_EQ(fit->points, 4U);
  EXPECT_LT(fit->largest_misfit, 1e-12);
  EXPECT_NEAR(sweeps::beverloo_rate(0.58, 1.4, kBulk, kG, 6.0 * kGrain, kGrain), w[1], 1e-15);
  EXPECT_EQ(sweeps::beverloo_rate(0.58, 1.4, kBulk, kG, 1.0 * kGrain, kGrain), 0.0);  // D < k d: no flow
}

TEST(BeverlooFit, RefusesWhatItCannotFit) {
  const std::vector<double> d{0.010, 0.012};
  EXPECT_FALSE(sweeps::fit_beverloo(std::vector<double>{0.010}, std::vector<double>{0.01}, kBulk, kG, kGrain));
  EXPECT_FALSE(sweeps::fit_beverloo(d, std::vector<double>{0.02, 0.01}, kBulk, kG, kGrain));  // falls with D
  EXPECT_FALSE(sweeps::fit_beverloo(d, std::vector<double>{0.0, 0.01}, kBulk, kG, kGrain));   // a zero rate
  EXPECT_FALSE(sweeps::fit_beverloo(std::vector<double>{0.01, 0.01}, std::vector<double>{0.01, 0.02}, kBulk, kG, kGrain));
  EXPECT_FALSE(sweeps::fit_beverloo(d, std::vector<double>{0.01, 0.02}, 0.0, kG, kGrain));
}

TEST(BeverlooFit, AHopperSweepsReportTablesAndPlotsItPerEngine) {
  sweeps::SweepSpec spec;
  spec.name = "hopper";
  spec.seeds = {1, 2};
  spec.axes = {{"walls[1].base_radius", "orifice radius (m)", {5e-3, 6e-3, 7e-3}, false}};
  spec.beverloo = sweeps::BeverlooSpec{0, 2.0, kGrain, 2500.0, "mass_flow_rate", "packing_fraction", kG};
  const auto points = sweeps::expand(spec);
  const std::vector<std::string> engines{"inhouse", "lammps"};
  const std::vector<std::string> metrics{"mass_flow_rate", "packing_fraction"};
  // Seeds scatter ±2 % about the law with C = 0.6, k = 1.5 (inhouse) or C = 0.55 (lammps), at φ = 0.58.
  std::vector<sweeps::SweepRow> rows;
  for (const auto& p : points) {
    for (const std::uint64_t seed : spec.seeds) {
      for (const auto& engine : engines) {
        const double c = engine == "inhouse" ? 0.6 : 0.55;
        const double w = c * 0.58 * 2500.0 * std::sqrt(kG) * std::pow(2.0 * p.values[0] - 1.5 * kGrain, 2.5) *
                         (seed == 1 ? 1.02 : 0.98);
        rows.push_back({p.index, seed, engine, "ok", {w, 0.58}, ""});
      }
    }
  }
  const sweeps::SweepResults results{spec, points, engines, metrics, rows, "demwb sweep hopper.toml", 1.0, 1};
  const auto fits = sweeps::beverloo_fits(results);
  ASSERT_EQ(fits.size(), 2U);
  ASSERT_TRUE(fits[0].fit.has_value()) << fits[0].problem;
  EXPECT_NEAR(fits[0].bulk_density, 1450.0, 1e-9);
  EXPECT_NEAR(fits[0].fit->c, 0.6, 1e-9);  // the seeds' ±2 % cancel in the mean
  EXPECT_NEAR(fits[0].fit->k, 1.5, 1e-7);
  EXPECT_NEAR(fits[1].fit->c, 0.55, 1e-9);
  EXPECT_EQ(fits[0].orifice, (std::vector<double>{10e-3, 12e-3, 14e-3}));

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-beverloo-report";
  std::filesystem::remove_all(dir);
  sweeps::write_sweep_report(results, dir);
  const std::string md = support::read_file(dir / "report.md");
  EXPECT_NE(md.find("## Beverloo's law"), std::string::npos);
  EXPECT_NE(md.find("| inhouse | 1450.0 | 0.600 | 1.50 | 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| lammps | 1450.0 | 0.550 | 1.50 | 3 |"), std::string::npos) << md;
  EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "beverloo.dat") ||
              md.find("`plots/beverloo.png` not drawn") != std::string::npos);

  // Without the packing fraction there is nothing to fit, and the report says so.
  const std::vector<std::string> rate_only{"mass_flow_rate"};
  const sweeps::SweepResults partial{spec, points, engines, rate_only, rows, "demwb sweep hopper.toml", 1.0, 1};
  const auto none = sweeps::beverloo_fits(partial);
  ASSERT_EQ(none.size(), 2U);
  EXPECT_FALSE(none[0].fit.has_value());
  EXPECT_NE(none[0].problem.find("packing_fraction"), std::string::npos);
}

}  // namespace beverloo_fit_test
