// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/trace.hpp"

namespace reference::yade {

/// YADE's output files do not have the expected form; the message names the file and line.
class YadeOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses a trace CSV written by the generated script: a header line of column names, then one
/// line of numbers per row ('%.17g'; nan/inf accepted and left for the caller to judge).
/// `file` names the file in messages. Pure; throws YadeOutputError.
cases::Trace parse_trace_csv(std::string_view text, std::string_view file);

/// Parses the snapshot CSV: header "time,particle,x,y,z,vx,vy,vz,wx,wy,wz", then for each
/// snapshot one line per particle 0 … particle_count − 1 in order. Pure; throws YadeOutputError.
std::vector<cases::Snapshot> parse_snapshot_csv(std::string_view text, std::string_view file,
                                                std::size_t particle_count);

}  // namespace reference::yade
