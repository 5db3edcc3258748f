// SPDX-License-Identifier: MIT
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "cases/run_result.hpp"

namespace store {

/// A RunResult as JSON, losslessly: status, reason, version, wall time, log tail, conventions,
/// warnings, exact metrics, traces (column-major) and snapshots. Doubles round-trip exactly.
nlohmann::ordered_json run_result_json(const cases::RunResult& run);

/// The RunResult a run_result_json document describes; throws std::runtime_error naming the
/// missing or malformed field.
cases::RunResult run_result_from_json(const nlohmann::ordered_json& j);

}  // namespace store
