// SPDX-License-Identifier: MIT
#include "reference/liggghts/liggghts_runner.hpp"

#include <cstring>

#include <fmt/format.h>

#include "reference/common/banner_probe.hpp"
#include "reference/common/log_lines.hpp"
#include "reference/common/run_directory.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"
#include "support/text_tokens.hpp"

namespace reference::liggghts {
namespace {

constexpr std::size_t kLogTailLines = 30;
constexpr std::size_t kScreenTailLines = 10;

/// The last lines of the log, the screen and stderr, each under a title.
std::string tail_of(const std::filesystem::path& dir) {
  std::string out;
  const std::string log = support::file_tail(dir / kLogFile, kLogTailLines);
  out += log.empty() ? fmt::format("({} is empty or missing)\n", kLogFile)
                     : fmt::format("{} (last {} lines):\n{}", kLogFile, kLogTailLines, log);
  for (const char* file : {kScreenFile, kStderrFile}) {
    const std::string text = support::file_tail(dir / file, kScreenTailLines);
    if (!text.empty()) out += fmt::format("{} (last {} lines):\n{}", file, kScreenTailLines, text);
  }
  return out;
}

}  // namespace

std::optional<std::string> banner_version(std::string_view log_text) {
  constexpr std::string_view kBanner = "LIGGGHTS (Version ";
  for (const std::string_view line : support::split_lines(log_text)) {
    if (line.substr(0, kBanner.size()) != kBanner) continue;
    const std::string_view rest = line.substr(kBanner.size());
    const auto end = rest.find_first_of(",)");
    if (end == 0 || end == std::string_view::npos) continue;
    return std::string(rest.substr(0, end));
  }
  return std::nullopt;
}

std::filesystem::path make_run_directory(const std::filesystem::path& parent) {
  return reference::make_run_directory(parent, "liggghts");
}

LiggghtsProbe probe_liggghts(const std::string& program, double timeout_s) {
  return probe_banner(program, timeout_s, "LIGGGHTS", &banner_version);
}

LiggghtsRunOutcome run_liggghts(const std::string& program, const std::filesystem::path& dir, double timeout_s) {
  support::ProcessSpec spec;
  spec.argv = {program, "-in", kDeckFile, "-log", kLogFile};
  if (const auto stdbuf = support::find_program("stdbuf")) {
    spec.argv.insert(spec.argv.begin(), {stdbuf->string(), "-o0", "-e0"});
  }
  spec.working_directory = dir;
  spec.stdout_file = dir / kScreenFile;
  spec.stderr_file = dir / kStderrFile;
  spec.environment = mpi_singleton_environment(dir);
  spec.timeout_s = timeout_s;
  const support::ProcessResult r = support::run_process(spec);

  LiggghtsRunOutcome out;
  const std::string log = support::read_file_or_empty(dir / kLogFile);
  out.log_tail = tail_of(dir);
  out.warnings = warning_lines(log);
  out.version = banner_version(log);
  // Errors raised on one process reach the screen only.
  std::string error = first_error(log);
  if (error.empty()) error = first_error(support::read_file_or_empty(dir / kScreenFile));
  const std::string detail = error.empty() ? "" : ": " + error;
  if (!r.started) {
    out.reason = fmt::format("LIGGGHTS could not be started: {}", r.error);
  } else if (r.timed_out) {
    out.reason = fmt::format("LIGGGHTS timed out after {:.3g} s and was killed", timeout_s);
  } else if (r.signal) {
    out.reason = fmt::format("LIGGGHTS was killed by signal {} ({}){}", *r.signal, strsignal(*r.signal), detail);
  } else if (r.exit_code != 0) {
    out.reason = fmt::format("LIGGGHTS exited with status {}{}", r.exit_code,
                             error.empty() ? " and no ERROR line in its log or screen" : detail);
  } else if (!error.empty()) {
    out.reason = "LIGGGHTS exited normally after an error" + detail;
  } else {
    out.ok = true;
  }
  return out;
}

}  // namespace reference::liggghts
