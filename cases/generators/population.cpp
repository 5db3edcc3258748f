// SPDX-License-Identifier: MIT
#include "cases/generators/population.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <unordered_map>

#include <fmt/format.h>

#include "cases/generators/random_stream.hpp"
#include "dem/particles/particles.hpp"

namespace cases {
namespace {

/// Draws made before a truncated distribution is declared impossible to sample.
constexpr int kMaxRedraws = 10000;

/// Volume of a sphere of radius r.

/// One radius from the size specification (truncated distributions are drawn again).
double draw_radius(const SizeSpec& s, RandomStream& rng) {
  switch (s.kind) {
    case SizeSpec::Kind::monodisperse: return s.radius;
    case SizeSpec::Kind::discrete: {
      const double total = std::accumulate(s.weights.begin(), s.weights.end(), 0.0);
      double u = rng.uniform() * total;
      for (std::size_t k = 0; k < s.radii.size(); ++k) {
        if (u < s.weights[k]) return s.radii[k];
        u -= s.weights[k];
      }
      return s.radii.back();
    }
    case SizeSpec::Kind::gaussian:
    case SizeSpec::Kind::lognormal: break;
  }
  // Gaussian truncated to stay positive (and inside [min, max] when given), or log-normal.
  const double lo = s.min.value_or(0.0);
  const double hi = s.max.value_or(std::numeric_limits<double>::infinity());
  for (int k = 0; k < kMaxRedraws; ++k) {
    const double z = rng.normal();
    const double r = s.kind == SizeSpec::Kind::gaussian ? s.mean + s.std_dev * z
                                                        : s.median * std::exp(s.sigma_ln * z);
    if (r > lo && r > 0.0 && r <= hi) return r;
  }
  throw PopulationError("size", fmt::format("no radius drawn in {} tries fell inside ({}, {}]: the "
                                            "truncation leaves almost nothing of the distribution",
                                            kMaxRedraws, lo, hi));
}

/// Rounding allowance of the containment tests, relative to the sphere radius: a lattice laid
/// exactly to the region's edge must not lose its last row to the last bit of a sum.
constexpr double kEdgeAllowance = 1e-9;

/// True when a sphere of radius r centred at x lies wholly inside the region.
bool inside(const RegionSpec& g, const Vector3& x, double r) {
  const double eps = kEdgeAllowance * r;
  if (g.shape == RegionSpec::Shape::box) {
    for (int k = 0; k < 3; ++k) {
      if (x[k] - r < g.min[k] - eps || x[k] + r > g.max[k] + eps) return false;
    }
    return true;
  }
  double radial2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (k == g.axis) {
      const double h = x[k] - g.base[k];
      if (h - r < -eps || h + r > g.height + eps) return false;
    } else {
      radial2 += (x[k] - g.base[k]) * (x[k] - g.base[k]);
    }
  }
  return std::sqrt(radial2) + r <= g.radius + eps;
}

/// Bounding box of the region.
void bounds(const RegionSpec& g, Vector3& lo, Vector3& hi) {
  if (g.shape == RegionSpec::Shape::box) {
    lo = g.min;
    hi = g.max;
    return;
  }
  for (int k = 0; k < 3; ++k) {
    lo[k] = k == g.axis ? g.base[k] : g.base[k] - g.radius;
    hi[k] = k == g.axis ? g.base[k] + g.height : g.base[k] + g.radius;
  }
}

/// Steps a lattice fill may take per sphere it may make, and in all besides; a step is a position,
/// a row or a layer examined. A cylinder holds π/4 of the sites of its bounding box, only the
/// first and last rows of a chord are examined outside it, and a column one site wide takes four
/// steps a site (its layer, its row, the site, the row after).
constexpr std::uint64_t kLatticeVisitsPerSphere = 5;
/// See kLatticeVisitsPerSphere.
constexpr std::uint64_t kLatticeVisitsSlack = 1'000'000;

/// Tries random insertion may make per sphere on average before it gives up (besides one sphere's
/// max_attempts): near jamming every placement costs more, and ten million spheres with
/// max_attempts = 10⁸ must not keep the loader busy for hours.
constexpr std::uint64_t kRandomTriesPerSphere = 100;

/// Lattice sites of pitch a for spheres of radius r inside the region, bottom layer first (along
/// z for a box, along the axis for a cylinder), then by row and column; at most `wanted` of them
/// (the first ones in that order). A row of a cylinder is walked only along its chord (from two
/// pitches before to two after; inside() still decides each site). Throws PopulationError after
/// `max_visits` steps (positions, rows and layers examined): a pitch too fine for the region.
std::vector<Vector3> lattice_sites(const RegionSpec& g, Arrangement kind, double a, double r, std::size_t wanted,
                                   std::uint64_t max_visits) {
  Vector3 lo;
  Vector3 hi;
  bounds(g, lo, hi);
  const int up = g.shape == RegionSpec::Shape::cylinder ? g.axis : 2;
  const int across = up == 0 ? 1 : 0;
  const int along = 3 - up - across;
  const bool hcp = kind == Arrangement::hcp;
  const double eps = kEdgeAllowance * r;
  const double row = hcp ? a * std::sqrt(3.0) / 2.0 : a;
  const double layer = hcp ? a * std::sqrt(2.0 / 3.0) : a;
  std::vector<Vector3> sites;
  std::uint64_t visits = 0;
  // Every layer, row and position examined counts: in a region so large that adding a pitch no
  // longer moves a coordinate, rows beside a cylinder or layers without a row would otherwise
  // loop for ever without examining a position.
  const auto visit = [&] {
    if (++visits > max_visits) {
      throw PopulationError("spacing", fmt::format("a lattice of pitch {:.6g} m took {} steps through the region "
                                                   "(positions, rows and layers) and found {} sites: the pitch is "
                                                   "too fine for the region",
                                                   a, max_visits, sites.size()));
    }
  };
  for (std::int64_t k = 0; sites.size() < wanted; ++k) {
    visit();
    const double h = lo[up] + r + static_cast<double>(k) * layer;
    if (h + r > hi[up] + eps) break;
    const bool b_layer = hcp && k % 2 == 1;
    for (std::int64_t j = 0; sites.size() < wanted; ++j) {
      visit();
      const double y = lo[along] + r + static_cast<double>(j) * row + (b_layer ? a * std::sqrt(3.0) / 6.0 : 0.0);
      if (y + r > hi[along] + eps) break;
      const double offset = (hcp && j % 2 == 1 ? 0.5 * a : 0.0) + (b_layer ? 0.5 * a : 0.0);
      const double x0 = lo[across] + r + offset;
      std::int64_t first = 0;
      double last = std::numeric_limits<double>::infinity();
      if (g.shape == RegionSpec::Shape::cylinder) {
        const double dy = y - g.base[along];
        const double reach = g.radius + eps - r;
        const double chord2 = reach * reach - dy * dy;
        if (!(chord2 >= 0.0)) continue;  // the row passes beside the cylinder
        const double half = std::sqrt(chord2);
        const double skip = std::floor((g.base[across] - half - x0) / a) - 2.0;
        if (skip > 0.0 && skip < 1e15) first = static_cast<std::int64_t>(skip);
        last = g.base[across] + half + 2.0 * a;
      }
      for (std::int64_t i = first; sites.size() < wanted; ++i) {
        const double x = x0 + static_cast<double>(i) * a;
        if (x + r > hi[across] + eps || x > last) break;
        visit();
        Vector3 p{};
        p[up] = h;
        p[along] = y;
        p[across] = x;
        if (inside(g, p, r)) sites.push_back(p);
      }
    }
  }
  return sites;
}

/// A uniform hash grid of placed spheres for the overlap tests of random insertion.
class OverlapGrid {
 public:
  explicit OverlapGrid(double cell) : cell_(cell) {}
  void add(const Vector3& x, double r) {
    spheres_.push_back({x, r});
    cells_[key(cell_of(x))].push_back(spheres_.size() - 1);
  }
  /// True when a sphere (x, r) would overlap a placed one (reach ≤ the cell edge).
  [[nodiscard]] bool overlaps(const Vector3& x, double r) const {
    const auto c = cell_of(x);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (const std::size_t s : it->second) {
            const auto& [y, q] = spheres_[s];
            const double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                              (x[2] - y[2]) * (x[2] - y[2]);
            if (d2 < (r + q) * (r + q)) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  [[nodiscard]] std::array<std::int64_t, 3> cell_of(const Vector3& x) const {
    return {cell_index(x[0]), cell_index(x[1]), cell_index(x[2])};
  }
  /// Cell of one coordinate, clamped into the int64 range (a region may span 1e300 m; NaN: 0).
  [[nodiscard]] std::int64_t cell_index(double x) const {
    constexpr double kLimit = 4.0e18;
    const double c = std::floor(x / cell_);
    return !(c > -kLimit) ? (c < 0.0 ? -static_cast<std::int64_t>(kLimit) : 0)
                          : static_cast<std::int64_t>(std::min(c, kLimit));
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    const auto h = [](std::int64_t v) { return static_cast<std::uint64_t>(v) * 0x9E3779B97F4A7C15ULL; };
    return h(c[0]) ^ (h(c[1]) << 21U) ^ (h(c[2]) << 42U) ^ (h(c[2]) >> 22U);
  }
  double cell_;
  std::vector<std::pair<Vector3, double>> spheres_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

/// Checks the size specification; throws naming the sub-key.
void check_size(const SizeSpec& s) {
  switch (s.kind) {
    case SizeSpec::Kind::monodisperse:
      if (!(s.radius > 0.0)) throw PopulationError("size.radius", "must be > 0");
      break;
    case SizeSpec::Kind::gaussian:
      if (!(s.mean > 0.0)) throw PopulationError("size.mean", "must be > 0");
      if (!(s.std_dev >= 0.0)) throw PopulationError("size.std_dev", fmt::format("must be >= 0, got {}", s.std_dev));
      break;
    case SizeSpec::Kind::lognormal:
      if (!(s.median > 0.0)) throw PopulationError("size.median", "must be > 0");
      if (!(s.sigma_ln >= 0.0)) throw PopulationError("size.sigma_ln", fmt::format("must be >= 0, got {}", s.sigma_ln));
      break;
    case SizeSpec::Kind::discrete:
      if (s.radii.empty() || s.radii.size() != s.weights.size()) {
        throw PopulationError("size.weights", fmt::format("needs one weight per radius ({} radii, {} weights)",
                                                          s.radii.size(), s.weights.size()));
      }
      break;
  }
  if (s.min && s.max && !(*s.min < *s.max)) {
    throw PopulationError("size.max", fmt::format("must exceed size.min ({}), got {}", *s.min, *s.max));
  }
}

/// Gives every sphere the population's velocity plus its seeded jitter, in list order.
void assign_velocities(std::vector<ParticleSpec>& spheres, const PopulationSpec& spec, RandomStream& rng) {
  for (ParticleSpec& p : spheres) {
    p.velocity = spec.velocity;
    if (spec.velocity_jitter > 0.0) {
      for (int k = 0; k < 3; ++k) p.velocity[k] += spec.velocity_jitter * rng.uniform(-1.0, 1.0);
    }
  }
}

/// A sphere of the population at x.
ParticleSpec sphere(const PopulationSpec& spec, const Vector3& x, double r, double interaction_ratio) {
  ParticleSpec p;
  p.radius = r;
  p.effect_radius = r * interaction_ratio;
  p.material = spec.material;
  p.position = x;
  p.fixed = spec.fixed;
  return p;
}

}  // namespace

double largest_radius(const SizeSpec& s) {
  switch (s.kind) {
    case SizeSpec::Kind::monodisperse: return s.radius;
    case SizeSpec::Kind::discrete: return *std::max_element(s.radii.begin(), s.radii.end());
    case SizeSpec::Kind::gaussian:
      return s.max.value_or(s.mean + 6.0 * s.std_dev);  // untruncated: 6 σ (p < 1e-9 per draw)
    case SizeSpec::Kind::lognormal: return s.max.value_or(s.median * std::exp(6.0 * s.sigma_ln));
  }
  return s.radius;
}

double region_volume(const RegionSpec& g) {
  if (g.shape == RegionSpec::Shape::box) {
    return (g.max[0] - g.min[0]) * (g.max[1] - g.min[1]) * (g.max[2] - g.min[2]);
  }
  return std::numbers::pi * g.radius * g.radius * g.height;
}

std::vector<ParticleSpec> generate_population(const PopulationSpec& spec,
                                              const std::vector<ParticleSpec>& placed,
                                              double interaction_ratio, std::size_t max_spheres) {
  check_size(spec.size);
  RandomStream rng(spec.seed);
  const RegionSpec& g = spec.region;
  const double r_max = largest_radius(spec.size);
  {
    // The region must hold at least one sphere of the largest radius.
    Vector3 lo;
    Vector3 hi;
    bounds(g, lo, hi);
    Vector3 centre{};
    for (int k = 0; k < 3; ++k) centre[k] = 0.5 * (lo[k] + hi[k]);
    if (!inside(g, centre, r_max)) {
      throw PopulationError("region", fmt::format("is smaller than one sphere of the largest radius {:.6g} m", r_max));
    }
  }

  // Radii first: one stream decides sizes, then positions, then velocities, in that order.
  std::vector<double> radii;
  if (spec.count && *spec.count > max_spheres) {
    throw PopulationError("count", fmt::format("asks for {} spheres; the scene may hold at most {} more", *spec.count,
                                               max_spheres));
  }
  // A solid volume fixes the number of spheres by their drawn sizes, before any position.
  const auto draw_until = [&](double target, std::string_view key, const std::string& what) {
    double volume = 0.0;
    while (volume < target) {
      if (radii.size() == max_spheres) {
        throw PopulationError(std::string(key), fmt::format("needs more than {} spheres {}, the most the scene may "
                                                            "still hold",
                                                            max_spheres, what));
      }
      const double r = draw_radius(spec.size, rng);
      radii.push_back(r);
      volume += dem::sphere_volume(r);
    }
  };
  if (spec.solid_volume) {
    draw_until(*spec.solid_volume, "solid_volume", fmt::format("to reach a solid volume of {:.6g} m³", *spec.solid_volume));
  }
  if (spec.arrangement != Arrangement::random || spec.count || spec.solid_volume) {
    std::size_t n = spec.solid_volume ? radii.size() : spec.count.value_or(0);
    const bool every_site = !spec.count && !spec.solid_volume;
    std::vector<Vector3> sites;
    if (spec.arrangement != Arrangement::random) {
      const double pitch = spec.spacing > 0.0 ? spec.spacing : 2.0 * r_max;
      if (pitch < 2.0 * r_max) {
        throw PopulationError("spacing", fmt::format("{:.6g} m is less than the largest diameter {:.6g} m: "
                                                     "neighbouring spheres would overlap",
                                                     pitch, 2.0 * r_max));
      }
      if (every_site) {
        // Every site is wanted: estimate them first (a cell of volume a³, or a³/√2 close packed),
        // so that a fine pitch in a large region is refused before any is made.
        const double cell = spec.arrangement == Arrangement::hcp ? pitch * pitch * pitch / std::sqrt(2.0)
                                                                 : pitch * pitch * pitch;
        const double estimate = region_volume(g) / cell;
        if (!(estimate <= 2.0 * static_cast<double>(max_spheres))) {
          throw PopulationError("spacing", fmt::format("a lattice of pitch {:.6g} m fills the region with about {:.3g} "
                                                       "spheres; the scene may hold at most {} more (give count)",
                                                       pitch, estimate, max_spheres));
        }
      }
      // One site more than allowed tells a region holding too many from one holding exactly enough.
      sites = lattice_sites(g, spec.arrangement, pitch, r_max, every_site ? max_spheres + 1 : n,
                            kLatticeVisitsPerSphere * max_spheres + kLatticeVisitsSlack);
      if (every_site) n = sites.size();
      if (n > max_spheres) {
        throw PopulationError("spacing", fmt::format("a lattice of pitch {:.6g} m fills the region with more than {} "
                                                     "spheres, the most the scene may still hold (give count)",
                                                     pitch, max_spheres));
      }
      if (n > sites.size()) {
        throw PopulationError(spec.solid_volume ? "solid_volume" : "count",
                              fmt::format("{} {} spheres; the region holds {} lattice sites of pitch {:.6g} m",
                                          spec.solid_volume ? "needs" : "asks for", n, sites.size(), pitch));
      }
    }
    if (!spec.solid_volume) {
      for (std::size_t k = 0; k < n; ++k) radii.push_back(draw_radius(spec.size, rng));
    }
    if (spec.arrangement != Arrangement::random) {
      std::vector<ParticleSpec> out;
      for (std::size_t k = 0; k < n; ++k) out.push_back(sphere(spec, sites[k], radii[k], interaction_ratio));
      assign_velocities(out, spec, rng);
      return out;
    }
  } else {
    draw_until(spec.volume_fraction.value_or(0.0) * region_volume(g), "volume_fraction",
               fmt::format("to fill {:.3g} of the region's {:.6g} m³", spec.volume_fraction.value_or(0.0), region_volume(g)));
  }

  // Random sequential insertion, largest spheres first (they are the hardest to place).
  std::vector<std::size_t> order(radii.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&radii](std::size_t a, std::size_t b) { return radii[a] > radii[b]; });
  double reach = 2.0 * r_max;
  for (const ParticleSpec& p : placed) reach = std::max(reach, 2.0 * p.radius);
  OverlapGrid grid(reach);
  for (const ParticleSpec& p : placed) grid.add(p.position, p.radius);
  Vector3 lo;
  Vector3 hi;
  bounds(g, lo, hi);
  std::vector<ParticleSpec> out;
  double filled = 0.0;
  // Tries in all: kRandomTriesPerSphere a sphere on average, and one sphere's max_attempts.
  const std::uint64_t budget = kRandomTriesPerSphere * radii.size() + spec.max_attempts;
  std::uint64_t tries = 0;
  for (const std::size_t k : order) {
    const double r = radii[k];
    bool done = false;
    for (std::size_t attempt = 0; attempt < spec.max_attempts && !done && tries < budget; ++attempt) {
      ++tries;
      Vector3 x{};
      for (int a = 0; a < 3; ++a) x[a] = rng.uniform(lo[a] + r, hi[a] - r);
      if (!inside(g, x, r) || grid.overlaps(x, r)) continue;
      grid.add(x, r);
      out.push_back(sphere(spec, x, r, interaction_ratio));
      filled += dem::sphere_volume(r);
      done = true;
    }
    if (!done) {
      const std::string why = tries >= budget ? fmt::format("used up its {} tries ({} a sphere on average, plus "
                                                            "max_attempts)",
                                                            budget, kRandomTriesPerSphere)
                                              : fmt::format("found no free spot for the next in {} tries",
                                                            spec.max_attempts);
      throw PopulationError(spec.solid_volume ? "solid_volume" : (spec.volume_fraction ? "volume_fraction" : "count"),
                            fmt::format("random insertion placed {} of {} spheres (volume fraction {:.3f}) and {}: "
                                        "random sequential insertion jams near 0.38 for equal spheres; ask for "
                                        "fewer spheres or a lattice",
                                        out.size(), radii.size(), filled / region_volume(g), why));
    }
  }
  assign_velocities(out, spec, rng);
  return out;
}

}  // namespace cases
