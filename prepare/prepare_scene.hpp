// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "cases/scene.hpp"

namespace prepare {

/// How preparation runs.
struct PrepareOptions {
  int threads = 1;  ///< the core's threads (results do not depend on it)
  /// Directory of formed particle lists keyed by their inputs; none: always run the stages.
  std::optional<std::filesystem::path> cache_dir;
  /// Revision of the core's sources, part of every cache key, so that a changed core forms its
  /// agglomerates afresh.
  std::string core_revision;
  bool refresh = false;  ///< run the stages even on a cache hit (and store the result)
};

/// The scene every engine receives: `scene` with its [[stages]] run in order in the core
/// (formation, thesis §5.2.1; launch, §5.2.2), its particles replaced by the explicit result,
/// integration.duration set by the launch when the case says "launch" (eq 5.1), and a snapshot
/// at the end added when a breakup metric is listed. What each stage did goes to stage_log.
/// A scene without stages comes back unchanged. Throws cases::CaseError naming the stage's key
/// when a stage fails (the spheres never settle, a launched sphere starts inside a wall).
cases::Scene prepare_scene(const cases::Scene& scene, const PrepareOptions& options);

/// The cache key of stage `index` of `scene` when the particles are as in `scene`: SHA-256 of
/// the scene's physical description with that stage alone, and the core revision.
std::string stage_key(const cases::Scene& scene, std::size_t index, const std::string& core_revision);

}  // namespace prepare
