// SPDX-License-Identifier: MIT
// Every canonical case, prepared (agglomerate formation and launch run in the core) and run on
// the in-house engine with its energy ledger traced: the balance
// stays within 1e-9 of the largest ledger term over the whole run (docs/physics.md, "Energy
// ledger"), and every row of the trace carries finite numbers. The many-body cases run at a CI
// size (ci_size below).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/trace.hpp"
#include "prepare/prepare_scene.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace inhouse_energy_ledger_test {

const std::filesystem::path kCanonical = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical";

/// The canonical case files, sorted.
std::vector<std::string> canonical_files() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(kCanonical)) {
    if (entry.path().extension() == ".toml") out.push_back(entry.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Spheres from which a case counts as many-body, and how much of such a case the test runs.
constexpr std::size_t kManyBodySpheres = 500;
constexpr double kManyBodyWindow = 5.0e-3;  // s

/// `scene` at the size CI runs: a many-body case (the packing box, the reservoir, the hopper) runs its first
/// kManyBodyWindow seconds, and each settle stage stops after as long, settled or not, so that
/// the ledger still sees spheres poured into walls, skimmed and colliding (minutes instead of
/// seconds otherwise). DEMWB_LEDGER_WHOLE_RUNS=1 runs every case whole.
cases::Scene ci_size(cases::Scene scene) {
  const char* whole = std::getenv("DEMWB_LEDGER_WHOLE_RUNS");
  if ((whole != nullptr && std::string(whole) == "1") || scene.particles.size() < kManyBodySpheres) return scene;
  scene.integration.duration = std::min(scene.integration.duration, kManyBodyWindow);
  // Rows enough to see the ledger move within the window (the hopper traces every 5,000 steps,
  // and its window is under a thousand).
  scene.output.trace_every = std::min<std::size_t>(scene.output.trace_every, 100);
  std::erase_if(scene.output.snapshot_times, [](double t) { return t > kManyBodyWindow; });
  for (cases::StageSpec& stage : scene.stages) {
    if (auto* settle = std::get_if<cases::SettleStageSpec>(&stage.action)) {
      settle->min_duration = std::min(settle->min_duration, kManyBodyWindow);
      settle->max_duration = 2.0 * kManyBodyWindow;
      settle->kinetic_energy = std::numeric_limits<double>::max();  // settled once min_duration has passed
    }
  }
  return scene;
}

class CanonicalLedger : public ::testing::TestWithParam<std::string> {};

TEST_P(CanonicalLedger, BalancesToOnePartInABillion) {
  cases::Scene scene = prepare::prepare_scene(ci_size(cases::load_case(kCanonical / GetParam())), {});
  scene.output.trace_energy = true;
  const cases::RunResult r = reference::run_engine(reference::InhouseEngine{}, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  ASSERT_GT(r.energy.rows(), 2U);
  const std::vector<double>& balance = *r.energy.column("energy.balance");
  double scale = 0.0;
  for (const auto name : cases::kEnergyQuantities) {
    const std::vector<double>& v = *r.energy.column(name);
    for (const double x : v) {
      ASSERT_TRUE(std::isfinite(x)) << name;
      if (name != "energy.balance") scale = std::max(scale, std::abs(x));
    }
  }
  ASSERT_GT(scale, 0.0);
  double drift = 0.0;
  for (const double b : balance) drift = std::max(drift, std::abs(b - balance.front()));
  EXPECT_LE(drift, 1e-9 * scale) << "drift " << drift / scale << " of the largest term";
  // The ledger's integration error is the scheme's, not a missing path: far below the scale.
  double error = 0.0;
  for (const double x : *r.energy.column("energy.integration_error")) error = std::max(error, std::abs(x));
  EXPECT_LE(error, 1e-2 * scale);
}

INSTANTIATE_TEST_SUITE_P(Cases, CanonicalLedger, ::testing::ValuesIn(canonical_files()),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           return p.param.substr(0, p.param.size() - 5);
                         });

}  // namespace inhouse_energy_ledger_test
