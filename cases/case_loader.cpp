// SPDX-License-Identifier: MIT
#include "cases/case_loader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cases/loader_sections.hpp"
#include "cases/toml_reader.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace cases {
namespace {

constexpr auto kTopLevelKeys =
    std::to_array<std::string_view>({"case", "model", "mixing", "materials", "pairs", "particles",
                                     "walls", "fields", "integration", "output", "compare"});

/// Largest initial body overlap allowed, as a fraction of the smaller radius.
constexpr double kMaxInitialOverlap = 0.01;

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

/// Throws when two particles' bodies overlap by more than kMaxInitialOverlap of the smaller
/// radius at the start; points at the later of the two [[particles]] entries. Two fixed
/// particles never interact, so they may overlap (e.g. a wall built of spheres).
void check_initial_overlaps(const loader::Table& root, const Scene& scene) {
  const auto& ps = scene.particles;
  for (std::size_t j = 1; j < ps.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (ps[i].fixed && ps[j].fixed) continue;
      const double dx = ps[i].position[0] - ps[j].position[0];
      const double dy = ps[i].position[1] - ps[j].position[1];
      const double dz = ps[i].position[2] - ps[j].position[2];
      const double overlap = ps[i].radius + ps[j].radius - std::sqrt(dx * dx + dy * dy + dz * dz);
      const double limit = kMaxInitialOverlap * std::min(ps[i].radius, ps[j].radius);
      if (overlap <= limit) continue;
      const loader::Value entry = root.require("particles").elements()[j];
      throw CaseError(scene.source_path, "particles",
                      fmt::format("particles {} and {} overlap by {:.6g} m at the start, more "
                                  "than 1% of the smaller radius ({:.6g} m); move them apart",
                                  i, j, overlap, limit),
                      static_cast<int>(entry.where().begin.line),
                      static_cast<int>(entry.where().begin.column));
    }
  }
}

/// Throws when a mobile particle starts overlapping a wall by more than kMaxInitialOverlap of
/// its radius.
void check_wall_overlaps(const loader::Table& root, const Scene& scene) {
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      const WallSpec& wall = scene.walls[w];
      double distance = 0.0;
      for (std::size_t k = 0; k < 3; ++k) distance += (p.position[k] - wall.point[k]) * wall.normal[k];
      const double overlap = p.radius - distance;
      if (overlap <= kMaxInitialOverlap * p.radius) continue;
      const loader::Value entry = root.require("particles").elements()[i];
      throw CaseError(scene.source_path, "particles",
                      fmt::format("particle {} overlaps wall '{}' by {:.6g} m at the start, more than "
                                  "1% of its radius; move it inside the domain",
                                  i, wall.name, overlap),
                      static_cast<int>(entry.where().begin.line),
                      static_cast<int>(entry.where().begin.column));
    }
  }
}

/// Builds the pair table the core would build; a dem::ModelError becomes a CaseError pointing
/// at [materials] (missing or invalid property) or at the [model] key it names.
void check_model_buildable(const loader::Table& root, const Scene& scene) {
  try {
    const dem::PairTable table(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
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
      key_(std::move(key)),
      problem_(std::move(problem)) {}

namespace loader {

void check_scene(const Table& root, const Scene& scene) {
  check_initial_overlaps(root, scene);
  check_wall_overlaps(root, scene);
  check_model_buildable(root, scene);
  warn_held_spin(root, scene);
}

}  // namespace loader

Scene load_case(const std::filesystem::path& path) {
  std::string text;
  try {
    text = support::read_file(path);
  } catch (const std::runtime_error& e) {
    throw CaseError(path.string(), "(file)", e.what());
  }
  return load_case_text(text, path.string());
}

Scene load_case_text(std::string_view text, const std::string& path) {
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
  loader::read_particles(root, scene);
  loader::read_walls(root, scene);
  loader::read_fields(root, scene);
  loader::read_integration(root, scene);
  loader::read_compare(root, scene);
  loader::read_output(root, scene);
  loader::check_scene(root, scene);
  scene.warnings = diagnostics.warnings();
  return scene;
}

}  // namespace cases
