// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cases/run_result.hpp"

// The glass, meshes and trace comparisons shared by the tests that run the real reference codes on walls.
namespace demwb_mesh_test {

/// The [model] and [materials.glass] tables of the wall scenes: Hertz, Tsuji's dashpot (ε 0.7) and
/// Mindlin friction (μ 0.3) without a tangential dashpot; `model_lines` adds lines to [model].
inline std::string glass_hertz_mindlin(std::string_view model_lines = {}) {
  return std::string(R"([model]
normal = "hertz"
damping = "tsuji"
tangential = "mindlin_8g"
)") + std::string(model_lines) +
         R"([materials.glass]
density = 2500.0
youngs_modulus = 6.0e7
poisson_ratio = 0.23
restitution = 0.7
friction = 0.3
tangential_damping_ratio = 0.0
)";
}

/// A flat floor over [−10, 10] mm² at z = 0 as an ASCII STL of 32 triangles: a 4 × 4 grid of
/// squares, each cut along alternating diagonals (seams in three directions).
inline std::string flat_floor_stl() {
  std::string stl = "solid floor\n";
  const auto facet = [&](std::array<std::array<double, 2>, 3> c) {
    stl += "  facet normal 0 0 1\n    outer loop\n";
    for (const auto& p : c) stl += fmt::format("      vertex {:.17g} {:.17g} 0\n", p[0], p[1]);
    stl += "    endloop\n  endfacet\n";
  };
  const double h = 0.005;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x0 = -0.01 + h * i, y0 = -0.01 + h * j, x1 = x0 + h, y1 = y0 + h;
      if ((i + j) % 2 == 0) {
        facet({{{x0, y0}, {x1, y0}, {x1, y1}}});
        facet({{{x0, y0}, {x1, y1}, {x0, y1}}});
      } else {
        facet({{{x0, y0}, {x1, y0}, {x0, y1}}});
        facet({{{x1, y0}, {x1, y1}, {x0, y1}}});
      }
    }
  }
  return stl + "endsolid floor\n";
}

/// The largest difference between two runs' values of trace column `name`, and the largest
/// magnitude of the second run's.
inline std::pair<double, double> column_gap(const cases::RunResult& a, const cases::RunResult& b,
                                            const std::string& name) {
  const std::vector<double>& x = *a.trace.column(name);
  const std::vector<double>& y = *b.trace.column(name);
  EXPECT_EQ(x.size(), y.size()) << name;
  double worst = 0.0;
  double scale = 0.0;
  for (std::size_t r = 0; r < std::min(x.size(), y.size()); ++r) {
    worst = std::max(worst, std::abs(x[r] - y[r]));
    scale = std::max(scale, std::abs(y[r]));
  }
  return {worst, scale};
}

}  // namespace demwb_mesh_test
