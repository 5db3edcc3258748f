// SPDX-License-Identifier: MIT
// The log reader `demwb bench` times LAMMPS and LIGGGHTS with, on both codes' log formats.
#include <gtest/gtest.h>

#include "bench/lammps_log.hpp"

namespace {

TEST(BenchLog, ReadsALiggghtsLogWithItsMemoryLineAndTimeBreakdown) {
  // The end of a LIGGGHTS-PUBLIC 3.8.0 log (LAMMPS 2013's formats).
  const char* text =
      "Memory usage per processor = 5.13404 Mbytes\n"
      "    Step    Atoms         KinEng            CPU \n"
      "       0     2000  2.5641056e-05              0 \n"
      "     200     2000   7.553062e-06    0.061501028 \n"
      "Loop time of 0.0615315 on 1 procs for 200 steps with 2000 atoms, finish time Sun Dec  6 15:29:16 2026\n"
      "\n\n"
      "Pair  time (%) = 0.050545 (82.1449)\n"
      "Neigh time (%) = 0.001 (1.6)\n"
      "Comm  time (%) = 1.1395e-05 (0.018519)\n"
      "Outpt time (%) = 5.1168e-05 (0.0831574)\n"
      "Other time (%) = 0.010924 (17.7535)\n"
      "\n"
      "Nlocal:    2000 ave 2000 max 2000 min\n"
      "Neighbor list builds = 0\n";
  const bench::LammpsLog log = bench::parse_lammps_log(text);
  EXPECT_DOUBLE_EQ(log.loop_s, 0.0615315);
  EXPECT_EQ(log.steps, 200U);
  EXPECT_EQ(log.atoms, 2000U);
  EXPECT_EQ(log.procs, 1);
  EXPECT_DOUBLE_EQ(log.memory_mb_per_rank, 5.13404);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Pair"), 0.050545);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Neigh"), 0.001);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Other"), 0.010924);
  ASSERT_EQ(log.thermo.size(), 2U);
  EXPECT_DOUBLE_EQ(log.thermo[1].values.at("KinEng"), 7.553062e-06);
}

TEST(BenchLog, ReadsALammpsLogWithItsSectionTable) {
  const char* text =
      "Per MPI rank memory allocation (min/avg/max) = 16.09 | 16.09 | 16.09 Mbytes\n"
      "   Step          Atoms         KinEng    \n"
      "       100       32000   784292.08     \n"
      "Loop time of 0.534174 on 2 procs for 100 steps with 32000 atoms\n"
      "\n"
      "MPI task timing breakdown:\n"
      "Section |  min time  |  avg time  |  max time  |%varavg| %total\n"
      "---------------------------------------------------------------\n"
      "Pair    | 0.33346    | 0.33346    | 0.33346    |   0.0 | 62.43\n"
      "Neigh   | 0.05       | 0.06       | 0.07       |   0.0 | 11.2\n"
      "Other   |            | 0.02153    |            |       |  4.03\n"
      "\n";
  const bench::LammpsLog log = bench::parse_lammps_log(text);
  EXPECT_DOUBLE_EQ(log.loop_s, 0.534174);
  EXPECT_EQ(log.procs, 2);
  EXPECT_EQ(log.atoms, 32000U);
  EXPECT_DOUBLE_EQ(log.memory_mb_per_rank, 16.09);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Pair"), 0.33346);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Neigh"), 0.06);
  EXPECT_DOUBLE_EQ(log.breakdown_s.at("Other"), 0.02153);
}

TEST(BenchLog, AnEmptyOrDamagedLogHasNoLoopTime) {
  for (const char* text : {"", "garbage\n\x01\x02", "Loop time of x on y procs\n", "Pair  time (%) = (1)\n"}) {
    const bench::LammpsLog log = bench::parse_lammps_log(text);
    EXPECT_EQ(log.steps, 0U) << text;
    EXPECT_EQ(log.loop_s, 0.0) << text;
  }
}

}  // namespace
