// SPDX-License-Identifier: MIT
#include "cases/case_loader.hpp"
#include "cases/core_wall.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cases/case_file.hpp"
#include "cases/excerpt.hpp"
#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/output_budget.hpp"
#include "cases/toml_reader.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"
#include "dem/neighbors/neighbor_list.hpp"
#include "support/sha256.hpp"

namespace cases {
namespace {

constexpr auto kTopLevelKeys =
    std::to_array<std::string_view>({"case", "model", "mixing", "materials", "pairs", "particles",
                                     "populations", "walls", "domain", "neighbors", "fields",
                                     "stages", "integration", "output", "compare"});

/// The parsed document; a TOML syntax error becomes a CaseError with key "(syntax)".
toml::table parse_document(std::string_view text, const std::string& path) {
  try {
    return toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw CaseError(path, "(syntax)", std::string(e.description()),
                    static_cast<int>(e.source().begin.line),
                    static_cast<int>(e.source().begin.column));
  }
}

/// The box of the scene's periodic axes, in the core's terms.
dem::PeriodicBox periodic_box(const Scene& scene) {
  dem::PeriodicBox box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = scene.domain.min[static_cast<std::size_t>(k)];
    box.hi[k] = scene.domain.max[static_cast<std::size_t>(k)];
    box.periodic[static_cast<std::size_t>(k)] = scene.domain.periodic[static_cast<std::size_t>(k)];
  }
  return box;
}

/// Throws when two particles' bodies overlap by more than kMaxInitialOverlap of the smaller
/// radius at the start (nearest periodic images); points at the later one's entry. Two fixed
/// particles never interact, so they may overlap (e.g. a wall built of spheres). Candidate pairs
/// come from the core's neighbour list, so large generated populations are checked in O(N).
void check_initial_overlaps(const loader::Table& root, const Scene& scene) {
  const auto& ps = scene.particles;
  std::vector<dem::PackedSphere> spheres;
  std::vector<std::uint8_t> still;
  std::vector<double> radius;
  const dem::PeriodicBox box = periodic_box(scene);
  for (const ParticleSpec& p : ps) {
    // Wrapped into the periodic box, as the list expects.
    dem::Vec3 x(p.position[0], p.position[1], p.position[2]);
    const auto image = box.image_of(x);
    for (int k = 0; k < 3; ++k) x[k] -= image[static_cast<std::size_t>(k)] * (box.hi[k] - box.lo[k]);
    spheres.push_back({x[0], x[1], x[2], p.radius});
    still.push_back(p.fixed ? 1 : 0);
    radius.push_back(p.radius);
  }
  const dem::SizeClasses classes = dem::size_classes(radius);
  dem::NeighborList list;
  list.build({spheres, still, classes.of, classes.max_half_reach, &box, 0.0, 1, false});
  std::size_t worst_j = ps.size();
  std::size_t worst_i = 0;
  double worst_overlap = 0.0;
  for (std::uint32_t a = 0; a < list.sphere_count(); ++a) {
    for (std::uint32_t k = list.begin(a); k < list.begin(a + 1); ++k) {
      const dem::PartnerCode partner = list.partners()[k];
      const std::uint32_t b = partner & dem::kPartnerMask;
      const dem::Vec3 shift = list.shift(partner >> dem::kPartnerBits);
      const dem::Vec3 d = dem::Vec3(spheres[a].x, spheres[a].y, spheres[a].z) -
                          (dem::Vec3(spheres[b].x, spheres[b].y, spheres[b].z) - shift);
      const double overlap = ps[a].radius + ps[b].radius - d.norm();
      if (overlap <= kMaxInitialOverlap * std::min(ps[a].radius, ps[b].radius)) continue;
      // Report the pair whose later particle comes first in the file, as a pairwise scan would.
      const std::size_t j = std::max(a, b);
      if (j < worst_j || (j == worst_j && std::min(a, b) < worst_i)) {
        worst_j = j;
        worst_i = std::min(a, b);
        worst_overlap = overlap;
      }
    }
  }
  if (worst_j == ps.size()) return;
  const double limit = kMaxInitialOverlap * std::min(ps[worst_i].radius, ps[worst_j].radius);
  loader::fail_at_particle(root, scene, worst_j,
                   fmt::format("particles {} and {} overlap by {:.6g} m at the start, more than 1% of the "
                               "smaller radius ({:.6g} m); move them apart",
                               worst_i, worst_j, worst_overlap, limit));
}

/// Throws when a mobile particle starts overlapping a wall by more than kMaxInitialOverlap of
/// its radius.
void check_wall_overlaps(const loader::Table& root, const Scene& scene) {
  // A wall placed after the preparation (in_preparation = false) never meets these positions.
  const auto hit = first_wall_overlap(scene, [](const WallSpec& w) { return w.in_preparation; }, kMaxInitialOverlap);
  if (!hit) return;
  loader::fail_at_particle(root, scene, hit->particle,
                           fmt::format("particle {} overlaps wall '{}' by {:.6g} m at the start, more than 1% "
                                       "of its radius; move it inside the domain",
                                       hit->particle, scene.walls[hit->wall].name, hit->overlap));
}

/// Throws when a sphere starts more than kMaxPeriodicImages box lengths from the periodic box
/// along a periodic axis (its image count would not fit the core's int).
void check_periodic_positions(const loader::Table& root, const Scene& scene) {
  constexpr std::array<std::string_view, 3> kAxes{"x", "y", "z"};
  for (std::size_t k = 0; k < 3; ++k) {
    if (!scene.domain.periodic[k]) continue;
    const double lo = scene.domain.min[k];
    const double length = scene.domain.max[k] - lo;
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
      const double images = std::floor((scene.particles[i].position[k] - lo) / length);
      if (std::fabs(images) <= kMaxPeriodicImages) continue;
      loader::fail_at_particle(root, scene, i,
                       fmt::format("particle {} starts {:.3g} box lengths from the periodic box along {}, more than "
                                   "the limit of {:g}; place it in the box",
                                   i, images, kAxes[k], kMaxPeriodicImages));
    }
  }
}

/// Throws when a periodic axis is shorter than twice the longest pair the core lists (largest
/// interaction reach plus skin): a pair would then meet more than one periodic image.
void check_periodic_length(const loader::Table& root, const Scene& scene, const dem::PairTable& table) {
  if (!scene.domain.any_periodic()) return;
  std::vector<bool> used(scene.materials.size(), false);
  for (const ParticleSpec& p : scene.particles) used[p.material] = true;
  double reach = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const ParticleSpec& p : scene.particles) {
    smallest = std::min(smallest, p.radius);
    reach = std::max(reach, 2.0 * p.radius);
    const dem::PairExtent self{2.0 * p.radius, 2.0 * p.effect_radius, 0.5 * p.radius};
    for (std::size_t b = 0; b < scene.materials.size(); ++b) {
      if (used[b]) reach = std::max(reach, dem::interaction_range(table.law(p.material, b), self));
    }
  }
  const double skin = scene.neighbors.skin.value_or(0.2 * smallest);
  constexpr std::array<std::string_view, 3> kAxes{"x", "y", "z"};
  for (std::size_t k = 0; k < 3; ++k) {
    if (!scene.domain.periodic[k]) continue;
    const double length = scene.domain.max[k] - scene.domain.min[k];
    if (length >= 2.0 * (reach + skin)) continue;
    root.require("domain").table().fail(
        "max", fmt::format("the periodic box is {:.6g} m long along {}, shorter than twice the longest listed pair "
                           "distance {:.6g} m (interaction reach {:.6g} m + skin {:.6g} m): a pair would meet "
                           "more than one periodic image",
                           length, kAxes[k], reach + skin, reach, skin));
  }
}

/// The pair table the core would build; a dem::ModelError becomes a CaseError pointing at
/// [materials] (missing or invalid property) or at the [model] key it names.
dem::PairTable build_pair_table(const loader::Table& root, const Scene& scene) {
  try {
    return dem::PairTable(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  } catch (const dem::ModelError& e) {
    const std::string& key = e.key();
    constexpr std::string_view kModelPrefix = "model.";
    if (dem::find_property_spec(key) != nullptr) root.fail("materials", e.what());
    if (key.starts_with(kModelPrefix) && root.has("model")) {
      root.require("model").table().fail(key.substr(kModelPrefix.size()), e.what());
    }
    root.fail(key, e.what());
  }
}

/// Warns when rotation is off although some particle starts spinning.
void warn_held_spin(const loader::Table& root, const Scene& scene) {
  if (scene.integration.rotation) return;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const Vector3& w = scene.particles[i].angular_velocity;
    if (w[0] != 0.0 || w[1] != 0.0 || w[2] != 0.0) {
      root.require("integration")
          .table()
          .warn("rotation", fmt::format("rotation is off but particles[{}].angular_velocity is "
                                        "nonzero; every spin stays at its initial value",
                                        i));
      return;
    }
  }
}

}  // namespace

CaseError::CaseError(std::string file, std::string key, std::string problem, int line, int column)
    : std::runtime_error(loader::located_message(file, key, problem, line, column)),
      file_(std::move(file)),
      key_(excerpt(key, kMaxEchoedKey)),
      problem_(excerpt(problem, kMaxEchoedProblem)) {}

namespace loader {

Value origin_entry(const Table& root, const Scene& scene, std::size_t i, std::string& note) {
  const std::size_t explicit_count = scene.population_first.empty() ? scene.particles.size() : scene.population_first.front();
  if (i < explicit_count) return root.require("particles").elements()[i];
  std::size_t k = 0;
  while (k + 1 < scene.population_first.size() && scene.population_first[k + 1] <= i) ++k;
  note = fmt::format(" (particle {} was generated by populations[{}])", i, k);
  return root.require("populations").elements()[k];
}

void fail_at_particle(const Table& root, const Scene& scene, std::size_t i, const std::string& problem,
                      std::string_view listed_key, std::string_view generated_key) {
  std::string note;
  const Value entry = origin_entry(root, scene, i, note);
  if (!listed_key.empty()) entry.table().fail(std::string(note.empty() ? listed_key : generated_key), problem + note);
  const std::string key = entry.key().substr(0, entry.key().find('['));
  throw CaseError(scene.source_path, key, problem + note, static_cast<int>(entry.where().begin.line),
                  static_cast<int>(entry.where().begin.column));
}

void check_scene(const Table& root, const Scene& scene) {
  check_sphere_masses(root, scene);
  check_periodic_positions(root, scene);
  check_initial_overlaps(root, scene);
  // A launch stage places the spheres itself (clear of its wall); until then they may be anywhere.
  const bool launched = std::any_of(scene.stages.begin(), scene.stages.end(), [](const StageSpec& st) {
    return std::holds_alternative<LaunchStageSpec>(st.action);
  });
  if (!launched) check_wall_overlaps(root, scene);
  const dem::PairTable table = build_pair_table(root, scene);
  check_periodic_length(root, scene, table);
  check_time_scales(root, scene, table);
  warn_held_spin(root, scene);
}

}  // namespace loader

Scene load_case(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string text = read_case_file(path);
  return load_case_text(text, path.string(), options);
}

Scene load_case_text(std::string_view text, const std::string& path, const LoadOptions& options) {
  if (text.size() > kMaxCaseFileBytes) {
    throw CaseError(path, "(file)", fmt::format("the case text is {} bytes, more than the limit of {} bytes for a "
                                                "case file",
                                                text.size(), kMaxCaseFileBytes));
  }
  const toml::table document = parse_document(text, path);
  loader::Diagnostics diagnostics(path);
  const loader::Table root(document, "", diagnostics);
  root.allow_only(kTopLevelKeys);

  Scene scene;
  scene.source_path = path;
  scene.source_text = std::string(text);
  scene.source_sha256 = support::sha256_hex(text);
  loader::read_case_section(root, scene);
  loader::read_model(root, scene);
  loader::read_mixing(root, scene);
  loader::read_materials(root, scene);
  loader::read_pairs(root, scene);
  loader::read_walls(root, scene);  // before the particles: a velocity may be aimed at a wall
  loader::read_particles(root, scene);
  loader::read_populations(root, scene);
  if (scene.particles.empty()) {
    throw CaseError(path, "particles", "the case has no particles: list [[particles]] or generate [[populations]]");
  }
  loader::apply_rigid_walls(scene);
  loader::read_domain(root, scene);
  loader::read_neighbors(root, scene);
  loader::read_fields(root, scene);
  loader::read_stages(root, scene);
  loader::read_integration(root, scene);
  loader::read_compare(root, scene);
  loader::read_output(root, scene);
  loader::check_scene(root, scene);
  check_output_budget(scene, options.max_output_bytes.value_or(physical_memory_bytes()), path);
  scene.warnings = diagnostics.warnings();
  return scene;
}

}  // namespace cases
