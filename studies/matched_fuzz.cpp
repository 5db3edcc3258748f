// SPDX-License-Identifier: MIT
#include "studies/matched_fuzz.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "cases/catalogue.hpp"
#include "dem/contact/registry.hpp"
#include "dem/contact/wall.hpp"

namespace studies {
namespace {

/// A plausible range for a material key, for millimetre spheres of ~10⁻⁵ kg colliding at
/// ~0.1–1 m/s (contact times ~10⁻⁴ s); `log` draws log-uniformly.
struct KeyRange {
  std::string_view key;
  double low;
  double high;
  bool log;
};

constexpr std::array kRanges{
    KeyRange{"normal_stiffness", 1e3, 1e5, true},
    KeyRange{"restitution", 0.3, 0.95, false},
    KeyRange{"youngs_modulus", 1e6, 1e8, true},
    KeyRange{"poisson_ratio", 0.2, 0.4, false},
    KeyRange{"tangential_stiffness", 5e2, 5e4, true},
    KeyRange{"tangential_damping_ratio", 0.0, 0.5, false},
    KeyRange{"friction", 0.1, 0.8, false},
    KeyRange{"rolling_friction", 0.01, 0.2, false},
    KeyRange{"rolling_stiffness", 1e1, 1e3, true},
    KeyRange{"rolling_damping", 0.0, 1e-4, false},
    KeyRange{"cohesive_stiffness", 1e1, 1e3, true},
    KeyRange{"surface_energy", 0.005, 0.1, true},
    KeyRange{"interaction_ratio", 1.0, 1.1, false},
    KeyRange{"damping_coefficient", 0.01, 0.3, true},
    KeyRange{"viscous_modulus", 1e3, 1e5, true},
    KeyRange{"damping_rate", 10.0, 200.0, true},
    KeyRange{"viscoelastic_damping", 1e7, 1e9, true},
    KeyRange{"relative_permittivity", 1.0, 5.0, false},
    KeyRange{"coulomb_cutoff", 3e-3, 1e-2, false},
    KeyRange{"potential_exponent", 2.0, 6.0, false},
    KeyRange{"potential_critical_ratio", 1.05, 1.5, false},
    KeyRange{"potential_gravity", 9.81, 9.81, false},
};

/// The material keys a model reads: its sub-models' pair properties, with the inputs of the
/// derived ones (E* and G* from E and ν; the effect radius beside a cohesive stiffness).
std::set<std::string_view> material_keys(const std::array<std::string_view, 5>& model) {
  std::set<std::string_view> keys;
  std::size_t k = 0;
  for (const dem::Slot slot : dem::all_slots()) {
    if (const dem::SubModelInfo* row = dem::find_sub_model(slot, model[k++])) {
      keys.insert(row->properties.begin(), row->properties.end());
    }
  }
  if (keys.erase("effective_modulus") + keys.erase("effective_shear_modulus") > 0) {
    keys.insert({"youngs_modulus", "poisson_ratio"});
  }
  if (keys.contains("cohesive_stiffness")) keys.insert("interaction_ratio");
  return keys;
}

/// True when a registry row's mapping text for a code names a counterpart (the rows without one
/// begin "none", "no …", "not …" or "omitted"). Only weights the draw: the driver decides.
bool mapped(std::string_view text) {
  for (const std::string_view lead : {"none", "no ", "not ", "omitted"}) {
    if (text.substr(0, lead.size()) == lead) return false;
  }
  return !text.empty();
}

/// The three numbers of a vector in a case file.
std::string vec(double x, double y, double z) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", x, y, z); }

/// One drawn sphere: radius, centre [m] and material index.
struct Sphere {
  double r, x, y, z;
  int material;
};

/// Distance from a sphere's centre to the triangle (a, b, c), by the core's own triangle.
double distance_to_triangle(const Sphere& s, const dem::Vec3& a, const dem::Vec3& b, const dem::Vec3& c) {
  return dem::wall_frame(dem::triangle_wall(a, b, c), dem::Vec3(s.x, s.y, s.z), 0.0).distance;
}

/// Distance from a sphere's centre to the segment (a, b).
double distance_to_segment(const Sphere& s, const dem::Vec3& a, const dem::Vec3& b) {
  const dem::Vec3 x(s.x, s.y, s.z);
  const dem::Vec3 e = b - a;
  const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * e)).norm();
}

/// For YADE and LIGGGHTS, two scenes in five get a mesh wall under the spheres, drawn from a
/// stream of its own (the draft's other draws are the same with or without it; a draft the mesh
/// makes inexpressible is redrawn, so a seed's accepted scene may differ from what it was before
/// meshes came): a triangle 6–12 mm across tilted up to 0.5 rad, the sphere nearest its plane
/// within a few per cent of a radius of touching, and a second triangle folded up to ±0.6 rad
/// about one of its edges. The shared edge stays kYadeMeshEdgeClearance clear of every sphere for
/// YADE, which meets each facet on its own there (docs/engines.md, "Meshes"); LIGGGHTS' spheres
/// may start anywhere near it. A second
/// facet that would start overlapping a sphere is left out. The mesh takes one of the scene's
/// `materials`. Appends the wall to the case text and the STL to the scene's files.
void add_mesh(FuzzScene& scene, std::string& t, std::string_view code, std::uint64_t mixed,
              const std::vector<Sphere>& spheres, int materials) {
  if (code != "yade" && code != "liggghts") return;
  std::mt19937_64 rng(mixed ^ 0xD1B54A32D192ED03ULL);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  if (unit(rng) >= 0.4) return;
  const double tilt = uniform(0.0, 0.5), azimuth = uniform(0.0, 2.0 * M_PI);
  const dem::Vec3 n(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
  const dem::Vec3 u = n.cross(dem::Vec3::UnitY()).normalized();
  const dem::Vec3 v = n.cross(u);
  double height = std::numeric_limits<double>::infinity();
  double smallest = spheres[0].r;
  dem::Vec3 centre = dem::Vec3::Zero();
  for (const Sphere& s : spheres) {
    height = std::min(height, n.dot(dem::Vec3(s.x, s.y, s.z)) - s.r);
    smallest = std::min(smallest, s.r);
    centre += dem::Vec3(s.x, s.y, s.z) / static_cast<double>(spheres.size());
  }
  height -= uniform(-0.005, 0.02) * smallest;
  const dem::Vec3 middle = centre - (n.dot(centre) - height) * n;
  const double size = uniform(0.006, 0.012), start = uniform(0.0, 2.0 * M_PI);
  std::array<dem::Vec3, 4> c;
  for (int k = 0; k < 3; ++k) {
    const double angle = start + 2.0 * M_PI * k / 3.0 + uniform(-0.3, 0.3);
    c[static_cast<std::size_t>(k)] = middle + size * (std::cos(angle) * u + std::sin(angle) * v);
  }
  const dem::Vec3 edge_middle = 0.5 * (c[0] + c[1]);
  const double fold = uniform(-0.6, 0.6);
  c[3] = edge_middle + uniform(0.003, 0.008) * (std::cos(fold) * (edge_middle - middle).normalized() + std::sin(fold) * n);
  bool second = true;
  for (const Sphere& s : spheres) {
    second = second && s.r - distance_to_triangle(s, c[1], c[0], c[3]) < 0.005 * s.r &&
             (code != "yade" || distance_to_segment(s, c[0], c[1]) > s.r + kYadeMeshEdgeClearance);
  }
  std::string stl = "solid fuzz\n";
  const auto facet = [&](const dem::Vec3& a, const dem::Vec3& b, const dem::Vec3& d) {
    stl += "  facet normal 0 0 0\n    outer loop\n";
    for (const dem::Vec3* p : {&a, &b, &d}) stl += fmt::format("      vertex {:.17g} {:.17g} {:.17g}\n", (*p)[0], (*p)[1], (*p)[2]);
    stl += "    endloop\n  endfacet\n";
  };
  facet(c[0], c[1], c[2]);
  if (second) facet(c[1], c[0], c[3]);
  stl += "endsolid fuzz\n";
  scene.facets = second ? 2 : 1;
  const std::string file = scene.name + ".stl";
  scene.files.emplace_back(file, std::move(stl));
  t += fmt::format("[[walls]]\ntype = \"mesh\"\nname = \"mesh\"\nfile = \"{}\"\nmaterial = \"m{}\"\n\n", file,
                   static_cast<int>(unit(rng) * materials) % materials);
}

}  // namespace

namespace {

/// The k-th draft of `seed`: draft 0 is the seed's own scene; later ones come from the seed
/// mixed with k (splitmix64), named and labelled after the seed.
FuzzScene draft(std::string_view code, std::uint64_t seed, int k);

}  // namespace

FuzzScene random_matched_scene(std::string_view code, std::uint64_t seed, const ExpressibleFilter& expressible) {
  // The seed's own stream decides whether its scene must be expressible.
  std::mt19937_64 coin(seed ^ 0x9E3779B97F4A7C15ULL);
  const bool must = std::uniform_real_distribution<double>(0.0, 1.0)(coin) < kExpressibleShare;
  FuzzScene scene = draft(code, seed, 0);
  for (int k = 1; must && k < kMaxDrafts && !expressible(scene); ++k) scene = draft(code, seed, k);
  return scene;
}

FuzzScene random_matched_scene(std::string_view code, std::uint64_t seed) { return draft(code, seed, 0); }

namespace {

FuzzScene draft(std::string_view code, std::uint64_t seed, int k) {
  if (!cases::is_reference_code(code)) {
    throw std::invalid_argument(fmt::format("unknown reference code '{}' (known: lammps, yade, liggghts)", code));
  }
  std::uint64_t mixed = seed;
  if (k > 0) {
    // splitmix64 of seed + k: independent streams per draft.
    mixed = seed + 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(k);
    mixed = (mixed ^ (mixed >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    mixed = (mixed ^ (mixed >> 27U)) * 0x94D049BB133111EBULL;
    mixed ^= mixed >> 31U;
  }
  std::mt19937_64 rng(mixed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(unit(rng) * static_cast<double>(n)) % n; };

  FuzzScene scene;
  scene.name = fmt::format("fuzz_{}_{}", code, seed);

  // The model: one sub-model per slot. Mostly (85 %) among the rows whose registry entry gives
  // the code a mapping, so that most scenes run; otherwise any row, so that the mappings' n/a
  // answers are exercised too. JKR and DMT cohesion extend Hertz: they bring normal = hertz.
  std::array<std::string_view, 5> model{};
  std::size_t slot_index = 0;
  for (const dem::Slot slot : dem::all_slots()) {
    const auto rows = dem::sub_models(slot);
    std::vector<std::string_view> expressed;
    for (const dem::SubModelInfo& row : rows) {
      const std::string_view text = code == "lammps" ? row.lammps : code == "yade" ? row.yade : row.liggghts;
      if (row.keyword == "none" || mapped(text)) expressed.push_back(row.keyword);
    }
    const bool any = expressed.empty() || unit(rng) >= 0.85;
    model[slot_index++] = any ? rows[pick(rows.size())].keyword : expressed[pick(expressed.size())];
  }
  if (model[3] == "jkr" || model[3] == "dmt") model[0] = "hertz";
  scene.model = fmt::format("{}/{}/{}/{}/{}", model[0], model[1], model[2], model[3], model[4]);
  const std::set<std::string_view> keys = material_keys(model);

  std::string t;
  t += fmt::format("# Random matched scene: code {}, seed {}{} (demwb fuzz-matched; docs/engines.md).\n\n", code, seed,
                   k > 0 ? fmt::format(", draft {}", k + 1) : std::string());
  t += fmt::format("[case]\nname = \"{}\"\ndescription = \"random scene {} of the matched fuzz against {}\"\n\n",
                   scene.name, seed, code);
  // The policies the code's native mapping asks a case to state before it compares: half the
  // scenes take the code's convention (LAMMPS: the Mindlin stiffness on the JKR contact radius;
  // YADE: under DMT, the dashpot capped at the pull-off force and the friction limit raised by
  // it), half the defaults, so that both
  // the comparisons and the n/a answers are exercised.
  const bool code_policies = unit(rng) < 0.5;
  const bool lammps = code == "lammps";
  const bool yade = code == "yade";
  t += fmt::format("[model]\nnormal = \"{}\"\ndamping = \"{}\"\ntangential = \"{}\"\ncohesion = \"{}\"\nrolling = \"{}\"\n"
                   "mindlin_radius = \"{}\"\nadhesive_dashpot = \"{}\"\n{}\n",
                   model[0], model[1], model[2], model[3], model[4],
                   code_policies && lammps ? "contact_radius" : "overlap",
                   code_policies && yade ? "pulloff_cap" : "clamp",
                   code_policies && yade ? "friction_limit = \"total_plus_pulloff\"\n" : "");

  const int materials = unit(rng) < 0.5 ? 1 : 2;
  for (int m = 0; m < materials; ++m) {
    t += fmt::format("[materials.m{}]\ndensity = {:.17g}\n", m, uniform(1000.0, 3000.0));
    for (const KeyRange& r : kRanges) {
      if (!keys.contains(r.key)) continue;
      double value = r.log ? r.low * std::pow(r.high / r.low, unit(rng)) : uniform(r.low, r.high);
      // Half the scenes without a tangential dashpot: YADE's laws have none.
      if (r.key == "tangential_damping_ratio" && unit(rng) < 0.5) value = 0.0;
      t += fmt::format("{} = {:.17g}\n", r.key, value);
    }
    t += "\n";
  }

  // Spheres in a chain of near-contacts: each placed at a random direction from an earlier one,
  // at r_i + r_j + s·min(r_i, r_j) with s in [−0.5 %, 2 %], and kept only if it overlaps no
  // other by more (the loader allows 1 % of the smaller radius).
  const int n = 2 + static_cast<int>(pick(5));
  std::vector<Sphere> spheres;
  spheres.push_back({uniform(0.5e-3, 1.5e-3), 0.0, 0.0, 0.0, static_cast<int>(pick(materials))});
  for (int attempt = 0; static_cast<int>(spheres.size()) < n && attempt < 1000; ++attempt) {
    const Sphere& near = spheres[pick(spheres.size())];
    const double r = uniform(0.5e-3, 1.5e-3);
    const double cz = uniform(-1.0, 1.0);
    const double phi = uniform(0.0, 2.0 * M_PI);
    const double sz = std::sqrt(1.0 - cz * cz);
    const double d = near.r + r + std::min(near.r, r) * uniform(-0.005, 0.02);
    const Sphere s{r, near.x + d * sz * std::cos(phi), near.y + d * sz * std::sin(phi), near.z + d * cz,
                   static_cast<int>(pick(materials))};
    const bool clear = std::all_of(spheres.begin(), spheres.end(), [&](const Sphere& o) {
      const double gap = std::sqrt((s.x - o.x) * (s.x - o.x) + (s.y - o.y) * (s.y - o.y) + (s.z - o.z) * (s.z - o.z));
      return gap >= s.r + o.r - 0.005 * std::min(s.r, o.r);
    });
    if (clear) spheres.push_back(s);
  }
  scene.spheres = static_cast<int>(spheres.size());

  // Walls: a floor under the lowest sphere and a side wall beyond the rightmost, each within
  // a few per cent of a radius of touching.
  scene.walls = static_cast<int>(pick(3));
  double lowest = spheres[0].z - spheres[0].r;
  double rightmost = spheres[0].x + spheres[0].r;
  double smallest = spheres[0].r;
  for (const Sphere& s : spheres) {
    lowest = std::min(lowest, s.z - s.r);
    rightmost = std::max(rightmost, s.x + s.r);
    smallest = std::min(smallest, s.r);
  }
  if (scene.walls >= 1) {
    t += fmt::format("[[walls]]\ntype = \"plane\"\nname = \"floor\"\npoint = {}\nnormal = [0.0, 0.0, 1.0]\nmaterial = \"m{}\"\n\n",
                     vec(0.0, 0.0, lowest - uniform(-0.005, 0.02) * smallest), pick(materials));
  }
  if (scene.walls >= 2) {
    t += fmt::format("[[walls]]\ntype = \"plane\"\nname = \"side\"\npoint = {}\nnormal = [-1.0, 0.0, 0.0]\nmaterial = \"m{}\"\n\n",
                     vec(rightmost + uniform(-0.005, 0.02) * smallest, 0.0, 0.0), pick(materials));
  }

  add_mesh(scene, t, code, mixed, spheres, materials);

  // Random velocities (±0.2 m/s a component) and spins; spheres 0 and 1 (the compared pair:
  // sphere 1 was placed next to sphere 0) also approach each other at 0.6 m/s along their line
  // of centres, so that the pair the trace deviation is scaled by does touch.
  const double lx = spheres[1].x - spheres[0].x;
  const double ly = spheres[1].y - spheres[0].y;
  const double lz = spheres[1].z - spheres[0].z;
  const double l = std::sqrt(lx * lx + ly * ly + lz * lz);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere& s = spheres[i];
    const double approach = i == 0 ? kFuzzApproach / l : (i == 1 ? -kFuzzApproach / l : 0.0);
    t += fmt::format("[[particles]]\nradius = {:.17g}\nmaterial = \"m{}\"\nposition = {}\nvelocity = {}\nangular_velocity = {}\n\n",
                     s.r, s.material, vec(s.x, s.y, s.z),
                     vec(uniform(-kFuzzSpeed, kFuzzSpeed) + approach * lx, uniform(-kFuzzSpeed, kFuzzSpeed) + approach * ly,
                         uniform(-kFuzzSpeed, kFuzzSpeed) + approach * lz),
                     vec(uniform(-200.0, 200.0), uniform(-200.0, 200.0), uniform(-200.0, 200.0)));
  }

  scene.gravity = unit(rng) < 0.5;
  if (scene.gravity) t += "[fields]\ngravity = [0.0, 0.0, -9.81]\n\n";
  t += fmt::format("[integration]\nscheme = \"velocity_verlet\"\ntimestep = \"auto\"\nduration = {}\nrotation = true\n\n",
                   kFuzzDuration);
  t += "[output]\ntrace_every = 5\n\n";
  t += fmt::format("[compare]\nengines = [\"{0}\"]\nmatched = [\"{0}\"]\nmetrics = []\npair = [0, 1]\n", code);
  scene.toml = std::move(t);
  scene.draws = k + 1;
  return scene;
}

}  // namespace

}  // namespace studies
