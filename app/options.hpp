// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "app/case_runner.hpp"
#include "cases/case_loader.hpp"

namespace app {

/// Adds the options every running command shares: --timeout, --cache, --no-cache, --baselines,
/// --match, --threads, --reproducible, and the binaries (add_program_options).
void add_run_options(boost::program_options::options_description& opts);

/// The case-loading limits of --max-memory: the most bytes of output (traces, energy ledger,
/// snapshots) one run of a case may hold; default half the machine's physical memory.
cases::LoadOptions load_options(const boost::program_options::variables_map& vm);

/// The value of --timeout, checked: seconds in (0, 1e7].
double timeout_option(const boost::program_options::variables_map& vm);

/// The run options of `vm` that a command passes on to the one it starts (gate → suite, suite and
/// refresh → sweep): --timeout, --threads, and --no-cache, --cache, --lammps, --yade, --liggghts
/// when given.
std::vector<std::string> forwarded_run_options(const boost::program_options::variables_map& vm);

/// Arguments of `demwb sweep` for running `sweep_file` into `out` with `jobs` runs at once and
/// the run options of `vm` that a sweep shares (--timeout, --threads, --cache, --no-cache,
/// --lammps, --yade, --liggghts): how suite (full tier) and refresh --sweep start a sweep.
std::vector<std::string> sweep_arguments(const std::filesystem::path& sweep_file, const std::filesystem::path& out,
                                         unsigned jobs, const boost::program_options::variables_map& vm);

/// Adds --tier fast|full (suite and gate; docs/user-guide.md, "Tiers").
void add_tier_option(boost::program_options::options_description& opts);
/// The value of --tier, checked: `fast` (the default) or `full`.
cases::Tier tier_option(const boost::program_options::variables_map& vm);

/// Adds --lammps PATH, --yade PATH and --liggghts PATH (the reference binaries to drive).
void add_program_options(boost::program_options::options_description& opts);

/// The reference binaries: --lammps / --yade / --liggghts, else $DEMWB_LAMMPS / $DEMWB_YADE /
/// $DEMWB_LIGGGHTS, else `lmp`, `yade` and `liggghts` in PATH. The version probe may take min(10 s, `timeout_s`).
reference::ExternalPrograms external_programs(const boost::program_options::variables_map& vm, double timeout_s);

/// `scene` with the reference codes of --match added to compare.matched (engines_to_run then adds
/// each code and its matched engine to the engines run), or with none under --no-match.
cases::Scene with_matches(cases::Scene scene, const boost::program_options::variables_map& vm);
/// What suite and gate print under --no-match, so that a green result is not read as covering
/// the matched comparisons.
inline constexpr const char* kNoMatchNote =
    "note: --no-match: the cases' matched runs and their comparisons were left out\n";
/// Throws when --match or --no-match is given to `command`, which runs the engines its own files
/// name (a sweep's, a baseline's) and would otherwise ignore them.
void refuse_matches(const boost::program_options::variables_map& vm, std::string_view command);

/// The run context those options describe; `work_dir` holds the engines' scratch files.
RunContext run_context(const boost::program_options::variables_map& vm,
                       const std::filesystem::path& work_dir);

/// Parses `args` against `visible` options plus positional arguments named in `positional`
/// (in order; a name ending in '?' is optional and stored without the '?'). Prints help for -h/--help and returns
/// empty in that case. Throws boost::program_options::error on bad usage.
std::optional<boost::program_options::variables_map> parse_command(
    const std::vector<std::string>& args, const std::string& usage,
    const boost::program_options::options_description& visible,
    const std::vector<std::string>& positional);

}  // namespace app
