// SPDX-License-Identifier: MIT
// Section reader for [[populations]]: generated particles (lattice fill, random insertion, size
// distributions), appended to the explicit [[particles]] in file order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "cases/generators/population.hpp"
#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/names.hpp"

namespace cases::loader {
namespace {

constexpr auto kPopulationKeys = std::to_array<std::string_view>(
    {"name", "material", "seed", "arrangement", "count", "volume_fraction", "solid_volume", "spacing", "velocity",
     "velocity_jitter", "fixed", "max_attempts", "region", "size"});
constexpr auto kBoxKeys = std::to_array<std::string_view>({"shape", "min", "max"});
constexpr auto kCylinderKeys = std::to_array<std::string_view>({"shape", "base", "axis", "radius", "height"});
constexpr auto kSizeKeys = std::to_array<std::string_view>(
    {"distribution", "radius", "mean", "std_dev", "median", "sigma_ln", "radii", "weights", "min", "max"});

constexpr std::array<std::string_view, 3> kArrangements{"simple_cubic", "hcp", "random"};
constexpr std::array<std::string_view, 2> kShapes{"box", "cylinder"};
constexpr std::array<std::string_view, 4> kDistributions{"monodisperse", "gaussian", "lognormal", "discrete"};

/// Keys of one distribution (besides `distribution`, `min`, `max`).
std::vector<std::string_view> distribution_keys(std::string_view d) {
  if (d == "monodisperse") return {"radius"};
  if (d == "gaussian") return {"mean", "std_dev"};
  if (d == "lognormal") return {"median", "sigma_ln"};
  return {"radii", "weights"};
}

RegionSpec read_region(const Table& t) {
  RegionSpec g;
  const std::string shape = t.require("shape").keyword(kShapes, "region shape");
  if (shape == "box") {
    t.allow_only(kBoxKeys);
    g.shape = RegionSpec::Shape::box;
    g.min = t.require("min").vector3();
    g.max = t.require("max").vector3();
    for (int k = 0; k < 3; ++k) {
      if (!(g.max[k] > g.min[k])) {
        t.fail("max", fmt::format("must exceed min along every axis (axis {}: min {}, max {})", kAxes[k], g.min[k], g.max[k]));
      }
    }
  } else {
    t.allow_only(kCylinderKeys);
    g.shape = RegionSpec::Shape::cylinder;
    g.base = t.require("base").vector3();
    const std::string axis = t.require("axis").keyword(kAxes, "axis");
    g.axis = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
    g.radius = t.require("radius").number(positive_range());
    g.height = t.require("height").number(positive_range());
  }
  return g;
}

SizeSpec read_size(const Table& t) {
  t.allow_only(kSizeKeys);
  SizeSpec s;
  const std::string d = t.require("distribution").keyword(kDistributions, "size distribution");
  for (const std::string_view key : {"radius", "mean", "std_dev", "median", "sigma_ln", "radii", "weights"}) {
    const auto wanted = distribution_keys(d);
    if (t.has(key) && std::find(wanted.begin(), wanted.end(), key) == wanted.end()) {
      t.fail(key, fmt::format("is not a parameter of distribution '{}' (it takes {})", d, fmt::join(wanted, ", ")));
    }
  }
  if (d == "monodisperse") {
    s.kind = SizeSpec::Kind::monodisperse;
    s.radius = t.require("radius").number(positive_range());
  } else if (d == "gaussian") {
    s.kind = SizeSpec::Kind::gaussian;
    s.mean = t.require("mean").number(positive_range());
    s.std_dev = t.require("std_dev").number(non_negative_range());
  } else if (d == "lognormal") {
    s.kind = SizeSpec::Kind::lognormal;
    s.median = t.require("median").number(positive_range());
    s.sigma_ln = t.require("sigma_ln").number(non_negative_range());
  } else {
    s.kind = SizeSpec::Kind::discrete;
    const Value radii = t.require("radii");
    const Value weights = t.require("weights");
    for (const Value& v : radii.elements()) s.radii.push_back(v.number(positive_range()));
    for (const Value& v : weights.elements()) s.weights.push_back(v.number(non_negative_range()));
    if (s.radii.empty()) radii.fail("must list at least one radius");
    if (s.weights.size() != s.radii.size()) {
      weights.fail(fmt::format("needs one weight per radius ({} radii, {} weights)", s.radii.size(), s.weights.size()));
    }
    double total = 0.0;
    for (const double w : s.weights) total += w;
    if (!(total > 0.0)) weights.fail("must not all be zero");
  }
  if (const auto v = t.find("min")) s.min = v->number(non_negative_range());
  if (const auto v = t.find("max")) s.max = v->number(positive_range());
  if (s.min && s.max && !(*s.min < *s.max)) t.fail("max", fmt::format("must exceed min ({}), got {}", *s.min, *s.max));
  if (s.kind == SizeSpec::Kind::discrete && (s.min || s.max)) {
    t.fail(s.min ? "min" : "max", "truncates a continuous distribution; a discrete table lists its radii itself");
  }
  return s;
}

PopulationSpec read_population(const Table& t, const Scene& scene) {
  t.allow_only(kPopulationKeys);
  PopulationSpec p;
  if (const auto v = t.find("name")) p.name = read_name(*v);
  p.material = material_index(t.require("material"), scene);
  p.seed = static_cast<std::uint64_t>(t.require("seed").integer(0, INT64_MAX));
  const std::string arrangement = t.require("arrangement").keyword(kArrangements, "arrangement");
  p.arrangement = arrangement == "simple_cubic" ? Arrangement::simple_cubic
                                                : (arrangement == "hcp" ? Arrangement::hcp : Arrangement::random);
  const bool random = p.arrangement == Arrangement::random;
  if (const auto v = t.find("count")) p.count = static_cast<std::size_t>(v->integer(1, 100'000'000));
  if (const auto v = t.find("volume_fraction")) {
    if (!random) v->fail("applies to arrangement = \"random\"; a lattice fills its sites (use count to take fewer)");
    p.volume_fraction = v->number({0.0, 0.64, true, true});
  }
  if (const auto v = t.find("solid_volume")) {
    if (p.count || p.volume_fraction) {
      v->fail(fmt::format("gives the number of spheres, as {} does: give one of them", p.count ? "count" : "volume_fraction"));
    }
    p.solid_volume = v->number(positive_range());
  }
  if (random && !p.count && !p.volume_fraction && !p.solid_volume) {
    t.fail("count", "random insertion needs one of count, volume_fraction and solid_volume");
  }
  if (random && p.count && p.volume_fraction) {
    t.fail("volume_fraction", "random insertion needs one of count, volume_fraction and solid_volume, not two");
  }
  if (const auto v = t.find("spacing")) {
    if (random) v->fail("applies to lattice arrangements only");
    p.spacing = v->number(positive_range());
  }
  if (const auto v = t.find("max_attempts")) {
    if (!random) v->fail("applies to arrangement = \"random\" only");
    p.max_attempts = static_cast<std::size_t>(v->integer(1, 100'000'000));
  }
  if (const auto v = t.find("velocity")) p.velocity = read_velocity(*v);
  if (const auto v = t.find("velocity_jitter")) {
    p.velocity_jitter = v->number(non_negative_range());
    // The fastest sphere moves at most |velocity| + √3 jitter.
    check_speed(*v, length(p.velocity) + std::sqrt(3.0) * p.velocity_jitter,
                "largest speed |velocity| + √3 velocity_jitter");
  }
  if (const auto v = t.find("fixed")) p.fixed = v->boolean();
  if (p.fixed && (p.velocity[0] != 0.0 || p.velocity[1] != 0.0 || p.velocity[2] != 0.0 || p.velocity_jitter > 0.0)) {
    t.fail("fixed", "a fixed population must be at rest (no velocity, no velocity_jitter)");
  }
  p.region = read_region(t.require("region", "table [populations.region]").table());
  p.size = read_size(t.require("size", "table [populations.size]").table());
  return p;
}

}  // namespace

void read_populations(const Table& root, Scene& scene) {
  const auto section = root.find("populations");
  if (!section) return;
  if (!section->node().is_array()) {
    section->fail("expected an array of tables ([[populations]]), got " + describe(section->node()));
  }
  for (const Value& entry : section->elements()) {
    const Table t = entry.table();
    const PopulationSpec spec = read_population(t, scene);
    const double ratio = scene.materials[spec.material].interaction_ratio.value_or(1.0);
    scene.population_first.push_back(scene.particles.size());
    try {
      std::vector<ParticleSpec> made =
          generate_population(spec, scene.particles, ratio, kMaxParticles - scene.particles.size());
      scene.particles.insert(scene.particles.end(), made.begin(), made.end());
    } catch (const PopulationError& e) {
      const std::string sub = e.key();
      const auto dot = sub.find('.');
      const std::string head = sub.substr(0, dot);
      if (dot == std::string::npos) t.fail(head, e.what());
      t.require(head).table().fail(sub.substr(dot + 1), e.what());
    }
  }
}

}  // namespace cases::loader
