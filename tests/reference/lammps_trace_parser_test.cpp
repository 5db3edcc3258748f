// SPDX-License-Identifier: MIT
// Reading `fix print` output captured from real LAMMPS runs (tests/data/lammps/).
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/common/fix_print_table.hpp"
#include "reference/lammps/trace_columns.hpp"
#include "support/text_file.hpp"

namespace lammps_trace_parser_test {

using demwb_lammps_unit::data_file;
using demwb_lammps_unit::data_scene;
using reference::lammps::assemble_trace;
using reference::parse_fix_print;

std::string captured(const std::string& name) { return support::read_file(data_file(name)); }

/// The message of the std::runtime_error `f` throws, or "" when it does not throw.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(LammpsTraceParser, ReadsTheCapturedSingleCollisionTrace) {
  const cases::Trace t = parse_fix_print(captured("single_collision.trace.txt"), "trace.txt");
  ASSERT_EQ(t.columns().size(), 17u);
  EXPECT_EQ(t.columns().front(), "step");
  EXPECT_EQ(t.columns().back(), "c0-1.fn_exact");
  ASSERT_EQ(t.rows(), 161u);
  EXPECT_EQ(t.column("p0.vx")->front(), 4.0);
  EXPECT_EQ(t.column("time")->at(1), 5.0000000000000004e-06);  // all 17 digits
  EXPECT_EQ(t.column("c0-1.overlap")->front(), -0.00020000000000000573);
}

TEST(LammpsTraceParser, AssemblesTheInhouseColumnsAndSampleTimes) {
  const cases::Scene scene = data_scene("single_collision");
  const cases::Trace printed =
      parse_fix_print(captured("single_collision.trace.txt"), "trace.txt");
  const auto assembled = assemble_trace(scene, printed, 160);
  EXPECT_TRUE(assembled.warnings.empty());
  const cases::Trace& t = assembled.trace;
  std::vector<std::string> expected{"time"};
  for (const auto q : cases::kParticleQuantities) expected.push_back(cases::particle_column(0, q));
  expected.push_back("c0-1.overlap");
  expected.push_back("c0-1.fn");
  EXPECT_EQ(t.columns(), expected);
  ASSERT_EQ(t.rows(), 161u);
  for (std::size_t k = 0; k < t.rows(); ++k) {
    EXPECT_EQ(t.column("time")->at(k), static_cast<double>(k) * 5e-6) << "row " << k;
  }
  // The pair force is what LAMMPS applied: the mobile sphere's force, opposite in sign (to the
  // last bits: fn is that force projected on the pair normal).
  for (std::size_t k = 0; k < t.rows(); ++k) {
    EXPECT_DOUBLE_EQ(t.column("c0-1.fn")->at(k), -t.column("p0.fx")->at(k)) << "row " << k;
  }
}

TEST(LammpsTraceParser, KeepsEveryNthStepWhenTraceEveryIsLarger) {
  const cases::Scene scene = data_scene("sandwich_damped_every4");
  const cases::Trace printed =
      parse_fix_print(captured("sandwich_damped_every4.trace.txt"), "trace.txt");
  const auto assembled = assemble_trace(scene, printed, 260);
  ASSERT_EQ(assembled.trace.rows(), 66u);
  EXPECT_EQ(assembled.trace.column("time")->at(65), 260 * 5e-6);
  EXPECT_TRUE(assembled.warnings.empty());
}

TEST(LammpsTraceParser, WarnsWhenPerAtomForcesCannotIsolateAPair) {
  const cases::Scene scene = data_scene("chain_inexact");
  const cases::Trace printed = parse_fix_print(captured("chain_inexact.trace.txt"), "trace.txt");
  const auto assembled = assemble_trace(scene, printed, 4);
  ASSERT_EQ(assembled.warnings.size(), 1u);
  EXPECT_NE(assembled.warnings.front().find("c1-2.fn: at 5 of 5 rows"), std::string::npos);
}

TEST(LammpsTraceParser, RejectsATraceWithTheWrongSteps) {
  const cases::Scene scene = data_scene("single_collision");
  const cases::Trace printed =
      parse_fix_print(captured("single_collision.trace.txt"), "trace.txt");
  EXPECT_NE(error_of([&] { (void)assemble_trace(scene, printed, 200); })
                .find("has 161 rows; expected 201"),
            std::string::npos);
  cases::Trace shifted;
  for (const auto& name : printed.columns()) shifted.add_column(name);
  std::vector<double> row(printed.columns().size(), 0.0);
  shifted.append_row(row);
  row[0] = 2.0;
  shifted.append_row(row);
  EXPECT_EQ(error_of([&] { (void)assemble_trace(scene, shifted, 1); }),
            "LAMMPS trace file row 1 is step 2; expected step 1");
}

TEST(LammpsTraceParser, NamesTheLineOfATruncatedRow) {
  std::string text = captured("single_collision.trace.txt");
  text.resize(text.size() - 40);  // the run was killed while writing the last row
  EXPECT_NE(error_of([&] { (void)parse_fix_print(text, "trace.txt"); })
                .find("trace.txt line 162: "),
            std::string::npos);
}

TEST(LammpsTraceParser, NamesTheLineAndColumnOfABadValue) {
  EXPECT_EQ(error_of([] { (void)parse_fix_print("# a b\n1 2\n3 x4\n", "f.txt"); }),
            "f.txt line 3: value 2 of column 'b' is \"x4\", not a number");
  EXPECT_EQ(error_of([] { (void)parse_fix_print("# a b\n1 2 3\n", "f.txt"); }),
            "f.txt line 2: 3 values for 2 columns");
  EXPECT_EQ(error_of([] { (void)parse_fix_print("1 2\n", "f.txt"); }),
            "f.txt line 1: expected the header \"# name …\", found \"1 2\"");
  EXPECT_EQ(error_of([] { (void)parse_fix_print("# a a\n", "f.txt"); }),
            "f.txt line 1: column 'a' appears twice");
  EXPECT_EQ(error_of([] { (void)parse_fix_print("", "f.txt"); }),
            "f.txt is empty (no header line)");
}

TEST(LammpsTraceParser, AcceptsWhatPrintfWritesForSpecialValues) {
  const cases::Trace t = parse_fix_print("# a b c d\n-0 nan -nan inf\n", "f.txt");
  EXPECT_EQ(t.column("a")->front(), 0.0);
  EXPECT_TRUE(std::isnan(t.column("b")->front()));
  EXPECT_TRUE(std::isnan(t.column("c")->front()));
  EXPECT_TRUE(std::isinf(t.column("d")->front()));
}

}  // namespace
