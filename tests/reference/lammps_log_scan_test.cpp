// SPDX-License-Identifier: MIT
// Version banner, errors and warnings read from captured LAMMPS logs.
#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/common/log_lines.hpp"
#include "reference/lammps/log_scan.hpp"
#include "support/text_file.hpp"

namespace lammps_log_scan_test {

using namespace reference::lammps;
using reference::first_error;
using reference::warning_lines;

std::string captured(const std::string& name) {
  return support::read_file(demwb_lammps_unit::data_file(name));
}

TEST(LammpsLogScan, ReadsTheVersionFromTheBanner) {
  EXPECT_EQ(banner_version(captured("single_collision.log.lammps")),
            "LAMMPS 29 Sep 2021 - Update 2");
  EXPECT_FALSE(banner_version("Total wall time: 0:00:00\n").has_value());
}

TEST(LammpsLogScan, FindsTheErrorAndTheCommandThatCausedIt) {
  EXPECT_EQ(first_error(captured("unknown_command.log.lammps")),
            "ERROR: Unknown command: this_is_not_a_command (src/input.cpp:274) "
            "(Last command: this_is_not_a_command)");
  EXPECT_EQ(first_error(captured("single_collision.log.lammps")), "");
}

TEST(LammpsLogScan, CollectsWarnings) {
  EXPECT_TRUE(warning_lines(captured("single_collision.log.lammps")).empty());
  EXPECT_EQ(warning_lines("x\nWARNING: one (src/a.cpp:1)\ny\nWARNING: two\n"),
            (std::vector<std::string>{"WARNING: one (src/a.cpp:1)", "WARNING: two"}));
}

}  // namespace
