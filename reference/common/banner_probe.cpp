// SPDX-License-Identifier: MIT
#include "reference/common/banner_probe.hpp"

#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "reference/common/run_directory.hpp"
#include "support/interrupts.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"
#include "support/utf8.hpp"

namespace reference {

BannerProbe probe_banner(const std::string& program, double timeout_s, std::string_view code, BannerReader read) {
  BannerProbe probe;
  if (!support::find_program(program)) return probe;
  std::filesystem::path dir;
  try {
    dir = make_run_directory({}, "probe");
  } catch (const std::exception& e) {
    probe.version = fmt::format("{} (version unknown: {})", code, e.what());
    return probe;
  }
  const support::OwnedPathGuard partial(dir);
  const std::filesystem::path log = dir / "log.probe";
  support::ProcessSpec spec;
  spec.argv = {program, "-in", "/dev/null", "-log", log.string(), "-screen", "none"};
  spec.environment = mpi_singleton_environment(dir);
  spec.timeout_s = timeout_s;
  const support::ProcessResult r = support::run_process(spec);
  probe.seconds = r.wall_time_s;
  probe.timed_out = r.timed_out;
  const std::optional<std::string> banner = read(support::read_file_or_empty(log));
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  if (r.timed_out) {
    probe.version = fmt::format("{} (version unknown: {} did not finish an empty run within {:.3g} s)", code, program,
                                timeout_s);
  } else if (banner) {
    probe.version = support::printable_utf8(*banner);
  } else if (!r.started) {
    probe.version = fmt::format("{} (version unknown: {})", code, r.error);
  } else {
    probe.version = fmt::format("{} (version unknown: {} wrote no banner, exit status {})", code, program, r.exit_code);
  }
  return probe;
}

}  // namespace reference
