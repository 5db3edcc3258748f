// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace support {

/// How to run a child process.
struct ProcessSpec {
  std::vector<std::string> argv;                 ///< program (searched in PATH) and arguments
  std::filesystem::path working_directory;       ///< empty: inherit
  std::filesystem::path stdout_file;             ///< empty: /dev/null; relative to the caller
  std::filesystem::path stderr_file;             ///< empty: /dev/null
  std::map<std::string, std::string> environment;  ///< added to (or replacing in) the parent's
  double timeout_s = 0.0;                        ///< > 0: kill the process group after this
};

/// How a child process ended.
struct ProcessResult {
  bool started = false;      ///< false when the program could not be executed
  int exit_code = -1;        ///< valid when exited normally
  std::optional<int> signal; ///< set when killed by a signal
  bool timed_out = false;
  double wall_time_s = 0.0;
  std::string error;         ///< why it did not start, if it did not
};

/// Runs a child in its own process group and waits for it (or the timeout). Inside an MPI job the
/// child does not inherit the launcher's rank variables (OMPI_*, PMIX_*, PMI_*): it is not a rank.
ProcessResult run_process(const ProcessSpec& spec);

/// Full path of `program` found in PATH, or empty.
std::optional<std::filesystem::path> find_program(const std::string& program);

/// Last `max_lines` lines of a text file ("" if it cannot be read).
std::string file_tail(const std::filesystem::path& path, std::size_t max_lines);

}  // namespace support
