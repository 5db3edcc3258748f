// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "cases/run_result.hpp"
#include "reports/gnuplot.hpp"

namespace reports {

/// The curves of one run's energy ledger for the report's energy plot: one per ledger term that
/// is not zero throughout the run (a case without a fluid draws no fluid work). The first run
/// drawn (`first`) titles them by term, later runs by "term (engine)" with dashed lines, so that
/// an in-house run and its matched variants stay apart.
std::vector<Series> energy_series(const cases::RunResult& run, bool first);

}  // namespace reports
