// SPDX-License-Identifier: MIT
// The output a run would hold in memory (cases/output_budget.hpp): the estimate's parts, the
// budget check and where it points, and the time step and duration the estimate resolves.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/output_budget.hpp"
#include "cases/time_step.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"
#include "dem/timestep/timestep_control.hpp"
#include "case_texts.hpp"

namespace output_budget_test {

using cases::CaseError;

/// kPair traced: 100 steps, every 10th traced, the energy ledger, two snapshots, two engines
/// (output.trace_every on line 29).
const std::string kTraced = std::string(case_texts::kPair) + R"(
[output]
trace_every = 10
trace_energy = true
snapshot_times = [0.0, 5.0e-4]

[compare]
engines = ["inhouse", "analytic"]
)";

TEST(OutputBudget, TheEstimateCountsRowsColumnsSnapshotsAndEngines) {
  const cases::Scene s = cases::load_case_text(kTraced, "traced.toml");
  const cases::OutputEstimate e = cases::estimate_output(s);
  EXPECT_EQ(e.steps, 100U);
  EXPECT_EQ(e.trace_rows, 11U);       // t = 0 and every 10th step
  EXPECT_EQ(e.trace_columns, 13U);    // time and the 12 of the one moving sphere
  EXPECT_EQ(e.energy_columns, 14U);   // time and the 13 of the ledger
  EXPECT_EQ(e.snapshots, 2U);
  EXPECT_EQ(e.snapshot_values, 19U);  // time and 9 per sphere
  EXPECT_EQ(e.engines, 2U);
  EXPECT_EQ(e.engine_bytes, 8U * (11U * 27U + 2U * 19U));
  EXPECT_EQ(e.text_bytes, cases::kCsvBytesPerValue * 11U * 27U);
  EXPECT_EQ(e.bytes, 2U * e.engine_bytes + e.text_bytes);
  EXPECT_EQ(cases::estimate_output_bytes(s), e.bytes);
}

TEST(OutputBudget, MatchedEnginesCountAsEngines) {
  std::string text(kTraced);
  text.replace(text.find("engines = [\"inhouse\", \"analytic\"]"), 33,
               "engines = [\"inhouse\", \"lammps\", \"yade\"]\nmatched = [\"lammps\", \"yade\"]");
  EXPECT_EQ(cases::estimate_output(cases::load_case_text(text, "m.toml")).engines, 5U);
}

TEST(OutputBudget, AnOversizedTraceNamesTraceEveryAtItsLine) {
  const cases::Scene s = cases::load_case_text(kTraced, "traced.toml");
  try {
    cases::check_output_budget(s, 1000, "traced.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "output.trace_every");
    EXPECT_EQ(std::string(e.what()).rfind("traced.toml:29:15: output.trace_every: ", 0), 0U) << e.what();
    EXPECT_NE(e.problem().find("more than the limit of 1000 bytes"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("integration.duration"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("11 rows × 13 columns + 14 energy columns"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(cases::check_output_budget(s, cases::estimate_output_bytes(s), "traced.toml"));
}

TEST(OutputBudget, ManySnapshotsNameSnapshotEvery) {
  std::string text(kTraced);
  text.replace(text.find("snapshot_times = [0.0, 5.0e-4]"), 30, "snapshot_every = 1.0e-8");
  const cases::Scene s = cases::load_case_text(text, "snap.toml");
  EXPECT_EQ(cases::estimate_output(s).snapshots, 100001U);
  try {
    cases::check_output_budget(s, 1000, "snap.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "output.snapshot_every") << e.what();
  }
}

TEST(OutputBudget, ASceneWithoutTextIsRefusedWithoutAPosition) {
  cases::Scene s = cases::load_case_text(kTraced, "traced.toml");
  s.source_text.clear();
  try {
    cases::check_output_budget(s, 10, "built.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("built.toml: output.trace_every: ", 0), 0U) << e.what();
  }
}

TEST(OutputBudget, TheLoadOptionSetsTheLimit) {
  cases::LoadOptions tight;
  tight.max_output_bytes = 1000;
  EXPECT_THROW(static_cast<void>(cases::load_case_text(kTraced, "traced.toml", tight)), CaseError);
  EXPECT_NO_THROW(static_cast<void>(cases::load_case_text(kTraced, "traced.toml")));
}

TEST(OutputBudget, TheDefaultLimitIsThePhysicalMemory) {
  EXPECT_GE(cases::physical_memory_bytes(), std::uint64_t{64} << 20U) << "no machine this runs on has less";
  // A billion steps, four engines, everything traced: terabytes, refused by default.
  std::string text(kTraced);
  text.replace(text.find("timestep = 1.0e-5\nduration = 1.0e-3"), 35, "timestep = 1.0e-9\nduration = 1.0");
  text.replace(text.find("trace_every = 10"), 16, "trace_every = 1\ntrace_particles = [0, 1]");
  text.replace(text.find("engines = [\"inhouse\", \"analytic\"]"), 33,
               "engines = [\"inhouse\", \"analytic\", \"lammps\", \"yade\"]");
  try {
    static_cast<void>(cases::load_case_text(text, "huge.toml"));
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "output.trace_every");
  }
}

TEST(OutputBudget, EveryCanonicalCaseNeedsLittleMemory) {
  const auto dir = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases" / "canonical";
  std::size_t seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    ++seen;
    EXPECT_LT(cases::estimate_output_bytes(cases::load_case(entry.path())), 200U << 20U) << entry.path();
  }
  EXPECT_GE(seen, 10U) << dir;
}

/// Three materials, fixed and moving spheres of several sizes and speeds, a wall, gravity.
constexpr std::string_view kMixed = R"([case]
name = "mixed"
[model]
normal = "hertz"
damping = "tsuji"
[materials.glass]
density = 2500.0
youngs_modulus = 6.0e10
poisson_ratio = 0.25
restitution = 0.9
[materials.steel]
density = 7800.0
youngs_modulus = 2.0e11
poisson_ratio = 0.3
restitution = 0.8
[materials.rubber]
density = 1100.0
youngs_modulus = 1.0e7
poisson_ratio = 0.45
restitution = 0.6
[[particles]]
radius = 0.01
material = "glass"
position = [0.0, 0.0, 0.1]
velocity = [1.0, 0.0, 0.0]
[[particles]]
radius = 0.004
material = "glass"
position = [0.1, 0.0, 0.1]
velocity = [0.0, -3.0, 0.0]
[[particles]]
radius = 0.02
material = "steel"
position = [0.2, 0.0, 0.1]
fixed = true
[[particles]]
radius = 0.003
material = "rubber"
position = [0.3, 0.0, 0.1]
velocity = [0.5, 0.5, 0.0]
[[particles]]
radius = 0.05
material = "steel"
position = [0.5, 0.0, 0.1]
velocity = [0.0, 0.0, -0.2]
[[walls]]
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "rubber"
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = "auto"
duration = 0.01
)";

TEST(TimeStep, TheAutomaticStepFromTheSphereCensusIsTheCoresStep) {
  const cases::Scene s = cases::load_case_text(kMixed, "mixed.toml");
  // The core's own computation over every sphere (reference/common/core_setup.cpp).
  std::vector<dem::ParticleInit> inits;
  for (const cases::ParticleSpec& p : s.particles) {
    inits.push_back({p.radius, p.effect_radius, s.materials[p.material].density, static_cast<std::uint32_t>(p.material),
                     dem::Vec3(p.position[0], p.position[1], p.position[2]),
                     dem::Vec3(p.velocity[0], p.velocity[1], p.velocity[2]), dem::Vec3::Zero(), p.fixed, 0.0});
  }
  dem::ParticleProperties props;
  dem::KinematicState state;
  dem::build_particles(inits, props, state);
  const dem::PairTable table(s.materials, s.mixing, s.pair_overrides, s.model);
  const dem::TimestepLimits full =
      dem::timestep_limits(props, state, table, dem::Vec3(0.0, 0.0, -9.81), true, 20.0, {2});
  const dem::TimestepLimits fast = cases::scene_timestep_limits(s, table);
  EXPECT_EQ(fast.cundall_strack, full.cundall_strack);
  EXPECT_EQ(fast.collision_duration, full.collision_duration);
  EXPECT_EQ(cases::run_timestep(s), dem::automatic_timestep(full));
  EXPECT_GT(cases::estimate_output(s).steps, 1U);
}

TEST(TimeStep, ALaunchedRunLastsEq51FromTheListedSpheres) {
  const std::string text = R"([case]
name = "launched"
[model]
normal = "linear"
damping = "restitution"
[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5
restitution = 0.5
[[particles]]
radius = 0.01
material = "glass"
position = [0.0, 0.0, 0.5]
[[particles]]
radius = 0.01
material = "glass"
position = [0.04, 0.0, 0.5]
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "glass"
[[stages]]
kind = "launch"
wall = "floor"
speed = 2.0
angle = 30.0
direction = [1.0, 0.0, 0.0]
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = "launch"
)";
  const cases::Scene s = cases::load_case_text(text, "launched.toml");
  // L_A = 2 (0.02 + 0.01) about the centre of mass; t_max = 4 L_A / (u sin θ).
  EXPECT_NEAR(cases::run_duration(s), 4.0 * 0.06 / (2.0 * std::sin(std::numbers::pi / 6.0)), 1e-12);
  EXPECT_EQ(cases::estimate_output(s).snapshots, 2U);
}

}  // namespace
