// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "cases/scene.hpp"

namespace store {

/// Everything physical about a scene as canonical JSON (materials, mixing, pair overrides,
/// model and policies, particles, walls, fields, integration, output), in a fixed key order and
/// with doubles at full precision. Name, description and source file are left out: two case
/// files that describe the same scene have the same JSON.
nlohmann::ordered_json scene_json(const cases::Scene& scene);

/// SHA-256 (hex) of scene_json: the identity of a scene for the reference-result cache.
std::string scene_fingerprint(const cases::Scene& scene);

}  // namespace store
