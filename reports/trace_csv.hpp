// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "cases/trace.hpp"

namespace reports {

/// The trace as CSV: a header of column names, then one row per sample with every value at
/// full precision (%.17g), so a reader recovers the doubles exactly.
std::string trace_csv(const cases::Trace& trace);

}  // namespace reports
