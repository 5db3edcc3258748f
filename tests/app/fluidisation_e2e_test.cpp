// SPDX-License-Identifier: MIT
// End to end: a small bed poured and settled in a box, a lid placed over it when the run starts,
// then blown out sideways by a plug flow (docs/fluidisation.md in miniature). `demwb run` writes the
// ORF curve and its plot; `demwb sweep` writes every seed's curve to bed.csv and plots their mean.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../small_pour.hpp"
#include "demwb_process.hpp"
#include "support/text_file.hpp"

namespace fluidisation_e2e_test {

using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

/// 48 glass spheres (r = 1 mm) settle in a box 6.6 mm wide, those reaching above 4 mm are skimmed,
/// a lid is placed at 4 mm, and a plug flow along +x at `speed` (ramped over 5 ms) blows through the
/// box, whose x+ face is open: the bed leaves at 30 m/s (drag about seven weights), stays at 0.5.
std::string blown_bed(double speed) {
  return test_support::small_pour_head("blown_bed", R"(["z+", "x+"])") + R"([[walls]]
type = "rectangle"
name = "lid"
centre = [3.3e-3, 3.3e-3, 4.0e-3]
normal = [0.0, 0.0, 1.0]
axis = [1.0, 0.0, 0.0]
size = [6.6e-3, 6.6e-3]
material = "glass"
in_preparation = false
[[walls]]
type = "plane"
name = "stop"
point = [6.6e-3, 0.0, 0.0]
normal = [-1.0, 0.0, 0.0]
material = "glass"
in_preparation = true
remove_at = 0.0
[fields]
gravity = [0.0, 0.0, -9.81]
[fields.fluid.plug_flow]
speed = )" + std::to_string(speed) + R"(
ramp_time = 0.005
zones = [{ min = [-1.0, -1.0, -1.0], max = [1.0, 1.0, 1.0], direction = [1.0, 0.0, 0.0] }]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-5
duration = 0.03
[[stages]]
kind = "settle"
kinetic_energy = 1.0e-8
min_duration = 0.05
max_duration = 2.0
remove_above = 4.0e-3
remove_by = "top"
[output]
snapshot_every = 0.002
[compare]
engines = ["inhouse"]
reference = "inhouse"
metrics = ["orf", "dose_remaining", "fluidisation_time", "orf_largest_drop"]
packing = { min = [0.0, 0.0, 0.0], max = [6.6e-3, 6.6e-3, 4.0e-3], orf_grid = [20, 12] }
)";
}

TEST(DemwbFluidisation, ARunWritesItsOrfCurveAndTheFluidisationMetrics) {
  const fs::path dir = scratch("fluidisation_run");
  support::write_file(dir / "blown.toml", blown_bed(30.0));
  const fs::path out = dir / "out";
  const auto r = demwb({"run", (dir / "blown.toml").string(), "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string csv = support::read_file(out / "packing_inhouse.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "time,orf,dose_remaining");
  std::size_t lines = 0;
  for (const char c : csv) lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, 1 + 16U);  // snapshots at 0, 2, …, 30 ms
  const auto results = nlohmann::json::parse(support::read_file(out / "results.json"));
  const auto& metrics = results.at("engines").at("inhouse").at("metrics");
  ASSERT_TRUE(metrics.at("fluidisation_time").is_number()) << results.dump(2);
  const double t = metrics.at("fluidisation_time").get<double>();
  EXPECT_GT(t, 0.002);  // the flow needs its ramp to lift the bed
  EXPECT_LT(t, 0.03);
  EXPECT_EQ(metrics.at("dose_remaining").get<double>(), 0.0);
  EXPECT_GT(metrics.at("orf_largest_drop").get<double>(), 0.0);
  const std::string report = support::read_file(out / "report.md");
  EXPECT_NE(report.find("fluidisation.png"), std::string::npos) << report;
}

TEST(DemwbFluidisation, ASweepWritesEverySeedsCurveAndSaysWhenABedStays) {
  const fs::path dir = scratch("fluidisation_sweep");
  support::write_file(dir / "blown.toml", blown_bed(30.0));
  support::write_file(dir / "blow.toml", R"toml(
[sweep]
name = "blow"
case = "blown.toml"
seeds = [1, 2]
[[parameters]]
key = "fields.fluid.plug_flow.speed"
label = "u (m/s)"
values = [0.5, 30.0]
)toml");
  const fs::path out = dir / "out";
  const auto r = demwb({"sweep", (dir / "blow.toml").string(), "-j", "2", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string bed = support::read_file(out / "bed.csv");
  EXPECT_EQ(bed.substr(0, bed.find('\n')), "point,fields.fluid.plug_flow.speed,seed,engine,time,orf,dose_remaining");
  std::size_t lines = 0;
  for (const char c : bed) lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, 1 + 4 * 16U);  // 2 points × 2 seeds × 16 snapshots
  const auto fingerprint = nlohmann::json::parse(support::read_file(out / "sweep.json"));
  EXPECT_TRUE(fingerprint.contains("bed_csv_sha256"));
  // At 0.5 m/s the bed stays: no fluidisation time, with the reason in sweep.csv.
  const std::string csv = support::read_file(out / "sweep.csv");
  EXPECT_NE(csv.find("did not fluidise"), std::string::npos) << csv;
  const std::string report = support::read_file(out / "report.md");
  EXPECT_NE(report.find("orf_curves_inhouse"), std::string::npos) << report;
}

}  // namespace fluidisation_e2e_test
