// SPDX-License-Identifier: MIT
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "compare/case_outcome.hpp"

namespace reports {

/// The results.json document of one case (schema in docs/results-format.md): case name and
/// hash, one entry per engine (status, version, wall time, metrics, reason, warnings,
/// conventions) and one row per comparison. Values are finite numbers or null, never NaN.
nlohmann::ordered_json results_json(const comparison::CaseOutcome& outcome, bool wall_times = true);

}  // namespace reports
