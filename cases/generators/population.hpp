// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases/limits.hpp"
#include "cases/scene.hpp"

namespace cases {

/// Where a population goes: an axis-aligned box, or an upright cylinder along x, y or z.
struct RegionSpec {
  enum class Shape { box, cylinder };
  Shape shape = Shape::box;
  Vector3 min{};      ///< box: lower corner [m]
  Vector3 max{};      ///< box: upper corner [m]
  Vector3 base{};     ///< cylinder: centre of the bottom face [m]
  int axis = 2;       ///< cylinder: 0, 1, 2 for x, y, z
  double radius = 0;  ///< cylinder radius [m]
  double height = 0;  ///< cylinder height along the axis [m]
};

/// How the body radii of a population are drawn.
struct SizeSpec {
  enum class Kind { monodisperse, gaussian, lognormal, discrete };
  Kind kind = Kind::monodisperse;
  double radius = 0.0;              ///< monodisperse [m]
  double mean = 0.0;                ///< gaussian mean radius [m]
  double std_dev = 0.0;             ///< gaussian standard deviation [m]
  double median = 0.0;              ///< lognormal median radius [m]
  double sigma_ln = 0.0;            ///< lognormal standard deviation of ln r [-]
  std::optional<double> min;        ///< truncation: radii below are drawn again [m]
  std::optional<double> max;        ///< truncation: radii above are drawn again [m]
  std::vector<double> radii;        ///< discrete table of radii [m]
  std::vector<double> weights;      ///< discrete table: relative number frequencies
};

/// How a population is arranged.
enum class Arrangement { simple_cubic, hcp, random };

/// A generated population of spheres (a case file's [[populations]] entry).
struct PopulationSpec {
  std::string name;
  std::size_t material = 0;
  RegionSpec region;
  SizeSpec size;
  Arrangement arrangement = Arrangement::simple_cubic;
  std::optional<std::size_t> count;         ///< spheres wanted (lattice: the first sites, bottom up)
  std::optional<double> volume_fraction;    ///< random: fill the region to this fraction
  /// Draw spheres until their total volume reaches this [m³] (thesis §6.3: 150 % of the reservoir's
  /// volume); a lattice then takes that many sites, bottom up.
  std::optional<double> solid_volume;
  double spacing = 0.0;                     ///< lattice pitch [m]; 0: twice the largest radius
  std::uint64_t seed = 1;
  Vector3 velocity{};                       ///< every sphere's velocity [m/s]
  double velocity_jitter = 0.0;             ///< plus a random velocity of up to this speed [m/s]
  bool fixed = false;
  std::size_t max_attempts = 10000;         ///< random insertion: tries per sphere
};

/// A population that cannot be generated; `key` is the entry's sub-key ("region.max", "count").
class PopulationError : public std::runtime_error {
 public:
  PopulationError(std::string key, const std::string& problem)
      : std::runtime_error(problem), key_(std::move(key)) {}
  [[nodiscard]] const std::string& key() const noexcept { return key_; }

 private:
  std::string key_;
};

/// Largest radius the size specification can draw [m].
[[nodiscard]] double largest_radius(const SizeSpec& size);
/// Volume of a region [m³].
[[nodiscard]] double region_volume(const RegionSpec& region);

/// The spheres of `spec`, a function of the specification and its seed alone (and, for random
/// insertion, of the spheres already `placed`, which the new ones do not overlap). Effect radii
/// are r·interaction_ratio. Throws PopulationError on an impossible request: a region smaller
/// than one sphere, more spheres than the region holds, a volume fraction random insertion
/// cannot reach, or more than `max_spheres` spheres (found before they are made: the work done
/// is bounded by max_spheres whatever the region and the radii).
std::vector<ParticleSpec> generate_population(const PopulationSpec& spec,
                                              const std::vector<ParticleSpec>& placed,
                                              double interaction_ratio,
                                              std::size_t max_spheres = kMaxParticles);

}  // namespace cases
