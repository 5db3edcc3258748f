// SPDX-License-Identifier: MIT
#include "bench/lammps_log.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

#include "support/text_tokens.hpp"

namespace bench {
namespace {

std::optional<double> to_number(std::string_view t) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc{} || end != t.data() + t.size()) return std::nullopt;
  return v;
}

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

LammpsLog parse_lammps_log(std::string_view text) {
  LammpsLog log;
  std::vector<std::string> header;
  bool in_breakdown = false;
  for (const std::string_view raw : support::split_lines(text)) {
    const std::vector<std::string_view> w = support::split_words(raw);
    if (w.empty()) {
      in_breakdown = false;
      continue;
    }
    if (w[0] == "Step") {
      header.assign(w.begin(), w.end());
      continue;
    }
    if (!header.empty() && w.size() == header.size()) {
      ThermoRow row;
      bool numeric = true;
      for (std::size_t k = 0; k < w.size() && numeric; ++k) {
        const auto v = to_number(w[k]);
        numeric = v.has_value();
        if (numeric) row.values[header[k]] = *v;
      }
      if (numeric) {
        row.step = static_cast<std::uint64_t>(row.values["Step"]);
        log.thermo.push_back(std::move(row));
        continue;
      }
    }
    header.clear();
    // "Loop time of 0.534174 on 1 procs for 100 steps with 32000 atoms"
    if (starts_with(raw, "Loop time of") && w.size() >= 12) {
      log.loop_s += to_number(w[3]).value_or(0.0);
      log.procs = static_cast<int>(to_number(w[5]).value_or(0.0));
      log.steps += static_cast<std::uint64_t>(to_number(w[8]).value_or(0.0));
      log.atoms = static_cast<std::uint64_t>(to_number(w[11]).value_or(0.0));
      continue;
    }
    // "Per MPI rank memory allocation (min/avg/max) = 16.09 | 16.09 | 16.09 Mbytes"
    if (starts_with(raw, "Per MPI rank memory allocation") && w.size() >= 10) {
      log.memory_mb_per_rank = std::max(log.memory_mb_per_rank, to_number(w[9]).value_or(0.0));
      continue;
    }
    // "Memory usage per processor = 16.0904 Mbytes" (older versions)
    if (starts_with(raw, "Memory usage per processor") && w.size() >= 6) {
      log.memory_mb_per_rank = std::max(log.memory_mb_per_rank, to_number(w[5]).value_or(0.0));
      continue;
    }
    // "Pair  time (%) = 0.050545 (82.1449)" (LAMMPS before 2014, LIGGGHTS 3.8)
    if (w.size() >= 6 && w[1] == "time" && w[2] == "(%)" && w[3] == "=") {
      if (const auto seconds = to_number(w[4])) log.breakdown_s[std::string(w[0])] += *seconds;
      continue;
    }
    if (starts_with(raw, "Section |")) {
      in_breakdown = true;
      continue;
    }
    // "Other   |            | 0.02153    |            |       |  4.03"
    if (in_breakdown && w.size() >= 4 && w[0] == "Other" && w[1] == "|") {
      if (const auto avg = to_number(w[3])) log.breakdown_s["Other"] += *avg;
      continue;
    }
    // "Pair    | 0.33346    | 0.33346    | 0.33346    |   0.0 | 62.43"
    if (in_breakdown && w.size() >= 5 && w[1] == "|") {
      if (const auto avg = to_number(w[4])) log.breakdown_s[std::string(w[0])] += *avg;
    }
  }
  return log;
}

}  // namespace bench
