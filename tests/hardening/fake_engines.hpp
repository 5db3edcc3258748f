// SPDX-License-Identifier: MIT
#pragma once
// Stand-ins for the reference binaries, for the hardening tests: shell scripts that misbehave in
// one chosen way (fail, hang, write garbage, NaN or a truncated trace) and otherwise hand over to
// the real LAMMPS or YADE, so that everything around the fault is genuine.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "support/process.hpp"
#include "support/text_file.hpp"

namespace demwb_hardening {

namespace fs = std::filesystem;

/// How a fake binary misbehaves.
enum class Fault {
  exit_1,       ///< fails with status 1 (and an ERROR line for LAMMPS)
  hang,         ///< never finishes the run (writes its pid to `pid_file` first)
  hang_probe,   ///< LAMMPS only: never finishes even the version probe
  garbage,      ///< runs for real, then replaces the trace with bytes that are not a trace
  nan,          ///< runs for real, then writes "nan" into the trace's last row
  truncated,    ///< runs for real, then cuts the trace in half mid-line
};

/// The shell lines that damage `trace` after a real run, for the faults that do.
inline std::string damage(Fault fault, const std::string& trace) {
  switch (fault) {
    case Fault::garbage:
      return fmt::format("head -c 4096 /dev/urandom > {0}; printf 'not,a\\ttrace\\x00\\n' >> {0}\n", trace);
    case Fault::nan:  // the first position column of the last row (third field: after step/time or time, x)
      return fmt::format("awk -v FS='{0}' -v OFS='{0}' 'NR > 1 {{ print prev }} {{ prev = $0 }} END {{ $0 = prev; ${1} = \"nan\"; print }}' {2} > {2}.new && mv {2}.new {2}\n",
                         trace.ends_with(".csv") ? "," : " ", trace.ends_with(".csv") ? 2 : 3, trace);
    case Fault::truncated:
      return fmt::format("size=$(stat -c %s {0}); truncate -s $((size / 2 + 3)) {0}\n", trace);
    default:
      return "";
  }
}

/// True when the process `pid` has ended: gone, or a zombie nobody has reaped yet (a fake whose
/// parent died is reparented, and in a container nobody may reap it).
inline bool process_ended(const std::string& pid) {
  std::ifstream stat("/proc/" + pid + "/stat");
  if (!stat) return true;
  std::string line;
  std::getline(stat, line);
  const auto close = line.rfind(')');
  return close != std::string::npos && line.size() > close + 2 && line[close + 2] == 'Z';
}

/// Writes an executable script `path` with `body`.
inline void write_script(const fs::path& path, const std::string& body) {
  support::write_file(path, "#!/bin/bash\n" + body);
  fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
}

/// A fake `lmp` with `fault`, in `dir`; the real binary is `real_lmp`.
inline fs::path fake_lammps(const fs::path& dir, Fault fault, const fs::path& real_lmp, const fs::path& pid_file) {
  fs::create_directories(dir);
  const fs::path script = dir / "lmp";
  std::string body = R"(args=("$@"); log=; input=
while [ $# -gt 0 ]; do case "$1" in -log) log="$2"; shift;; -in) input="$2"; shift;; esac; shift; done
)";
  body += fmt::format("if [ \"$input\" = /dev/null ]; then {}; fi\n",
                      fault == Fault::hang_probe ? fmt::format("echo $$ > {}; exec sleep 600", pid_file.string())
                                                 : "exec " + real_lmp.string() + " \"${args[@]}\"");
  switch (fault) {
    case Fault::exit_1:
      body += "echo 'ERROR: deliberate failure of a fake lmp' > \"$log\"; exit 1\n";
      break;
    case Fault::hang:
      body += fmt::format("echo $$ > {}; exec sleep 600\n", pid_file.string());
      break;
    default:
      body += real_lmp.string() + " \"${args[@]}\" || exit $?\n" + damage(fault, "trace.txt");
  }
  write_script(script, body);
  return script;
}

/// A fake `yade` launcher in `dir` whose interpreter is a fake python with `fault` (the real
/// interpreter and module directory are those of the launcher `real_yade`'s installation).
inline fs::path fake_yade(const fs::path& dir, Fault fault, const fs::path& real_python, const fs::path& modules,
                          const fs::path& pid_file) {
  fs::create_directories(dir);
  const fs::path python = dir / "python3-fake";
  std::string body;
  switch (fault) {
    case Fault::exit_1:
      body = "echo 'RuntimeError: deliberate failure of a fake python' >&2; exit 1\n";
      break;
    case Fault::hang:
    case Fault::hang_probe:
      body = fmt::format("echo $$ > {}; exec sleep 600\n", pid_file.string());
      break;
    default:
      body = real_python.string() + " \"$@\" || exit $?\n" + damage(fault, "trace.csv");
  }
  write_script(python, body);
  const fs::path launcher = dir / "yade";
  support::write_file(launcher, fmt::format("#!{}\n# a fake launcher\nimport sys\nsys.path.insert(1,'{}')\n",
                                            python.string(), modules.string()));
  fs::permissions(launcher, fs::perms::owner_all);
  return launcher;
}

/// A fake `liggghts` with `fault`, in `dir`; the real binary is `real_liggghts`. Its trace is the
/// thermo table of its log, so the damage is done to log.liggghts: garbage replaces the whole log,
/// nan the time of the step-0 row, truncated cuts the log in half.
inline fs::path fake_liggghts(const fs::path& dir, Fault fault, const fs::path& real_liggghts, const fs::path& pid_file) {
  fs::create_directories(dir);
  const fs::path script = dir / "liggghts";
  std::string body = R"(args=("$@"); log=log.liggghts; input=
while [ $# -gt 0 ]; do case "$1" in -log) log="$2"; shift;; -in) input="$2"; shift;; esac; shift; done
)";
  body += fmt::format("if [ \"$input\" = /dev/null ]; then {}; fi\n",
                      fault == Fault::hang_probe ? fmt::format("echo $$ > {}; exec sleep 600", pid_file.string())
                                                 : "exec " + real_liggghts.string() + " \"${args[@]}\"");
  switch (fault) {
    case Fault::exit_1:
      body += "echo 'ERROR: deliberate failure of a fake liggghts' > \"$log\"; exit 1\n";
      break;
    case Fault::hang:
      body += fmt::format("echo $$ > {}; exec sleep 600\n", pid_file.string());
      break;
    case Fault::nan:
      body += real_liggghts.string() + " \"${args[@]}\" || exit $?\n" +
              "awk '{ if (!done && $1 == \"0\" && NF > 3) { $2 = \"nan\"; done = 1 } print }' \"$log\" > \"$log.new\" && "
              "mv \"$log.new\" \"$log\"\n";
      break;
    default:
      body += real_liggghts.string() + " \"${args[@]}\" || exit $?\n" + damage(fault, "\"$log\"");
  }
  write_script(script, body);
  return script;
}

}  // namespace demwb_hardening
