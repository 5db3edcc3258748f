// SPDX-License-Identifier: MIT
// Load-time limits on untrusted case files (docs/case-format.md, "Limits"): only regular files of
// bounded size are read, echoed values are cut short, derived quantities and counts are bounded.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "cases/case_file.hpp"
#include "cases/case_loader.hpp"
#include "cases/excerpt.hpp"
#include "cases/generators/population.hpp"
#include "cases/limits.hpp"
#include "cases/suggestion.hpp"
#include "case_texts.hpp"

namespace limits_test {

namespace fs = std::filesystem;
using cases::CaseError;
using case_texts::error_of;
using case_texts::kPair;
using case_texts::replaced;

/// kPair with the first occurrence of `from` replaced by `to`.
std::string pair_with(std::string_view from, std::string_view to) { return replaced(std::string(kPair), from, to); }

/// A scratch path under the temporary directory, removed first.
fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("demwb_limits_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(p);
  return p;
}

/// The CaseError reading `path` throws.
CaseError read_error(const fs::path& path, std::uint64_t max_bytes = cases::kMaxCaseFileBytes) {
  try {
    static_cast<void>(cases::read_case_file(path, max_bytes));
  } catch (const CaseError& e) {
    return e;
  }
  ADD_FAILURE() << "no CaseError reading " << path;
  return CaseError(path.string(), "(none)", "no error");
}

/// A population of glass spheres of radius `radius` in the box [0, region_max]³ with the entry
/// lines `lines`.
std::string population(const std::string& lines, const std::string& radius = "0.001",
                       const std::string& region_max = "1.0") {
  return R"([case]
name = "many"
[model]
normal = "linear"
[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5
[[populations]]
material = "glass"
seed = 1
)" + lines + R"(
region = { shape = "box", min = [0.0, 0.0, 0.0], max = [)" + region_max + ", " + region_max + ", " + region_max + R"(] }
size = { distribution = "monodisperse", radius = )" +
         radius + R"( }
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 1.0e-3
)";
}

TEST(CaseFile, ReadsARegularFileWhole) {
  const fs::path file = scratch("regular.toml");
  std::ofstream(file, std::ios::binary) << kPair;
  EXPECT_EQ(cases::read_case_file(file), kPair);
  EXPECT_EQ(cases::load_case(file).particles.size(), 2U);
  fs::remove(file);
}

TEST(CaseFile, RefusesADirectoryNamingIt) {
  const fs::path dir = scratch("dir.toml");
  fs::create_directories(dir);
  const CaseError e = read_error(dir);
  EXPECT_EQ(e.key(), "(file)");
  EXPECT_EQ(std::string(e.what()).rfind(dir.string() + ": (file): is a directory", 0), 0U) << e.what();
  fs::remove_all(dir);
}

TEST(CaseFile, RefusesDevZeroWithoutReadingIt) {
  try {
    static_cast<void>(cases::load_case("/dev/zero"));
    FAIL() << "/dev/zero loaded";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.key(), "(file)");
    EXPECT_NE(std::string(e.what()).find("/dev/zero: (file): is a character device"), std::string::npos) << e.what();
  }
}

TEST(CaseFile, RefusesAFifoWithoutWaitingForAWriter) {
  const fs::path fifo = scratch("fifo.toml");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto result = std::async(std::launch::async, [&fifo] { return std::string(read_error(fifo).what()); });
  if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    // The reader is stuck in open(): release it with a writer, then fail.
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    ADD_FAILURE() << "reading a FIFO blocked";
  }
  EXPECT_NE(result.get().find("is a FIFO"), std::string::npos);
  fs::remove(fifo);
}

TEST(CaseFile, RefusesAFileLargerThanTheCapBeforeReadingIt) {
  const fs::path file = scratch("large.toml");
  {
    std::ofstream out(file, std::ios::binary);
    out << kPair << "# " << std::string(cases::kMaxCaseFileBytes, 'x') << "\n";
  }
  const CaseError e = read_error(file);
  EXPECT_NE(e.problem().find("more than the limit of 4194304 bytes"), std::string::npos) << e.what();
  EXPECT_THROW(static_cast<void>(cases::load_case(file)), CaseError);
  fs::remove(file);
}

TEST(CaseFile, TheCapIsInclusive) {
  const fs::path file = scratch("cap.toml");
  std::ofstream(file, std::ios::binary) << std::string(100, 'a');
  EXPECT_EQ(cases::read_case_file(file, 100).size(), 100U);
  EXPECT_NE(read_error(file, 99).problem().find("is 100 bytes, more than the limit of 99 bytes"), std::string::npos);
  fs::remove(file);
}

TEST(CaseFile, AMissingFileNamesThePathAndTheReason) {
  const CaseError e = read_error("/nonexistent/demwb/case.toml");
  EXPECT_EQ(std::string(e.what()), "/nonexistent/demwb/case.toml: (file): cannot open for reading (No such file or directory)");
}

TEST(CaseFile, TextInMemoryHasTheSameCap) {
  const std::string text = std::string(kPair) + "# " + std::string(cases::kMaxCaseFileBytes, 'x');
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "(file)");
  EXPECT_NE(e.problem().find("more than the limit"), std::string::npos);
}

TEST(Excerpt, LeavesShortPrintableTextAlone) {
  EXPECT_EQ(cases::excerpt("glass_2"), "glass_2");
  EXPECT_EQ(cases::excerpt("§4.3 é"), "§4.3 é");
}

TEST(Excerpt, WritesControlCharactersAsHexEscapes) {
  EXPECT_EQ(cases::excerpt("a\nshell touch x\n#"), "a\\x0ashell touch x\\x0a#");
  EXPECT_EQ(cases::excerpt(std::string_view("\0\x1b\x7f", 3)), "\\x00\\x1b\\x7f");
}

TEST(Excerpt, CutsLongTextAndGivesItsLength) {
  const std::string shown = cases::excerpt(std::string(5'000'000, 'a'));
  EXPECT_EQ(shown, std::string(cases::kMaxEchoedValue, 'a') + "…(5000000 bytes)");
  EXPECT_EQ(cases::excerpt("abcdef", 3), "abc…(6 bytes)");
}

TEST(Excerpt, NeverSplitsAUtf8Character) {
  // "é" is two bytes: a cut after 3 bytes of "aéé" keeps "aé", not half of the second "é".
  EXPECT_EQ(cases::excerpt("aéé", 4), "aé…(5 bytes)");
}

TEST(EchoedValues, AMegabyteStringIsNotEchoedWhole) {
  const std::string name(3'000'000, 'x');
  const CaseError e = error_of(std::string(kPair) + "\n[compare]\nengines = [\"" + name + "\"]\n");
  EXPECT_EQ(e.key(), "compare.engines[0]");
  EXPECT_LT(std::string(e.what()).size(), 1000U) << std::string(e.what()).substr(0, 300);
  EXPECT_NE(std::string(e.what()).find("…(3000000 bytes)"), std::string::npos);
}

TEST(EchoedValues, AMegabyteKeyIsNotEchoedWholeNorCompared) {
  const std::string key(3'000'000, 'k');
  const CaseError e = error_of(std::string(kPair) + key + " = 1\n");
  EXPECT_LT(std::string(e.what()).size(), 2000U);
  EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos);
  EXPECT_FALSE(cases::closest_match(key, std::vector<std::string_view>{"kk", "k"}).has_value());
}

TEST(EchoedValues, LineBreaksInAValueDoNotBreakTheMessage) {
  const CaseError e = error_of(pair_with("material = \"glass\"", "material = \"a\\nshell touch x\\n#\""));
  const std::string what = e.what();
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  EXPECT_NE(what.find("a\\x0ashell touch x\\x0a#"), std::string::npos) << what;
}

TEST(EchoedValues, ALongStringInADescribedTypeIsCut) {
  const CaseError e = error_of(pair_with("density = 2500.0", "density = \"" + std::string(10'000, 'd') + "\""));
  EXPECT_EQ(e.key(), "materials.glass.density");
  EXPECT_NE(std::string(e.what()).find("expected a number, got string \"ddd"), std::string::npos);
  EXPECT_NE(std::string(e.what()).find("…(10000 bytes)"), std::string::npos);
}

TEST(DerivedQuantities, ATinyDensityIsBlamedForTheMass) {
  const CaseError e = error_of(pair_with("density = 2500.0", "density = 1e-300"));
  EXPECT_EQ(e.key(), "materials.glass.density");
  EXPECT_NE(e.problem().find("must be finite and within [1e-100, 1e+100]"), std::string::npos) << e.what();
}

TEST(DerivedQuantities, ASubnormalRadiusIsBlamedForTheMass) {
  const CaseError e = error_of(pair_with("radius = 0.01", "radius = 5e-324"));
  EXPECT_EQ(e.key(), "particles[0].radius");
  EXPECT_NE(e.problem().find("has mass"), std::string::npos) << e.what();
}

TEST(DerivedQuantities, AGeneratedSphereOfSubnormalRadiusNamesItsPopulation) {
  // Before the limits this laid a lattice of pitch 1e-323 m and never finished.
  const std::string text = population("arrangement = \"simple_cubic\"\ncount = 8", "5e-324", "0.1");
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "populations[0].size") << e.what();
  EXPECT_NE(e.problem().find("generated by populations[0]"), std::string::npos) << e.what();
}

TEST(Counts, ALatticeTooFineForItsRegionGivesUpAfterBoundedWork) {
  // A pitch of 1e-323 m in a 0.1 m cylinder: rows of 1e22 candidates. The lattice gives up after
  // 5 steps (positions, rows, layers) per sphere the scene may still hold, plus a million.
  cases::PopulationSpec p;
  p.arrangement = cases::Arrangement::simple_cubic;
  p.count = 8;
  p.region.shape = cases::RegionSpec::Shape::cylinder;
  p.region.base = {0.0, 0.0, 0.0};
  p.region.radius = 0.05;
  p.region.height = 0.1;
  p.size.radius = 5e-324;
  try {
    static_cast<void>(cases::generate_population(p, {}, 1.0, 100));
    FAIL() << "no error";
  } catch (const cases::PopulationError& e) {
    EXPECT_EQ(e.key(), "spacing");
    EXPECT_NE(std::string(e.what()).find("took 1000500 steps through the region"), std::string::npos) << e.what();
  }
}

TEST(DerivedQuantities, AHugeStiffnessNamesTheMaterialProperty) {
  const CaseError e = error_of(pair_with("normal_stiffness = 1.0e5", "normal_stiffness = 1e300"));
  EXPECT_EQ(e.key(), "materials.glass.normal_stiffness");
  EXPECT_NE(e.problem().find("collision stiffness k = 1e+300 N/m"), std::string::npos) << e.what();
}

TEST(DerivedQuantities, AHugeStiffnessOfAPairOverrideNamesTheOverride) {
  const CaseError e = error_of(std::string(kPair) + "\n[[pairs]]\nmaterials = [\"glass\", \"glass\"]\nnormal_stiffness = 1e250\n");
  EXPECT_EQ(e.key(), "pairs[0].normal_stiffness") << e.what();
}

TEST(DerivedQuantities, AHugeYoungsModulusOfAHertzContactNamesIt) {
  const std::string text = replaced(pair_with("normal = \"linear\"", "normal = \"hertz\""), "normal_stiffness = 1.0e5",
                                    "youngs_modulus = 1e250\npoisson_ratio = 0.3");
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "materials.glass.youngs_modulus") << e.what();
}

TEST(DerivedQuantities, AnAutomaticTimeStepNeedingTooManyStepsIsRefused) {
  const CaseError e =
      error_of(replaced(pair_with("timestep = 1.0e-5", "timestep = \"auto\""), "duration = 1.0e-3", "duration = 1.0e5"));
  EXPECT_EQ(e.key(), "integration.timestep");
  EXPECT_NE(e.problem().find("the automatic time step"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("more than the limit of 1e9"), std::string::npos) << e.what();
}

TEST(DerivedQuantities, AnAutomaticTimeStepWithoutContactStillLoads) {
  // One sphere and no wall: nothing to size the step by. The run says so, not the loader.
  const std::string text =
      replaced(pair_with("timestep = 1.0e-5", "timestep = \"auto\""),
               "[[particles]]\nradius = 0.01\nmaterial = \"glass\"\nposition = [0.05, 0.0, 0.0]\nfixed = true\n", "");
  EXPECT_EQ(cases::load_case_text(text, "one.toml").particles.size(), 1U);
}

TEST(DerivedQuantities, AFormationThatCouldRunForeverIsRefused) {
  const std::string text =
      replaced(pair_with("normal = \"linear\"", "normal = \"linear\"\ndamping = \"restitution\""),
               "normal_stiffness = 1.0e5", "normal_stiffness = 1.0e5\nrestitution = 0.5") +
      "\n[[stages]]\nkind = \"formation\"\npull = 1.0\npull_time = 0.1\nrestitution = 0.1\nkinetic_energy = 1e-9\n"
      "max_duration = 1e300\n";
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "stages[0].max_duration") << e.what();
  EXPECT_NE(e.problem().find("more than the limit of 1e9"), std::string::npos);
}

TEST(Speeds, AVelocityFasterThanLightIsRefused) {
  EXPECT_EQ(error_of(pair_with("velocity = [1.0, 0.0, 0.0]", "velocity = [1e300, 0.0, 0.0]")).key(),
            "particles[0].velocity");
  EXPECT_EQ(error_of(pair_with("velocity = [1.0, 0.0, 0.0]", "velocity = [2.5e8, 2.5e8, 0.0]")).key(),
            "particles[0].velocity");
  // 2.9e8 m/s is fast, not impossible.
  EXPECT_EQ(cases::load_case_text(pair_with("velocity = [1.0, 0.0, 0.0]", "velocity = [-2.9e8, 0.0, 0.0]"), "c.toml")
                .particles.size(),
            2U);
}

TEST(Speeds, APopulationsJitterCountsTowardsItsSpeed) {
  const std::string text = population("arrangement = \"simple_cubic\"\ncount = 8\nvelocity = [1.0e8, 0.0, 0.0]\nvelocity_jitter = 1.2e8", "0.01", "0.1");
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "populations[0].velocity_jitter");
  EXPECT_NE(e.problem().find("√3 velocity_jitter"), std::string::npos);
}

TEST(Speeds, FluidAndLaunchSpeedsAreBounded) {
  EXPECT_EQ(error_of(std::string(kPair) + "\n[fields.fluid]\nvelocity = [0.0, 0.0, 1e10]\n").key(),
            "fields.fluid.velocity");
  EXPECT_EQ(error_of(std::string(kPair) +
                     "\n[fields.fluid.plug_flow]\nspeed = 1e9\nzones = [{ min = [0, 0, 0], max = [1, 1, 1], "
                     "direction = [1, 0, 0] }]\n")
                .key(),
            "fields.fluid.plug_flow.speed");
  const std::string launched = std::string(kPair) + R"(
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, -1.0]
normal = [0.0, 0.0, 1.0]
material = "glass"

[[stages]]
kind = "launch"
wall = "floor"
speed = 3.0e8
angle = 30.0
direction = [1.0, 0.0, 0.0]
)";
  EXPECT_EQ(error_of(launched).key(), "stages[0].speed") << error_of(launched).what();
}

TEST(Counts, MoreMaterialsThanTheLimitAreRefused) {
  std::string text(kPair);
  for (std::size_t k = 0; k < cases::kMaxMaterials; ++k) {
    text += "\n[materials.m" + std::to_string(k) + "]\ndensity = 1000.0\nnormal_stiffness = 1.0e5\n";
  }
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "materials");
  EXPECT_NE(e.problem().find("257 materials, more than the limit of 256"), std::string::npos) << e.what();
}

TEST(Counts, MoreWallsThanTheLimitAreRefused) {
  std::string text(kPair);
  for (std::size_t k = 0; k < cases::kMaxWalls / 6 + 1; ++k) {
    text += "\n[[walls]]\ntype = \"box\"\nmin = [-1, -1, -1]\nmax = [1, 1, 1]\nmaterial = \"glass\"\n";
  }
  const CaseError e = error_of(text);
  EXPECT_EQ(e.key(), "walls[" + std::to_string(cases::kMaxWalls / 6) + "]");
  EXPECT_NE(e.problem().find("more than the limit of 256"), std::string::npos) << e.what();
}

TEST(Counts, APopulationAskingForTooManySpheresIsRefusedBeforeAnyIsMade) {
  const CaseError e = error_of(population("arrangement = \"simple_cubic\"\ncount = 100000000"));
  EXPECT_EQ(e.key(), "populations[0].count");
  EXPECT_NE(e.problem().find("the scene may hold at most 10000000 more"), std::string::npos) << e.what();
}

TEST(Counts, ALatticeFillOfTooManySitesIsRefusedBeforeAnyIsMade) {
  // 1 m³ at a pitch of 2 µm: 1.25e17 sites.
  const CaseError e = error_of(population("arrangement = \"hcp\"", "1e-6"));
  EXPECT_EQ(e.key(), "populations[0].spacing");
  EXPECT_NE(e.problem().find("about"), std::string::npos) << e.what();
}

TEST(Counts, ARandomFillOfTooManySpheresStopsAtTheLimit) {
  const CaseError e = error_of(population("arrangement = \"random\"\nvolume_fraction = 0.3", "1e-30"));
  EXPECT_EQ(e.key(), "populations[0].volume_fraction");
  EXPECT_NE(e.problem().find("needs more than 10000000 spheres"), std::string::npos) << e.what();
}

TEST(Normals, AHugeNormalIsScaledWithoutOverflowingToZero) {
  const cases::Scene s = cases::load_case_text(std::string(kPair) + R"(
[[walls]]
type = "plane"
point = [-1.0, 0.0, 0.0]
normal = [1e300, 0.0, 0.0]
material = "glass"
)",
                                               "wall.toml");
  ASSERT_EQ(s.walls.size(), 1U);
  EXPECT_EQ(s.walls[0].normal[0], 1.0);
}

}  // namespace
