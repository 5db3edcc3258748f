// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace comparison {

/// Verdict on one (case, engine, metric) comparison (docs/metrics.md, "Statuses").
enum class Status {
  pass,            ///< within tolerance
  fail,            ///< outside tolerance
  error,           ///< engine crashed, timed out, produced NaN, or the metric could not be computed
  missing,         ///< engine not installed
  not_applicable,  ///< engine cannot express the case (reason given)
};

/// Name used in tables and results.json: "pass", "fail", "error", "missing", "n/a".
std::string_view to_string(Status status) noexcept;
/// Status named `name`, or empty.
std::optional<Status> parse_status(std::string_view name) noexcept;
/// Only pass and n/a are green.
[[nodiscard]] constexpr bool is_green(Status status) noexcept {
  return status == Status::pass || status == Status::not_applicable;
}

}  // namespace comparison
