// SPDX-License-Identifier: MIT
// The YADE driver's CSV parsers, on output captured from the real YADE and on broken input.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "reference/yade/output_parser.hpp"
#include "reference/yade/run_plan.hpp"
#include "support/text_file.hpp"

namespace yade_output_parser_test {

using reference::yade::parse_snapshot_csv;
using reference::yade::parse_trace_csv;
using reference::yade::YadeOutputError;

const std::filesystem::path kData = std::filesystem::path(DEMWB_TEST_DATA_DIR) / "yade";

/// The message of the YadeOutputError `f` throws, or "" when it does not throw.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const YadeOutputError& e) {
    return e.what();
  }
  return "";
}

TEST(YadeTraceParser, ReadsCapturedSingleCollisionTrace) {
  const cases::Trace t = parse_trace_csv(support::read_file(kData / "single_collision_trace.csv"), "trace.csv");
  ASSERT_EQ(t.columns().size(), 15u);
  EXPECT_EQ(t.columns().front(), "time");
  EXPECT_EQ(t.columns().back(), "c0-1.fn");
  ASSERT_EQ(t.rows(), 161u);  // 160 steps of 5e-6 s, every step, plus t = 0
  EXPECT_EQ((*t.column("p0.vx"))[0], 4.0);
  EXPECT_EQ((*t.column("time"))[160], 160 * 5e-6);  // O.iter·O.dt, the in-house sample time
  // A linear spring: while in contact the normal force is k_e δ and acts on p along −x.
  const auto& overlap = *t.column("c0-1.overlap");
  const auto& fn = *t.column("c0-1.fn");
  const auto& fx = *t.column("p0.fx");
  int contact_rows = 0;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    if (overlap[r] > 0.0) {
      ++contact_rows;
      EXPECT_NEAR(fn[r], 1e5 * overlap[r], 1e-13 * 82.0) << "row " << r;
      EXPECT_DOUBLE_EQ(fx[r], -fn[r]) << "row " << r;
    } else {
      EXPECT_EQ(fn[r], 0.0) << "row " << r;
    }
  }
  EXPECT_GT(contact_rows, 120);
}

TEST(YadeTraceParser, AcceptsCrLfAndNonFiniteNumbers) {
  const cases::Trace t = parse_trace_csv("time,a\r\n0,nan\r\n1e-3,-inf\r\n", "t.csv");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_TRUE(std::isnan((*t.column("a"))[0]));
  EXPECT_TRUE(std::isinf((*t.column("a"))[1]));
}

TEST(YadeTraceParser, ErrorsNameFileLineAndColumn) {
  EXPECT_EQ(error_of([] { parse_trace_csv("", "trace.csv"); }), "trace.csv: empty file (no header line)");
  EXPECT_EQ(error_of([] { parse_trace_csv("time,p0.x\n0,1\n0.5\n", "trace.csv"); }),
            "trace.csv line 3: expected 2 values, found 1");
  EXPECT_EQ(error_of([] { parse_trace_csv("time,p0.x\n0,1\n1,abc\n", "trace.csv"); }),
            "trace.csv line 3, column 'p0.x': 'abc' is not a number");
  EXPECT_EQ(error_of([] { parse_trace_csv("time,p0.x\n0,1.5x\n", "trace.csv"); }),
            "trace.csv line 2, column 'p0.x': '1.5x' is not a number");
  EXPECT_EQ(error_of([] { parse_trace_csv("time,p0.x,p0.x\n", "trace.csv"); }),
            "trace.csv line 1: column 'p0.x' appears twice");
  EXPECT_EQ(error_of([] { parse_trace_csv("time,p0.x\n0,1\n\n1,2\n", "trace.csv"); }),
            "trace.csv line 3: empty line");
}

TEST(YadeSnapshotParser, ReadsCapturedSnapshots) {
  const auto snaps = parse_snapshot_csv(support::read_file(kData / "single_collision_snapshots.csv"),
                                        "snapshots.csv", 2);
  ASSERT_EQ(snaps.size(), 3u);
  EXPECT_EQ(snaps[0].time, 0.0);
  EXPECT_NEAR(snaps[1].time, 3.7e-4, 1e-15);
  EXPECT_EQ(snaps[0].velocity[0][0], 4.0);
  EXPECT_EQ(snaps[2].position[1][0], 0.1102);  // the fixed sphere never moves
  EXPECT_LT(snaps[2].velocity[0][0], -3.99);    // p rebounds
}

TEST(YadeSnapshotParser, ErrorsNameTheLine) {
  const std::string header = "time,particle,x,y,z,vx,vy,vz,wx,wy,wz\n";
  EXPECT_EQ(error_of([&] { parse_snapshot_csv(header + "0,1,0,0,0,0,0,0,0,0,0\n", "s.csv", 2); }),
            "s.csv line 2: expected particle 0, found 1");
  EXPECT_EQ(error_of([&] {
              parse_snapshot_csv(header + "0,0,0,0,0,0,0,0,0,0,0\n1,1,0,0,0,0,0,0,0,0,0\n", "s.csv", 2);
            }),
            "s.csv line 3: time 1 differs from the snapshot's 0");
  EXPECT_EQ(error_of([&] { parse_snapshot_csv(header + "0,0,0,0,0,0,0,0,0,0,0\n", "s.csv", 2); }),
            "s.csv: the last snapshot has 1 of 2 particles");
  EXPECT_EQ(error_of([] { parse_snapshot_csv("time,x\n", "s.csv", 2); }),
            "s.csv line 1: expected the header 'time,particle,x,y,z,vx,vy,vz,wx,wy,wz'");
}

}  // namespace
