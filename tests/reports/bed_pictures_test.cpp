// SPDX-License-Identifier: MIT
// The report's pictures of a packed bed: which snapshots are drawn, the window around the packing
// region, the drawn discs (painter's order, colour by speed), and the ORF curve's CSV and plot.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reports/packing_plot.hpp"
#include "reports/snapshot_view.hpp"
#include "support/text_file.hpp"

namespace bed_pictures_test {

TEST(FrameIndices, SpreadEvenlyWithTheFirstAndLastSnapshot) {
  EXPECT_EQ(reports::frame_indices(41, 6), (std::vector<std::size_t>{0, 8, 16, 24, 32, 40}));
  EXPECT_EQ(reports::frame_indices(11, 6), (std::vector<std::size_t>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(reports::frame_indices(3, 6), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(reports::frame_indices(1, 6), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(reports::frame_indices(0, 6).empty());
  EXPECT_EQ(reports::frame_indices(10, 1), (std::vector<std::size_t>{9}));
  for (std::size_t count = 2; count < 60; ++count) {
    const auto f = reports::frame_indices(count, 6);
    ASSERT_FALSE(f.empty());
    EXPECT_EQ(f.front(), 0U);
    EXPECT_EQ(f.back(), count - 1);
    EXPECT_EQ(f.size(), std::min<std::size_t>(count, 6));
    for (std::size_t k = 1; k < f.size(); ++k) EXPECT_LT(f[k - 1], f[k]);
  }
}

TEST(FluidisationFrames, ShowTheStillBedThenSpreadOverTheFall) {
  // Still until snapshot 4, falls from 5 to 9, empty after: frame 0, then 4 … 9.
  const std::vector<double> orf{0.9, 0.9, 0.9, 0.9, 0.9, 0.7, 0.5, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(reports::fluidisation_frames(orf, 6), (std::vector<std::size_t>{0, 4, 5, 7, 8, 9}));
  // A bed that stays (falls by less than 0.05) is shown evenly.
  const std::vector<double> still{0.9, 0.89, 0.88, 0.88, 0.88, 0.88, 0.88, 0.88, 0.88, 0.88, 0.88};
  EXPECT_EQ(reports::fluidisation_frames(still, 6), reports::frame_indices(still.size(), 6));
  // Falling from the first snapshot on: the first frame is not repeated.
  const std::vector<double> at_once{1.0, 0.5, 0.0, 0.0, 0.0};
  EXPECT_EQ(reports::fluidisation_frames(at_once, 6), (std::vector<std::size_t>{0, 1, 2}));
}

/// Three mobile spheres in a 2 × 6 × 2 mm reservoir (one moving at 3 m/s and nearest the viewer,
/// one resting and farthest, one far outside the window) and a fixed one.
struct Bed {
  cases::Scene scene;
  cases::Snapshot snap;
};

Bed bed() {
  Bed b;
  b.scene.compare.packing = cases::PackingSpec{{0.0, 0.0, 0.0}, {2.0e-3, 6.0e-3, 2.0e-3}, std::nullopt, 45, 15};
  for (int k = 0; k < 4; ++k) {
    cases::ParticleSpec p;
    p.radius = 2.0e-4;
    b.scene.particles.push_back(p);
  }
  b.scene.particles[3].fixed = true;
  b.snap.position = {{1.9e-3, 3.0e-3, 1.0e-3}, {0.1e-3, 3.1e-3, 1.0e-3}, {1.0e-3, 3.0e-3, 0.5}, {1.0e-3, 1.0e-3, 2.0e-4}};
  b.snap.velocity = {{0.0, 0.0, 0.0}, {0.0, 3.0, 0.0}, {0.0, 0.0, 30.0}, {0.0, 0.0, 0.0}};
  return b;
}

TEST(PackingWindow, FramesTheRegionWithRoomAboveAndTheFastestMobileSphere) {
  const Bed b = bed();
  const reports::ProjectionWindow w = reports::packing_window(b.scene, {b.snap});
  EXPECT_DOUBLE_EQ(w.y_min, -0.6e-3);
  EXPECT_DOUBLE_EQ(w.y_max, 6.6e-3);
  EXPECT_DOUBLE_EQ(w.z_min, -0.2e-3);
  EXPECT_DOUBLE_EQ(w.z_max, 4.0e-3);
  EXPECT_DOUBLE_EQ(w.speed_max, 30.0);  // the sphere outside the window still sets the scale
  cases::Scene resting = b.scene;
  cases::Snapshot still = b.snap;
  for (auto& v : still.velocity) v = {0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(reports::packing_window(resting, {still}).speed_max, 1.0);
  resting.compare.packing.reset();
  EXPECT_DOUBLE_EQ(reports::packing_window(resting, {still}).y_max, 0.0);
}

TEST(RenderProjection, DrawsTheWindowsSpheresFarthestFirstColouredBySpeed) {
  const Bed b = bed();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-bed-pictures";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto window = reports::packing_window(b.scene, {b.snap});
  const auto problem = reports::render_projection(b.scene, b.snap, window, "t = 0", dir / "frame.png");
  // The data and script are written whether or not gnuplot is installed.
  const std::string dat = support::read_file(dir / "frame.dat");
  std::istringstream in(dat);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 3U) << dat;  // two mobile in the window, then the fixed one
  EXPECT_EQ(rows[0], "0.003 0.001 0.0002 0");     // x = 1.9 mm: the farthest, drawn first
  EXPECT_EQ(rows[1], "0.0031 0.001 0.0002 3");    // x = 0.1 mm: the nearest, drawn over it
  EXPECT_EQ(rows[2], "0.001 0.0002 0.0002");       // the fixed sphere, grey
  const std::string gp = support::read_file(dir / "frame.gp");
  EXPECT_NE(gp.find("set cbrange [0:30]"), std::string::npos) << gp;
  EXPECT_NE(gp.find("rect from 0,0 to 0.006,0.002"), std::string::npos) << gp;
  if (!problem) {
    EXPECT_GT(std::filesystem::file_size(dir / "frame.png"), 0U);
  } else {
    EXPECT_NE(problem->find("gnuplot"), std::string::npos) << *problem;
  }
  std::filesystem::remove_all(dir);
}

TEST(PackingSeriesCsv, HoldsOneRowPerSnapshotAtFullPrecision) {
  const std::string csv = reports::packing_series_csv({{0.0, 1.0, 1.0}, {0.1, 0.1 + 0.2, 0.5}});
  EXPECT_EQ(csv, "time,orf,dose_remaining\n0,1,1\n0.10000000000000001,0.30000000000000004,0.5\n");
}

}  // namespace bed_pictures_test
