// SPDX-License-Identifier: MIT
#include "reference/common/engine.hpp"

#include <chrono>
#include <cmath>
#include <exception>

#include <fmt/format.h>

#include "support/utf8.hpp"

namespace reference {

std::string Support::explain() const {
  std::string out;
  for (const auto& r : reasons) {
    if (!out.empty()) out += "; ";
    out += r;
  }
  return out;
}


cases::RunResult error_result(std::string reason, std::string log_tail) {
  cases::RunResult r;
  r.status = cases::RunStatus::error;
  r.reason = std::move(reason);
  r.log_tail = std::move(log_tail);
  return r;
}

cases::RunResult run_engine(const Engine& engine, const cases::Scene& scene, const RunOptions& options) {
  return run_engine(engine, PreparedScene(scene), options);
}

cases::RunResult run_engine(const Engine& engine, const PreparedScene& prepared, const RunOptions& options) {
  cases::RunResult result;
  result.engine = std::string(engine.name());
  const auto version = engine.version();
  if (!version) {
    result.status = cases::RunStatus::missing;
    result.reason = fmt::format("engine '{}' is not installed: {}", engine.name(), engine.location());
    return result;
  }
  const Support support = engine.supports(prepared);
  if (!support.supported()) {
    result.version = *version;
    result.status = cases::RunStatus::not_applicable;
    result.reason = support.explain();
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    result = engine.run(prepared, options);
  } catch (const std::exception& e) {
    result = cases::RunResult{};
    result.status = cases::RunStatus::error;
    result.reason = e.what();
  }
  result.engine = std::string(engine.name());
  result.version = *version;  // drivers clean what a binary printed (probe_lammps, detect_yade_version)
  // What an external program wrote may be any bytes: keep it valid, printable UTF-8 so that it
  // can reach results.json, report.md and the terminal (versions are cleaned where they are read).
  result.reason = support::printable_utf8(result.reason);
  result.log_tail = support::printable_utf8(result.log_tail);
  for (auto& w : result.warnings) w = support::printable_utf8(w);
  for (auto& [key, value] : result.conventions) value = support::printable_utf8(value);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.status == cases::RunStatus::ok) {
    if (const std::string bad = cases::first_non_finite(result.trace); !bad.empty()) {
      result.status = cases::RunStatus::error;
      result.reason = "non-finite value in trace: " + bad;
    }
  }
  return result;
}

}  // namespace reference
