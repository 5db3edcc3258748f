// SPDX-License-Identifier: MIT
// Snapshot steps by the in-house rule, and `dump custom` output captured from LAMMPS.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/common/dump_text.hpp"
#include "reference/common/dump_snapshots.hpp"
#include "support/text_file.hpp"

namespace lammps_snapshot_test {

using reference::parse_dump;
using reference::snapshots_from_dump;

TEST(LammpsSnapshots, ReadsTheCapturedDump) {
  const auto frames = parse_dump(
      support::read_file(demwb_lammps_unit::data_file("single_collision.snapshots.dump")),
      "snapshots.dump");
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[1].step, 74u);
  EXPECT_EQ(frames[1].columns.front(), "id");
  ASSERT_EQ(frames[2].rows.size(), 2u);

  const auto snaps = snapshots_from_dump(frames, {0, 74, 160}, 5e-6, 2, "LAMMPS");
  ASSERT_EQ(snaps.size(), 3u);
  EXPECT_EQ(snaps[0].time, 0.0);
  EXPECT_EQ(snaps[1].time, 74 * 5e-6);
  EXPECT_EQ(snaps[0].velocity[0], (cases::Vector3{4.0, 0.0, 0.0}));
  EXPECT_EQ(snaps[2].position[1], (cases::Vector3{0.11020000000000001, 0.0, 0.0}));
  EXPECT_LT(snaps[2].velocity[0][0], 0.0);  // rebounded
}

TEST(LammpsSnapshots, RejectsMissingStepsAtomsAndColumns) {
  const auto frames = parse_dump(
      support::read_file(demwb_lammps_unit::data_file("single_collision.snapshots.dump")),
      "snapshots.dump");
  EXPECT_THROW((void)snapshots_from_dump(frames, {75}, 5e-6, 2, "LAMMPS"), std::runtime_error);
  EXPECT_THROW((void)snapshots_from_dump(frames, {0}, 5e-6, 3, "LAMMPS"), std::runtime_error);
  auto without_omega = frames;
  without_omega[0].columns.back() = "tqz";
  EXPECT_THROW((void)snapshots_from_dump(without_omega, {0}, 5e-6, 2, "LAMMPS"), std::runtime_error);
}

TEST(LammpsSnapshots, NamesTheLineOfAMalformedDump) {
  const std::string text =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
      "ITEM: ATOMS id x\n1 0.5\n2\n";
  try {
    (void)parse_dump(text, "d.dump");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "d.dump line 11: 1 values for 2 columns");
  }
  try {
    (void)parse_dump("ITEM: TIMESTEP\n0\nITEM: ATOMS id\n", "d.dump");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "d.dump line 3: expected \"ITEM: NUMBER OF ATOMS\", found \"ITEM: ATOMS id\"");
  }
}

}  // namespace
