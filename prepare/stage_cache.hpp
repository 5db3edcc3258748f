// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace prepare {

/// A stage's stored result: the explicit particles it produced and its figures.
struct StoredStage {
  std::vector<cases::ParticleSpec> particles;
  std::vector<std::pair<std::string, double>> figures;
};

/// The stored result under `key` in `dir`, if there is one that reads back whole and matches the
/// particle count expected; anything else is treated as absent.
std::optional<StoredStage> find_stage(const std::filesystem::path& dir, const std::string& key,
                                      std::size_t particle_count);

/// Stores a stage's result under `key` (positions, velocities and spins at full precision,
/// written to a temporary file and renamed, so a reader never sees half a file). Throws
/// std::runtime_error naming the file on I/O failure.
void store_stage(const std::filesystem::path& dir, const std::string& key, const StoredStage& stage);

}  // namespace prepare
