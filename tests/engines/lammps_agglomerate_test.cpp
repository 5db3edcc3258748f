// SPDX-License-Identifier: MIT
// The JKR agglomerate's physics through the real LAMMPS binary, in the conventions LAMMPS
// expresses exactly (cases/ensembles/agglomerate_jkr_lammps.toml): a 27-sphere adhesive cluster
// hits a non-adhesive wall at 45°. Before chaos can act, the two codes' runs are the same run:
// energies and every sphere's final position agree at round-off, through the adhesive necks'
// vibration, the impact, friction at the wall and between spheres, and necks breaking.
#include <cmath>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace lammps_agglomerate_test {

cases::Scene cluster() {
  return cases::load_case(std::string(DEMWB_TEST_DATA_DIR) + "/many_body/jkr_cluster_wall.toml");
}

TEST(LammpsAgglomerate, AJkrClusterHittingAWallIsTheSameRunInBothCodes) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const cases::Scene scene = cluster();
  ASSERT_EQ(scene.particles.size(), 27U);
  const reference::LammpsEngine lammps_engine;
  ASSERT_TRUE(lammps_engine.supports(scene).reasons.empty()) << lammps_engine.supports(scene).reasons.front();
  const auto core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto lammps = reference::run_engine(lammps_engine, scene, demwb_lammps_test::scratch("jkr_cluster_wall"));
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  ASSERT_EQ(lammps.trace.rows(), core.trace.rows());

  const auto* ke_core = core.trace.column("all.kinetic_energy");
  const auto* ke_lammps = lammps.trace.column("all.kinetic_energy");
  const auto* rot_core = core.trace.column("all.rotational_energy");
  const auto* rot_lammps = lammps.trace.column("all.rotational_energy");
  ASSERT_NE(ke_core, nullptr);
  ASSERT_NE(ke_lammps, nullptr);
  ASSERT_NE(rot_core, nullptr);
  ASSERT_NE(rot_lammps, nullptr);
  // The impact happened: a fifth of the kinetic energy is gone and the spheres spin.
  EXPECT_LT(ke_core->back(), 0.85 * ke_core->front());
  EXPECT_GT(rot_core->back(), 1e-4);
  for (std::size_t k = 0; k < ke_core->size(); ++k) {
    EXPECT_NEAR((*ke_lammps)[k], (*ke_core)[k], 1e-12 * (*ke_core)[k]) << "sample " << k;
    EXPECT_NEAR((*rot_lammps)[k], (*rot_core)[k], 1e-10 * (*rot_core)[k] + 1e-18) << "sample " << k;
  }
  ASSERT_FALSE(core.snapshots.empty());
  ASSERT_FALSE(lammps.snapshots.empty());
  const auto& a = core.snapshots.back();
  const auto& b = lammps.snapshots.back();
  ASSERT_EQ(a.position.size(), b.position.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.position.size(); ++i) {
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(a.position[i][d] - b.position[i][d]));
  }
  EXPECT_LT(worst, 1e-12) << "largest position difference (m)";
}

}  // namespace
