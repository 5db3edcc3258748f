// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace app {

/// Exit codes of demwb.
enum ExitCode : int {
  kExitOk = 0,        ///< everything green
  kExitFailed = 1,    ///< a comparison failed or an engine errored
  kExitUsage = 2,     ///< bad command line or bad case file
};

/// The whole command line, for the reproduce command written into output directories.
struct Invocation {
  int argc;
  const char* const* argv;
};

/// `demwb run`.
int command_run(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb sweep`.
int command_sweep(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb compare`.
int command_compare(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb suite`.
int command_suite(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb study`.
int command_study(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb gate`.
int command_gate(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb refresh`.
int command_refresh(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb engines`.
int command_engines(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb bench`: the core against LAMMPS on one scene, speed and memory.
int command_bench(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb fuzz-matched`: random scenes on a reference code and its matched core.
int command_fuzz_matched(const std::vector<std::string>& args, const Invocation& inv);
/// `demwb convert`: thesis appendix E parameter conversion.
int command_convert(const std::vector<std::string>& args, const Invocation& inv);

/// Splits "a,b" and repeated values into one list of names.
std::vector<std::string> split_names(const std::vector<std::string>& values);

}  // namespace app
