// SPDX-License-Identifier: MIT
// The energy plot draws the ledger terms a run used, and keeps matched variants apart.
#include <string>

#include <gtest/gtest.h>

#include "cases/trace.hpp"
#include "reports/energy_plot.hpp"

namespace energy_plot_test {

/// A run whose ledger has kinetic energy and a balance, every other term zero.
cases::RunResult ledger_run(const std::string& engine) {
  cases::RunResult r;
  r.engine = engine;
  r.energy.add_column("time");
  for (const auto q : cases::kEnergyQuantities) r.energy.add_column(std::string(q));
  std::vector<double> row(1 + std::size(cases::kEnergyQuantities), 0.0);
  r.energy.append_row(row);
  row[0] = 1e-3;
  row[1] = 2.5;                                      // kinetic
  row[std::size(cases::kEnergyQuantities)] = 2.5;    // balance
  r.energy.append_row(row);
  return r;
}

TEST(EnergyPlot, DrawsOnlyTermsThatAreNotZeroThroughout) {
  const auto curves = reports::energy_series(ledger_run("inhouse"), true);
  ASSERT_EQ(curves.size(), 2U);
  EXPECT_EQ(curves[0].title, "kinetic");
  EXPECT_EQ(curves[1].title, "balance");
  EXPECT_EQ(curves[0].style, "lines");
  EXPECT_EQ(curves[0].y, (std::vector<double>{0.0, 2.5}));
}

TEST(EnergyPlot, LaterRunsAreNamedByEngineAndDashed) {
  const auto curves = reports::energy_series(ledger_run("inhouse@lammps"), false);
  ASSERT_EQ(curves.size(), 2U);
  EXPECT_EQ(curves[0].title, "kinetic (inhouse@lammps)");
  EXPECT_EQ(curves[0].style, "lines dt 2");
}

TEST(EnergyPlot, ARunWithoutLedgerDrawsNothing) {
  cases::RunResult r;
  r.engine = "lammps";
  EXPECT_TRUE(reports::energy_series(r, true).empty());
}

}  // namespace energy_plot_test
