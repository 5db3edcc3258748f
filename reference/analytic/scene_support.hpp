// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference::analytic {

/// Why the closed forms cannot express `scene`, one human-readable reason per violated
/// condition (empty when they can): linear normal law with no or restitution damping (eq
/// 3.10–3.11), no tangential/cohesion/rolling model, zero gravity, and either one mobile sphere
/// whose fixed partners lie on its line of motion, or two mobile spheres colliding head-on.
std::vector<std::string> unsupported_reasons(const PreparedScene& prepared);

}  // namespace reference::analytic
