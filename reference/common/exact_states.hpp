// SPDX-License-Identifier: MIT
#pragma once
// The slot through which the in-house engine obtains exact past states for a multi-step scheme's
// start-up (thesis §4.2.2) without depending on the engine that computes them: the registry fills
// it with the closed forms (docs/architecture.md, "Layers").

#include <functional>
#include <vector>

#include "cases/run_result.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference {

/// Exact states of every particle of a prepared scene at the given times (negative times: the motion
/// continued backwards). Throws std::invalid_argument with the reasons when the scene has no
/// exact solution.
using ExactStates =
    std::function<std::vector<cases::Snapshot>(const PreparedScene& prepared, const std::vector<double>& times)>;

}  // namespace reference
