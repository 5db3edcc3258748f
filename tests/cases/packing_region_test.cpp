// SPDX-License-Identifier: MIT
// [compare.packing]: the region of the packing metrics, read and checked at load time.
#include <gtest/gtest.h>

#include <string>

#include "cases/case_loader.hpp"
#include "cases/packing_region.hpp"
#include "case_texts.hpp"

namespace packing_region_test {

/// 27 lattice spheres of radius 4 mm in a 0.1 m box, with the given [compare] and [output] lines.
std::string packing_case(const std::string& compare, const std::string& output = "snapshot_times = [0.01]\n") {
  return case_texts::glass_population_case("packing", "seed = 3\narrangement = \"simple_cubic\"\ncount = 27\n") +
         "[compare]\n" + compare + "[output]\n" + output;
}

/// The dotted key a case error names, or "(no error)".
std::string key_of(const std::string& text) {
  try {
    static_cast<void>(cases::load_case_text(text, "bad.toml"));
  } catch (const cases::CaseError& e) {
    return e.key();
  }
  return "(no error)";
}

TEST(PackingRegion, IsReadWithItsDefaults) {
  const cases::Scene s = cases::load_case_text(
      packing_case("metrics = [\"packing_fraction\", \"orf\"]\npacking = { min = [0, 0, 0], max = [0.1, 0.06, 0.02] }\n"),
      "p.toml");
  ASSERT_TRUE(s.compare.packing.has_value());
  EXPECT_EQ(s.compare.packing->max, (cases::Vector3{0.1, 0.06, 0.02}));
  EXPECT_FALSE(s.compare.packing->interior_margin.has_value());
  EXPECT_EQ(s.compare.packing->orf_ny, 45U);
  EXPECT_EQ(s.compare.packing->orf_nz, 15U);
  EXPECT_DOUBLE_EQ(cases::interior_margin(s, *s.compare.packing), 4 * 0.004);  // two mean diameters
  const cases::Scene t = cases::load_case_text(
      packing_case("metrics = [\"packing_fraction_interior\"]\n"
                   "packing = { min = [0, 0, 0], max = [0.1, 0.1, 0.1], interior_margin = 0.01, orf_grid = [30, 10] }\n"),
      "p.toml");
  EXPECT_EQ(*t.compare.packing->interior_margin, 0.01);
  EXPECT_EQ(t.compare.packing->orf_ny, 30U);
  EXPECT_DOUBLE_EQ(cases::interior_margin(t, *t.compare.packing), 0.01);
}

TEST(PackingRegion, BadRegionsAndMissingPiecesNameTheirKey) {
  const std::string region = "packing = { min = [0, 0, 0], max = [0.1, 0.1, 0.1] }\n";
  EXPECT_EQ(key_of(packing_case("metrics = [\"orf\"]\n")), "compare.metrics");
  EXPECT_EQ(key_of(packing_case("metrics = [\"orf\"]\npacking = { min = [0, 0, 0], max = [0.1, 0.0, 0.1] }\n")),
            "compare.packing.max");
  EXPECT_EQ(key_of(packing_case("metrics = [\"orf\"]\npacking = { min = [0, 0, 0] }\n")), "compare.packing.max");
  EXPECT_EQ(key_of(packing_case("metrics = [\"orf\"]\npacking = { min = [0, 0, 0], max = [1, 1, 1], size = 3 }\n")),
            "compare.packing.size");
  EXPECT_EQ(key_of(packing_case(
                "metrics = [\"orf\"]\npacking = { min = [0, 0, 0], max = [1, 1, 1], orf_grid = [45] }\n")),
            "compare.packing.orf_grid");
  EXPECT_EQ(key_of(packing_case(
                "metrics = [\"orf\"]\npacking = { min = [0, 0, 0], max = [1, 1, 1], orf_grid = [0, 15] }\n")),
            "compare.packing.orf_grid[0]");
  EXPECT_EQ(key_of(packing_case(
                "metrics = [\"orf\"]\npacking = { min = [0, 0, 0], max = [1, 1, 1], interior_margin = -0.1 }\n")),
            "compare.packing.interior_margin");
  // The interior must leave something: a 1 cm region less two 16 mm margins does not.
  EXPECT_EQ(key_of(packing_case("metrics = [\"packing_fraction_interior\"]\n"
                                "packing = { min = [0, 0, 0], max = [0.1, 0.1, 0.01] }\n")),
            "compare.packing.max");
  EXPECT_EQ(key_of(packing_case("metrics = [\"packing_fraction_interior\"]\n"
                                "packing = { min = [0, 0, 0], max = [0.1, 0.1, 0.1], interior_margin = 0.05 }\n")),
            "compare.packing.interior_margin");
  // The metrics read the last snapshot.
  EXPECT_EQ(key_of(packing_case("metrics = [\"dose_remaining\"]\n" + region, "")), "output.snapshot_times");
  // A region without packing metrics is fine.
  EXPECT_EQ(key_of(packing_case(region, "")), "(no error)");
}

}  // namespace packing_region_test
