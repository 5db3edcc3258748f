// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/case_outcome.hpp"
#include "reference/engine.hpp"

namespace app {

/// Runs `scene` on each named engine (in order) and evaluates metrics and comparisons.
/// Unknown engine names must have been rejected by the caller.
comparison::CaseOutcome run_case(const cases::Scene& scene, const std::vector<std::string>& engines,
                                 const reference::RunOptions& options);

}  // namespace app
