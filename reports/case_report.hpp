// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>

#include "compare/case_outcome.hpp"

namespace reports {

/// Writes the case's plots into `plot_dir` and returns its markdown section: purpose, model and
/// mixed pair table, engine runs, metrics, discrepancies, plots, conventions, warnings.
/// Links are relative to `report_dir`; headings start at `level` (2 → "##").
std::string case_section(const comparison::CaseOutcome& outcome,
                         const std::filesystem::path& plot_dir,
                         const std::filesystem::path& report_dir, int level);

/// A reference code's verdict on a case that does not list it: "n/a" or "expresses it".
std::string unlisted_verdict(const comparison::UnlistedCode& code);

/// Discrepancy table of one case (one row per comparison).
std::string discrepancy_table(const comparison::CaseOutcome& outcome);

}  // namespace reports
