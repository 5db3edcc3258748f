// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace reference::yade {

/// Scene features outside the contact model that the YADE driver cannot express yet, one
/// human-readable reason each (phase 1: spheres, fixed spheres and uniform gravity only).
std::vector<std::string> unsupported_scene_features(const cases::Scene& scene);

/// Requested outputs the driver does not produce, as warnings (the run is still meaningful).
std::vector<std::string> unproduced_outputs(const cases::Scene& scene);

}  // namespace reference::yade
