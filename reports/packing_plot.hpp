// SPDX-License-Identifier: MIT
#pragma once
// The packed bed over a run (docs/metrics.md, "Fluidisation"): its ORF and dose remaining at every
// snapshot, as a CSV per engine and as the report's fluidisation plot (thesis figs 6.5 and 6.8).

#include <optional>
#include <string>
#include <vector>

#include "compare/case_outcome.hpp"
#include "compare/packing_series.hpp"
#include "reports/gnuplot.hpp"

namespace reports {

/// CSV of a packing series: time, orf, dose_remaining, one row per snapshot (17 significant digits).
std::string packing_series_csv(const std::vector<comparison::PackingSample>& samples);

/// The ORF and dose remaining of every engine that ran against time, with the plug flow's speed as
/// a share of its plateau when the case has one; empty when the case has no packing region or no
/// run has two snapshots.
std::optional<Plot> fluidisation_plot(const comparison::CaseOutcome& outcome);

}  // namespace reports
