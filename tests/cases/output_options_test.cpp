// SPDX-License-Identifier: MIT
// [output] for many particles: aggregate columns, snapshot intervals, the traced-particle default.
#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/trace.hpp"
#include "case_texts.hpp"

namespace output_options_test {

/// A case of `count` lattice spheres with the given [output] lines.
std::string population_case(int count, const std::string& output) {
  return case_texts::glass_population_case(
             "outputs", "seed = 3\narrangement = \"simple_cubic\"\ncount = " + std::to_string(count) + "\n") +
         "[output]\n" + output;
}

TEST(OutputOptions, ManyParticlesTraceNoneByDefaultAndFewTraceAll) {
  EXPECT_TRUE(cases::load_case_text(population_case(200, ""), "many.toml").output.trace_particles.empty());
  EXPECT_EQ(cases::load_case_text(population_case(16, ""), "few.toml").output.trace_particles.size(), 16U);
}

TEST(OutputOptions, AggregatesBecomeColumnsAfterTheContacts) {
  const cases::Scene s = cases::load_case_text(
      population_case(50, "trace_particles = [3]\ntrace_aggregates = [\"coordination_number\", \"kinetic_energy\"]\n"),
      "agg.toml");
  ASSERT_EQ(s.output.trace_aggregates.size(), 2U);
  const cases::Trace t = cases::trace_layout(s);
  ASSERT_EQ(t.columns().size(), 1U + 12U + 2U);
  EXPECT_EQ(t.columns()[13], "all.coordination_number");
  EXPECT_EQ(t.columns()[14], "all.kinetic_energy");
}

TEST(OutputOptions, SnapshotEveryAddsEvenlySpacedTimesMergedWithTheListedOnes) {
  const cases::Scene s =
      cases::load_case_text(population_case(8, "snapshot_every = 0.004\nsnapshot_times = [0.001, 0.004]\n"), "s.toml");
  EXPECT_EQ(s.output.snapshot_times, (std::vector<double>{0.0, 0.001, 0.004, 0.008}));
}

TEST(OutputOptions, BadValuesNameTheirKey) {
  const auto key_of = [](const std::string& output) -> std::string {
    try {
      static_cast<void>(cases::load_case_text(population_case(8, output), "bad.toml"));
    } catch (const cases::CaseError& e) {
      return e.key();
    }
    return "(no error)";
  };
  EXPECT_EQ(key_of("trace_aggregates = [\"temperature\"]\n"), "output.trace_aggregates[0]");
  EXPECT_EQ(key_of("trace_aggregates = [\"kinetic_energy\", \"kinetic_energy\"]\n"), "output.trace_aggregates[1]");
  EXPECT_EQ(key_of("snapshot_every = 0.0\n"), "output.snapshot_every");
  EXPECT_EQ(key_of("snapshot_every = 1e-9\n"), "output.snapshot_every");
}

}  // namespace
