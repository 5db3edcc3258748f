// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>

#include "compare/case_outcome.hpp"

namespace reports {

/// Writes everything one case produced into `dir`: results.json, trace_<engine>.csv per engine
/// that ran, snapshots/<engine>_<k>.vtk for each requested snapshot, the exact case file used
/// (case.toml), the command that reproduces the run (command.txt), and report.md with its plots
/// under plots/. Without `wall_times`, results.json leaves out the machine-dependent fields
/// (wall_time_s and the engines' scratch directories), so that two runs of the same case can be
/// compared byte for byte.
void write_case_outputs(const comparison::CaseOutcome& outcome, const std::filesystem::path& dir,
                        const std::string& command, bool wall_times = true);

/// A shell command line that reproduces this invocation: cd to the working directory, then argv
/// with each argument quoted where needed.
std::string reproduce_command(int argc, const char* const* argv);

}  // namespace reports
