// SPDX-License-Identifier: MIT
#include "reference/common/dump_snapshots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "cases/time_step.hpp"

namespace reference {
namespace {

/// Index of column `name` in `frame`; throws naming the step when absent.
std::size_t column(const DumpFrame& frame, std::string_view name, std::string_view code) {
  const auto it = std::find(frame.columns.begin(), frame.columns.end(), name);
  if (it == frame.columns.end()) {
    throw std::runtime_error(
        fmt::format("{} snapshot at step {} has no column '{}'", code, frame.step, name));
  }
  return static_cast<std::size_t>(it - frame.columns.begin());
}

/// The snapshot a frame holds, atoms ordered by id.
cases::Snapshot to_snapshot(const DumpFrame& frame, double time, std::size_t particles, std::string_view code) {
  const std::size_t id = column(frame, "id", code);
  const std::array<std::size_t, 9> c{column(frame, "x", code),      column(frame, "y", code),
                                     column(frame, "z", code),      column(frame, "vx", code),
                                     column(frame, "vy", code),     column(frame, "vz", code),
                                     column(frame, "omegax", code), column(frame, "omegay", code),
                                     column(frame, "omegaz", code)};
  cases::Snapshot snap;
  snap.time = time;
  snap.position.resize(particles);
  snap.velocity.resize(particles);
  snap.angular_velocity.resize(particles);
  std::vector<bool> seen(particles, false);
  for (const auto& row : frame.rows) {
    const double atom = row[id];
    if (!(atom >= 1.0 && atom <= static_cast<double>(particles)) || std::floor(atom) != atom) {
      throw std::runtime_error(
          fmt::format("{} snapshot at step {} has an unexpected atom id {}", code, frame.step, atom));
    }
    const auto i = static_cast<std::size_t>(atom) - 1;
    seen[i] = true;
    snap.position[i] = {row[c[0]], row[c[1]], row[c[2]]};
    snap.velocity[i] = {row[c[3]], row[c[4]], row[c[5]]};
    snap.angular_velocity[i] = {row[c[6]], row[c[7]], row[c[8]]};
  }
  const auto missing = std::find(seen.begin(), seen.end(), false);
  if (missing != seen.end()) {
    throw std::runtime_error(fmt::format("{} snapshot at step {} lacks atom id {}", code, frame.step,
                                         (missing - seen.begin()) + 1));
  }
  return snap;
}

}  // namespace

std::vector<cases::Snapshot> snapshots_from_dump(const std::vector<DumpFrame>& frames,
                                                 const std::vector<std::uint64_t>& steps,
                                                 double dt, std::size_t particles, std::string_view code) {
  std::vector<cases::Snapshot> out;
  for (const std::uint64_t n : steps) {
    const auto frame = std::find_if(frames.begin(), frames.end(),
                                    [n](const DumpFrame& f) { return f.step == n; });
    if (frame == frames.end()) {
      throw std::runtime_error(fmt::format("{} wrote no snapshot at step {}", code, n));
    }
    out.push_back(to_snapshot(*frame, static_cast<double>(n) * dt, particles, code));
  }
  return out;
}

SnapshotSchedule snapshot_schedule(const std::vector<double>& times, double dt, std::uint64_t steps) {
  SnapshotSchedule out;
  std::vector<std::uint64_t> at = cases::snapshot_steps(times, dt, steps);
  at.erase(std::unique(at.begin(), at.end()), at.end());
  if (at.empty()) return out;
  out.first = at.front() == 0;
  if (out.first) at.erase(at.begin());
  std::uint64_t previous = 0;
  for (const std::uint64_t n : at) {
    out.next_step += fmt::format("{}*(step>={})*(step<{})+", n, previous, n);
    previous = n;
  }
  out.next_step += fmt::format("{}*(step>={})", steps + 1, previous);
  return out;
}

}  // namespace reference
