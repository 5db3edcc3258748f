// SPDX-License-Identifier: MIT
// Generated populations: determinism per seed, no initial overlap, lattice geometry, size
// distributions against their moments, impossible requests.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/generators/population.hpp"
#include "cases/generators/random_stream.hpp"
#include "case_texts.hpp"

namespace population_test {

using cases::Arrangement;
using cases::PopulationSpec;
using cases::RegionSpec;
using cases::SizeSpec;

PopulationSpec box_population(Arrangement a, SizeSpec size, std::uint64_t seed = 7) {
  PopulationSpec p;
  p.arrangement = a;
  p.size = std::move(size);
  p.seed = seed;
  p.region.shape = RegionSpec::Shape::box;
  p.region.min = {0.0, 0.0, 0.0};
  p.region.max = {0.1, 0.08, 0.12};
  return p;
}

SizeSpec mono(double r) {
  SizeSpec s;
  s.radius = r;
  return s;
}

SizeSpec gaussian(double mean, double sd) {
  SizeSpec s;
  s.kind = SizeSpec::Kind::gaussian;
  s.mean = mean;
  s.std_dev = sd;
  return s;
}

double distance(const cases::Vector3& a, const cases::Vector3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// Largest overlap between any two spheres (negative: all apart), by brute force.
double worst_overlap(const std::vector<cases::ParticleSpec>& ps) {
  double worst = -1.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      worst = std::max(worst, ps[i].radius + ps[j].radius - distance(ps[i].position, ps[j].position));
    }
  }
  return worst;
}

TEST(RandomStream, IsTheSameSequenceForTheSameSeed) {
  cases::RandomStream a(42);
  cases::RandomStream b(42);
  cases::RandomStream c(43);
  bool differs = false;
  for (int k = 0; k < 1000; ++k) {
    const double u = a.uniform();
    EXPECT_EQ(u, b.uniform());
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    differs = differs || u != c.uniform();
  }
  EXPECT_TRUE(differs);
}

TEST(RandomStream, NormalVariatesHaveUnitMomentsAndAFixedFirstValue) {
  cases::RandomStream s(2024);
  double sum = 0.0;
  double sum2 = 0.0;
  constexpr int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double z = s.normal();
    sum += z;
    sum2 += z * z;
  }
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 5.0 * std::sqrt(2.0 / n));
}

TEST(Population, IsDeterministicForASeed) {
  for (const Arrangement a : {Arrangement::simple_cubic, Arrangement::hcp, Arrangement::random}) {
    SizeSpec size = gaussian(0.004, 0.0008);
    size.max = 0.005;
    PopulationSpec p = box_population(a, size);
    p.count = 300;
    p.velocity_jitter = 0.1;
    const auto one = cases::generate_population(p, {}, 1.0);
    const auto two = cases::generate_population(p, {}, 1.0);
    ASSERT_EQ(one.size(), 300U);
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t k = 0; k < one.size(); ++k) {
      EXPECT_EQ(one[k].position, two[k].position);
      EXPECT_EQ(one[k].radius, two[k].radius);
      EXPECT_EQ(one[k].velocity, two[k].velocity);
    }
    p.seed = 8;
    const auto other = cases::generate_population(p, {}, 1.0);
    EXPECT_NE(other[0].radius, one[0].radius);
  }
}

TEST(Population, NoInitialOverlapOnSeededRandomRequests) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SizeSpec size = seed % 2 == 0 ? gaussian(0.004, 0.0015) : mono(0.0035);
    size.max = seed % 2 == 0 ? std::optional<double>(0.006) : std::nullopt;
    if (seed % 3 == 0) {
      size = SizeSpec{};
      size.kind = SizeSpec::Kind::lognormal;
      size.median = 0.003;
      size.sigma_ln = 0.4;
      size.max = 0.008;
    }
    for (const Arrangement a : {Arrangement::simple_cubic, Arrangement::hcp, Arrangement::random}) {
      PopulationSpec p = box_population(a, size, seed);
      if (a == Arrangement::random) p.volume_fraction = 0.25;
      const auto made = cases::generate_population(p, {}, 1.0);
      ASSERT_GT(made.size(), 50U);
      EXPECT_LE(worst_overlap(made), 1e-12) << "seed " << seed;
      for (const auto& s : made) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_GE(s.position[k] - s.radius, p.region.min[k] - 1e-15);
          EXPECT_LE(s.position[k] + s.radius, p.region.max[k] + 1e-15);
        }
      }
    }
  }
}

TEST(Population, RandomInsertionAvoidsSpheresAlreadyPlaced) {
  PopulationSpec first = box_population(Arrangement::random, mono(0.005), 3);
  first.count = 200;
  const auto a = cases::generate_population(first, {}, 1.0);
  PopulationSpec second = box_population(Arrangement::random, gaussian(0.003, 0.001), 4);
  second.count = 300;
  const auto b = cases::generate_population(second, a, 1.0);
  std::vector<cases::ParticleSpec> all = a;
  all.insert(all.end(), b.begin(), b.end());
  EXPECT_LE(worst_overlap(all), 0.0);
}

TEST(Population, LatticesHaveTheirNeighbourDistances) {
  const double r = 0.005;
  for (const Arrangement a : {Arrangement::simple_cubic, Arrangement::hcp}) {
    PopulationSpec p = box_population(a, mono(r));
    p.spacing = 0.011;
    const auto made = cases::generate_population(p, {}, 1.0);
    // Count neighbours at the pitch for a sphere in the middle: 6 (simple cubic), 12 (hcp).
    const cases::Vector3 centre{0.05, 0.04, 0.06};
    const auto middle = std::min_element(made.begin(), made.end(), [&](const auto& x, const auto& y) {
      return distance(x.position, centre) < distance(y.position, centre);
    });
    int at_pitch = 0;
    double nearest = 1.0;
    for (const auto& s : made) {
      const double d = distance(s.position, middle->position);
      if (d == 0.0) continue;
      nearest = std::min(nearest, d);
      if (std::abs(d - 0.011) < 1e-9) ++at_pitch;
    }
    EXPECT_NEAR(nearest, 0.011, 1e-12);
    EXPECT_EQ(at_pitch, a == Arrangement::hcp ? 12 : 6);
  }
  // Simple cubic sites fill the box exactly: floor((L − 2r)/a) + 1 per axis.
  PopulationSpec cubic = box_population(Arrangement::simple_cubic, mono(r));
  cubic.spacing = 0.01;
  EXPECT_EQ(cases::generate_population(cubic, {}, 1.0).size(), 10U * 8U * 12U);
}

TEST(Population, FillsBottomUpAndCylindersHoldTheirSpheres) {
  PopulationSpec p;
  p.arrangement = Arrangement::hcp;
  p.size = mono(0.002);
  p.region.shape = RegionSpec::Shape::cylinder;
  p.region.base = {0.1, 0.2, 0.3};
  p.region.axis = 1;
  p.region.radius = 0.02;
  p.region.height = 0.05;
  p.count = 150;
  const auto made = cases::generate_population(p, {}, 1.5);
  ASSERT_EQ(made.size(), 150U);
  for (const auto& s : made) {
    const double radial = std::hypot(s.position[0] - 0.1, s.position[2] - 0.3);
    EXPECT_LE(radial + s.radius, 0.02 + 1e-15);
    EXPECT_GE(s.position[1] - s.radius, 0.2 - 1e-15);
    EXPECT_DOUBLE_EQ(s.effect_radius, 1.5 * s.radius);
  }
  for (std::size_t k = 1; k < made.size(); ++k) EXPECT_GE(made[k].position[1], made[k - 1].position[1] - 1e-15);
}

TEST(Population, SizeDistributionsMatchTheirMoments) {
  constexpr std::size_t n = 20000;
  const double nd = static_cast<double>(n);
  const auto radii = [n](const SizeSpec& s) {
    PopulationSpec p = box_population(Arrangement::simple_cubic, s, 11);
    p.region.max = {1.0, 1.0, 1.0};
    p.spacing = 2.0 * cases::largest_radius(s);
    p.count = n;
    std::vector<double> out;
    for (const auto& x : cases::generate_population(p, {}, 1.0)) out.push_back(x.radius);
    return out;
  };
  const auto mean = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  const auto sd = [&](const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0.0;
    for (const double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size() - 1));
  };
  // Gaussian far from zero: mean and s.d. within 5 standard errors.
  SizeSpec g = gaussian(0.004, 0.0005);
  g.max = 0.006;
  const auto rg = radii(g);
  EXPECT_NEAR(mean(rg), 0.004, 5.0 * 0.0005 / std::sqrt(nd));
  EXPECT_NEAR(sd(rg), 0.0005, 5.0 * 0.0005 / std::sqrt(2.0 * nd));
  // Truncated to stay positive: no radius at or below zero even when σ is the mean.
  SizeSpec wide = gaussian(0.002, 0.002);
  wide.max = 0.008;
  const auto rw = radii(wide);
  EXPECT_GT(*std::min_element(rw.begin(), rw.end()), 0.0);
  EXPECT_LE(*std::max_element(rw.begin(), rw.end()), 0.008);
  // Log-normal: the median of ln r.
  SizeSpec ln;
  ln.kind = SizeSpec::Kind::lognormal;
  ln.median = 0.003;
  ln.sigma_ln = 0.2;
  ln.max = 0.01;
  std::vector<double> logs;
  for (const double r : radii(ln)) logs.push_back(std::log(r));
  EXPECT_NEAR(mean(logs), std::log(0.003), 5.0 * 0.2 / std::sqrt(nd));
  EXPECT_NEAR(sd(logs), 0.2, 5.0 * 0.2 / std::sqrt(2.0 * nd));
  // Discrete: number frequencies follow the weights.
  SizeSpec d;
  d.kind = SizeSpec::Kind::discrete;
  d.radii = {0.002, 0.004};
  d.weights = {3.0, 1.0};
  const auto rd = radii(d);
  const double small = static_cast<double>(std::count(rd.begin(), rd.end(), 0.002)) / nd;
  EXPECT_NEAR(small, 0.75, 5.0 * std::sqrt(0.75 * 0.25 / nd));
}

TEST(Population, ImpossibleRequestsNameTheirKey) {
  const auto key_of = [](const PopulationSpec& p) -> std::string {
    try {
      static_cast<void>(cases::generate_population(p, {}, 1.0));
    } catch (const cases::PopulationError& e) {
      return e.key();
    }
    return "(no error)";
  };
  PopulationSpec tiny = box_population(Arrangement::hcp, mono(0.1));
  EXPECT_EQ(key_of(tiny), "region");
  PopulationSpec crowded = box_population(Arrangement::simple_cubic, mono(0.01));
  crowded.count = 1000;
  EXPECT_EQ(key_of(crowded), "count");
  PopulationSpec jammed = box_population(Arrangement::random, mono(0.008));
  jammed.volume_fraction = 0.5;
  jammed.max_attempts = 100;
  EXPECT_EQ(key_of(jammed), "volume_fraction");
  PopulationSpec negative = box_population(Arrangement::hcp, gaussian(0.004, -1.0));
  EXPECT_EQ(key_of(negative), "size.std_dev");
}

TEST(Population, ARegionTooLargeForItsCoordinatesIsAnErrorNotAHang) {
  // A cylinder of radius 1e300 (a fuzzed hopper case): the first row sits at -1e300, where adding
  // a pitch does not move it, and every row passes beside the cylinder (its chord is NaN). Rows and
  // layers count towards the lattice's budget, so the fill stops with an error naming `spacing`.
  for (const Arrangement a : {Arrangement::simple_cubic, Arrangement::hcp}) {
    PopulationSpec cylinder;
    cylinder.arrangement = a;
    cylinder.size = mono(1e-3);
    cylinder.spacing = 2.2e-3;
    cylinder.count = 4000;
    cylinder.region.shape = RegionSpec::Shape::cylinder;
    cylinder.region.base = {0.0, 0.0, 4e-3};
    cylinder.region.axis = 2;
    cylinder.region.radius = 1e300;
    cylinder.region.height = 8e-2;
    try {
      static_cast<void>(cases::generate_population(cylinder, {}, 1.0));
      ADD_FAILURE() << "no error";
    } catch (const cases::PopulationError& e) {
      EXPECT_EQ(e.key(), "spacing") << e.what();
    }
  }
}

TEST(Population, ASolidVolumeDrawsSpheresUntilTheirVolumeReachesIt) {
  // Thesis §6.3: radii are drawn until the spheres' volume exceeds 150 % of the reservoir's.
  const double target = 1.5 * 2e-3 * 6e-3 * 2e-3;  // 36 mm³
  for (const Arrangement a : {Arrangement::simple_cubic, Arrangement::hcp, Arrangement::random}) {
    SizeSpec size = gaussian(2e-4, 3.5e-5);
    PopulationSpec p = box_population(a, size, 11);
    p.region.max = {2e-3, 6e-3, 8e-2};  // the reservoir's footprint, tall enough for the lattice
    p.solid_volume = target;
    p.velocity_jitter = 0.01;
    const auto spheres = cases::generate_population(p, {}, 1.0);
    ASSERT_FALSE(spheres.empty());
    double volume = 0.0;
    for (const auto& s : spheres) volume += 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
    const double last = 4.0 / 3.0 * std::numbers::pi * std::pow(spheres.back().radius, 3);
    EXPECT_GE(volume, target);
    if (a != Arrangement::random) {
      EXPECT_LT(volume - last, target);  // the last sphere crossed it
    }
    EXPECT_LE(worst_overlap(spheres), 1e-12);
    // The same spheres as asking for that many by count: sizes come first from the stream.
    PopulationSpec counted = p;
    counted.solid_volume.reset();
    counted.count = spheres.size();
    const auto same = cases::generate_population(counted, {}, 1.0);
    ASSERT_EQ(same.size(), spheres.size());
    for (std::size_t k = 0; k < same.size(); ++k) {
      EXPECT_EQ(same[k].radius, spheres[k].radius);
      EXPECT_EQ(same[k].position, spheres[k].position);
      EXPECT_EQ(same[k].velocity, spheres[k].velocity);
    }
  }
  // Random insertion: a solid volume is the same request as its volume fraction of the region.
  PopulationSpec byvolume = box_population(Arrangement::random, mono(0.004), 5);
  byvolume.solid_volume = 0.2 * 0.1 * 0.08 * 0.12;
  PopulationSpec byfraction = box_population(Arrangement::random, mono(0.004), 5);
  byfraction.volume_fraction = 0.2;
  const auto v = cases::generate_population(byvolume, {}, 1.0);
  const auto f = cases::generate_population(byfraction, {}, 1.0);
  ASSERT_EQ(v.size(), f.size());
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_EQ(v[k].position, f[k].position);
}

TEST(Population, ASolidVolumeTheRegionCannotHoldNamesItsKey) {
  PopulationSpec p = box_population(Arrangement::simple_cubic, mono(0.01));
  p.solid_volume = 2.0 * 0.1 * 0.08 * 0.12;  // twice the region's volume
  try {
    static_cast<void>(cases::generate_population(p, {}, 1.0));
    ADD_FAILURE() << "no error";
  } catch (const cases::PopulationError& e) {
    EXPECT_EQ(e.key(), "solid_volume");
    EXPECT_NE(std::string(e.what()).find("lattice sites"), std::string::npos) << e.what();
  }
  const std::string text = case_texts::glass_population_case(
      "fill", "seed = 1\narrangement = \"hcp\"\ncount = 10\nsolid_volume = 1e-6\n");
  try {
    static_cast<void>(cases::load_case_text(text, "fill.toml"));
    ADD_FAILURE() << "no error";
  } catch (const cases::CaseError& e) {
    EXPECT_EQ(e.key(), "populations[0].solid_volume");
  }
}

TEST(Population, CaseFilesGenerateAndAppendAfterExplicitParticles) {
  const std::string text = R"(
[case]
name = "populated"
[model]
normal = "linear"
[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5
interaction_ratio = 1.2
[[particles]]
radius = 0.01
material = "glass"
position = [0.5, 0.5, 0.5]
fixed = true
[[populations]]
name = "bed"
material = "glass"
seed = 9
arrangement = "hcp"
count = 40
region = { shape = "box", min = [0.0, 0.0, 0.0], max = [0.1, 0.1, 0.1] }
size = { distribution = "gaussian", mean = 0.004, std_dev = 0.0005, max = 0.005 }
velocity = [0.0, 0.0, -1.0]
velocity_jitter = 0.01
[[populations]]
material = "glass"
seed = 10
arrangement = "random"
volume_fraction = 0.1
region = { shape = "cylinder", base = [0.3, 0.3, 0.0], axis = "z", radius = 0.05, height = 0.1 }
size = { distribution = "monodisperse", radius = 0.003 }
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 1.0e-3
)";
  const cases::Scene a = cases::load_case_text(text, "populated.toml");
  const cases::Scene b = cases::load_case_text(text, "populated.toml");
  ASSERT_EQ(a.population_first.size(), 2U);
  EXPECT_EQ(a.population_first[0], 1U);
  EXPECT_EQ(a.population_first[1], 41U);
  ASSERT_GT(a.particles.size(), 41U + 100U);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t k = 0; k < a.particles.size(); ++k) EXPECT_EQ(a.particles[k].position, b.particles[k].position);
  EXPECT_DOUBLE_EQ(a.particles[5].effect_radius, 1.2 * a.particles[5].radius);
  EXPECT_NEAR(a.particles[5].velocity[2], -1.0, 0.01);
}

}  // namespace
