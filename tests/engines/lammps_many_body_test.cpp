// SPDX-License-Identifier: MIT
// A many-body scene through the real LAMMPS binary: 512 generated spheres (a data file, one atom
// type), walls, gravity; the whole-scene aggregates of both engines.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace lammps_many_body_test {

cases::Scene settling_bed() {
  return cases::load_case(std::string(DEMWB_TEST_DATA_DIR) + "/many_body/settling_bed.toml");
}

TEST(LammpsManyBody, ASettlingBedRunsFromADataFileAndTracesTheSameAggregates) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const cases::Scene scene = settling_bed();
  ASSERT_EQ(scene.particles.size(), 512U);
  ASSERT_TRUE(reference::lammps::atoms_in_data_file(scene));
  const auto core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto lammps = reference::run_engine(reference::LammpsEngine{}, scene, demwb_lammps_test::scratch("settling_bed"));
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  ASSERT_EQ(lammps.trace.columns(), core.trace.columns());
  ASSERT_EQ(lammps.trace.rows(), core.trace.rows());
  EXPECT_EQ(lammps.snapshots.size(), 4U);  // snapshot_every = 0.04 s over 0.12 s
  EXPECT_EQ(core.snapshots.size(), 4U);

  // Both start from the identical explicit scene: the same kinetic energy to round-off.
  const double ke_core = core.trace.column("all.kinetic_energy")->front();
  const double ke_lammps = lammps.trace.column("all.kinetic_energy")->front();
  EXPECT_GT(ke_core, 0.0);
  EXPECT_NEAR(ke_lammps, ke_core, 1e-12 * ke_core);
  EXPECT_EQ(core.trace.column("all.coordination_number")->front(), 0.0);  // lattice with gaps
  EXPECT_EQ(lammps.trace.column("all.coordination_number")->front(), 0.0);

  // Settled: a packed bed in both, the same to within the chaos of 512 frictional spheres.
  const double z_core = core.trace.column("all.coordination_number")->back();
  const double z_lammps = lammps.trace.column("all.coordination_number")->back();
  EXPECT_GT(z_core, 3.0);
  EXPECT_GT(z_lammps, 3.0);
  EXPECT_LT(std::abs(z_core - z_lammps), 0.15 * z_core);
}

}  // namespace
