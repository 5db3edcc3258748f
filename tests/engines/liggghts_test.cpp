// SPDX-License-Identifier: MIT
// The real LIGGGHTS (ctest -L reference): every canonical two-body case it expresses runs, and the
// core in LIGGGHTS' numerics (inhouse@liggghts) reproduces its traces at round-off; the Hertz
// dashpot written from ε rebounds with ε; cohesion cases are n/a with the reason.
#include <algorithm>
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/liggghts/atom_types.hpp"
#include "reference/liggghts/liggghts_engine.hpp"
#include "reference/matching.hpp"

namespace liggghts_engine_test {

using demwb_lammps_test::canonical;

bool liggghts_installed() { return support::find_program("liggghts").has_value(); }

/// Run options with a scratch directory of the running test.
reference::RunOptions scratch(const std::string& run) {
  reference::RunOptions o;
  o.work_dir = std::filesystem::temp_directory_path() / "demwb-liggghts-tests" /
               demwb_engine_test::current_test_folder() / run;
  std::error_code ignored;
  std::filesystem::remove_all(o.work_dir, ignored);
  o.timeout_s = 120.0;
  return o;
}

/// The matched trace deviation (docs/metrics.md) of the core in LIGGGHTS' numerics against LIGGGHTS.
double matched_deviation(const cases::Scene& scene, const std::string& name) {
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch(name));
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  EXPECT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  EXPECT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  std::string problem;
  const auto d = comparison::trace_deviation(scene, core, liggghts, problem);
  EXPECT_TRUE(d.has_value()) << problem;
  return d ? d->whole : 1.0;
}

TEST(LiggghtsCanonical, EveryExpressedTwoBodyCaseMatchesTheCoreInLiggghtsNumerics) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed (scripts/setup.sh installs it)";
  for (const char* name : {"single_collision", "sandwich", "hertz_collision", "hertz_damped_collision",
                           "rigid_wall_hertz", "sliding_block", "oblique_wall_impact"}) {
    SCOPED_TRACE(name);
    const cases::Scene scene = canonical(name);
    ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported())
        << reference::LiggghtsEngine{}.supports(scene).explain();
    const double d = matched_deviation(scene, name);
    std::cout << fmt::format("  {:<24} whole-trace deviation {:.3e}\n", name, d);
    // The matched gate (1e-8); sliding_block's whole trace drifts to 1.4e-10 past its round-off
    // horizon (a one-ulp nudge of the start does the same), the others stay below 1e-14.
    EXPECT_LE(d, 1e-8);
  }
}

TEST(LiggghtsNative, TheHertzDashpotFromTheRestitutionReboundsWithIt) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  // hertz_damped_collision at a fine step: LIGGGHTS' own integration error is then far below
  // the 1e-3 asked of the rebound, which is the Tsuji dashpot's exact ε = 0.5.
  cases::Scene scene = canonical("hertz_damped_collision");
  scene.integration.timestep = 2e-7;
  scene.output.trace_every = 50;
  const cases::RunResult r = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("fine"));
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason << "\n" << r.log_tail;
  const std::vector<double>& va = *r.trace.column("p0.vx");
  const std::vector<double>& vb = *r.trace.column("p1.vx");
  const double before = scene.particles[0].velocity[0] - scene.particles[1].velocity[0];
  const double after = va.back() - vb.back();
  EXPECT_NEAR(-after / before, 0.5, 1e-3);
  EXPECT_EQ(r.conventions.at("version"), "LIGGGHTS-PUBLIC 3.8.0");
}

TEST(LiggghtsCanonical, CohesiveCasesAreNotApplicableWithTheReason) {
  for (const char* name : {"jkr_pulloff", "linear_cohesion_pair"}) {
    const reference::Support s = reference::LiggghtsEngine{}.supports(canonical(name));
    EXPECT_FALSE(s.supported()) << name;
    EXPECT_NE(s.explain().find("sjkr"), std::string::npos) << s.explain();
  }
}

TEST(LiggghtsManyBody, APolydispersePourFromADataFileFollowsTheCoreUntilItsContactsAmplifyRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  // 150 spheres of Gaussian radii: atoms from a data file, one type per material, diameters per
  // atom. Every position of LIGGGHTS and of the core in its numerics agrees to round-off while the
  // spheres fall and meet the floor (3e-18 m at 27 ms); from about 25 ms on the contacts between the
  // spheres amplify the codes' different summation orders tenfold per 3 ms (1e-13 m by 45 ms), as a
  // one-ulp nudge of the core's own start does (docs/metrics.md, "Round-off horizon").
  const cases::Scene scene = cases::load_case(std::filesystem::path(DEMWB_TEST_DATA_DIR) / "many_body" /
                                              "liggghts_pour.toml");
  ASSERT_GT(scene.particles.size(), reference::liggghts::kMaxInlineAtoms);
  ASSERT_TRUE(reference::liggghts::classify(scene).per_atom_diameter);
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("pour"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(liggghts.trace.rows(), core.trace.rows());
  ASSERT_EQ(liggghts.trace.columns(), core.trace.columns());
  // Positions to 1e-15 m; every other column (velocities, spins, forces, the pair's overlap and
  // fn, the energies) to 1e-9 of its largest value: a mapping error (a diameter, a density, a
  // dashpot) shows at order one; the coordination number exactly.
  for (std::size_t c = 1; c < core.trace.columns().size(); ++c) {
    const std::string& name = core.trace.columns()[c];
    const std::string q = name.substr(name.find('.') + 1);
    const std::vector<double>& a = core.trace.values(c);
    const std::vector<double>& b = liggghts.trace.values(c);
    double scale = 0.0;
    double worst = 0.0;
    for (std::size_t r = 0; r < a.size(); ++r) {
      scale = std::max(scale, std::abs(b[r]));
      worst = std::max(worst, std::abs(a[r] - b[r]));
    }
    if (q == "x" || q == "y" || q == "z") {
      EXPECT_LE(worst, 1e-15) << name << " [m], over 30 ms";
    } else if (name == "all.coordination_number") {
      EXPECT_EQ(worst, 0.0) << name;
    } else {
      EXPECT_LE(worst, 1e-9 * scale) << name << " (largest " << scale << ")";
    }
  }
  const std::vector<double>& z = *core.trace.column("all.coordination_number");
  EXPECT_GT(*std::max_element(z.begin(), z.end()), 0.0);  // the spheres did meet each other
}

}  // namespace liggghts_engine_test
