// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

namespace app {

/// Parses `args` against `visible` options plus positional arguments named in `positional`
/// (in order; the last may repeat when `last_repeats`). Prints help for -h/--help and returns
/// empty in that case. Throws boost::program_options::error on bad usage.
std::optional<boost::program_options::variables_map> parse_command(
    const std::vector<std::string>& args, const std::string& usage,
    const boost::program_options::options_description& visible,
    const std::vector<std::string>& positional);

}  // namespace app
