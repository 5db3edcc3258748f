// SPDX-License-Identifier: MIT
#pragma once
// Running the demwb program from end-to-end tests: real process, real files.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/process.hpp"
#include "support/text_file.hpp"

namespace demwb_e2e {

namespace fs = std::filesystem;

/// Exit code and captured streams of one demwb run.
struct Outcome {
  int exit_code;
  std::string out;
  std::string err;
};

/// Runs demwb with `args` (and `environment` added to this process's) in a scratch directory.
inline Outcome demwb(const std::vector<std::string>& args,
                     const std::map<std::string, std::string>& environment = {}, double timeout_s = 300) {
  static std::atomic<int> counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("demwb_e2e_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string n = std::to_string(counter++);
  support::ProcessSpec spec;
  spec.argv = {DEMWB_BINARY};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.stdout_file = dir / ("out" + n);
  spec.stderr_file = dir / ("err" + n);
  spec.environment = environment;
  spec.timeout_s = timeout_s;
  const auto r = support::run_process(spec);
  EXPECT_TRUE(r.started) << r.error;
  EXPECT_FALSE(r.timed_out) << "demwb did not finish within " << timeout_s << " s";
  return {r.exit_code, support::read_file(spec.stdout_file), support::read_file(spec.stderr_file)};
}

/// Path of a canonical case file in the source tree.
inline std::string canonical(const std::string& name) {
  return std::string(DEMWB_SOURCE_DIR) + "/cases/canonical/" + name + ".toml";
}

/// A fresh (removed) scratch path for one test's outputs.
inline fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("demwb_e2e_out_" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  return p;
}

/// The text of canonical case `name` without its `matched = [...]` line: a run of it goes to the
/// engines a test names and no further (the line adds the reference codes and the core in their
/// numerics to every run, and with them their time-step checks). A non-empty `engines` (a TOML
/// array, e.g. `["inhouse", "analytic"]`) also replaces the case's `engines = [...]` line.
inline std::string canonical_text_unmatched(const std::string& name, const std::string& engines = "") {
  const std::string text = support::read_file(canonical(name));
  std::string kept;
  bool dropped = false;
  bool listed = false;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string line = text.substr(at, end - at);
    at = end + 1;
    if (line.rfind("matched = ", 0) == 0) {
      dropped = true;
      continue;
    }
    if (!engines.empty() && line.rfind("engines = ", 0) == 0) {
      line = "engines = " + engines;
      listed = true;
    }
    kept += line + "\n";
  }
  EXPECT_TRUE(dropped) << name << " has no matched line to drop";
  EXPECT_TRUE(engines.empty() || listed) << name << " has no engines line to replace";
  return kept;
}

/// A scratch copy of canonical case `name` without its `matched` line (canonical_text_unmatched).
inline std::string canonical_unmatched(const std::string& name) {
  const fs::path file = scratch("unmatched_" + name) / (name + ".toml");
  fs::create_directories(file.parent_path());
  support::write_file(file, canonical_text_unmatched(name));
  return file.string();
}

}  // namespace demwb_e2e
