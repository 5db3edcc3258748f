// SPDX-License-Identifier: MIT
#include "cases/output_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cases/case_loader.hpp"
#include "cases/time_step.hpp"
#include "cases/trace.hpp"

namespace cases {
namespace {

/// Bytes of one recorded number.
constexpr double kBytesPerValue = 8.0;

/// Physical memory assumed when the system does not report it [bytes].
constexpr std::uint64_t kFallbackMemoryBytes = 16ULL << 30U;

/// x as an unsigned count, saturating (and NaN as the largest count: never under-estimate).
std::uint64_t saturate(double x) noexcept {
  constexpr double kTop = 1.8e19;  // just below 2⁶⁴
  if (!(x < kTop)) return UINT64_MAX;
  return x <= 0.0 ? 0 : static_cast<std::uint64_t>(x);
}

/// "123456789 bytes (118 MiB)": the count and the largest binary unit it reaches.
std::string bytes_text(std::uint64_t bytes) {
  constexpr std::array<std::string_view, 5> kUnits{"KiB", "MiB", "GiB", "TiB", "PiB"};
  double value = static_cast<double>(bytes);
  std::size_t unit = 0;
  if (value < 1024.0) return fmt::format("{} bytes", bytes);
  value /= 1024.0;
  while (value >= 1024.0 && unit + 1 < kUnits.size()) {
    value /= 1024.0;
    ++unit;
  }
  return fmt::format("{} bytes ({:.3g} {})", bytes, value, kUnits[unit]);
}

/// The case text parsed again, to point at a key; empty when it does not parse (a scene built in
/// code has no text).
std::optional<toml::table> reparse(const std::string& text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

/// Line and column of the first of `paths` (dotted keys) the document holds; 0, 0 when none.
std::pair<int, int> position_of(const std::optional<toml::table>& document,
                                std::initializer_list<std::string_view> paths) {
  if (!document) return {0, 0};
  for (const std::string_view path : paths) {
    if (const toml::node* node = document->at_path(path).node()) {
      return {static_cast<int>(node->source().begin.line), static_cast<int>(node->source().begin.column)};
    }
  }
  return {0, 0};
}

}  // namespace

OutputEstimate estimate_output(const Scene& scene) {
  OutputEstimate e;
  const OutputSpec& out = scene.output;
  e.duration = run_duration(scene);
  e.timestep = run_timestep(scene);
  e.steps = step_count(e.duration, e.timestep);
  e.trace_rows = e.steps / std::max<std::uint64_t>(1, out.trace_every) + 1;
  e.trace_columns = 1 + std::size(kParticleQuantities) * out.trace_particles.size() +
                    std::size(kPairQuantities) * (out.trace_pairs.size() + out.trace_walls.size()) +
                    out.trace_aggregates.size();
  e.energy_columns = out.trace_energy ? 1 + std::size(kEnergyQuantities) : 0;
  e.snapshots = out.snapshot_times.size() + (scene.duration_from_launch ? 2 : 0);
  e.snapshot_values = 1 + 9 * scene.particles.size();
  e.engines = std::max<std::uint64_t>(1, scene.compare.engines.size() + scene.compare.matched.size());
  e.traced_numbers = static_cast<double>(e.trace_rows) * static_cast<double>(e.trace_columns + e.energy_columns);
  e.snapshot_numbers = static_cast<double>(e.snapshots) * static_cast<double>(e.snapshot_values);
  const double engine_bytes = kBytesPerValue * (e.traced_numbers + e.snapshot_numbers);
  const double text_bytes = static_cast<double>(kCsvBytesPerValue) * e.traced_numbers;
  e.engine_bytes = saturate(engine_bytes);
  e.text_bytes = saturate(text_bytes);
  e.bytes = saturate(static_cast<double>(e.engines) * engine_bytes + text_bytes);
  return e;
}

std::uint64_t estimate_output_bytes(const Scene& scene) { return estimate_output(scene).bytes; }

void check_output_budget(const Scene& scene, std::uint64_t max_bytes, const std::string& file) {
  const OutputEstimate e = estimate_output(scene);
  if (e.bytes <= max_bytes) return;
  // Blame what holds the most: the traces (their rows), or the snapshots.
  const std::optional<toml::table> document = reparse(scene.source_text);
  std::string key = "output.trace_every";
  if (e.snapshot_numbers > e.traced_numbers) {
    key = document && document->at_path("output.snapshot_every").node() != nullptr ? "output.snapshot_every"
                                                                                   : "output.snapshot_times";
  }
  // At the key, else at [output], else at the duration.
  const auto [line, column] = position_of(document, {key, "output", "integration.duration"});
  throw CaseError(
      file, key,
      fmt::format("a run would hold about {} of output in memory, more than the limit of {}: {} engine{} × {} (the "
                  "trace: {} steps of {:.6g} s over {:.6g} s, every {} → {} rows × {} columns{}; {} snapshot{} × {} "
                  "values) + {} of CSV text; raise output.trace_every, shorten integration.duration, trace fewer "
                  "particles, pairs or walls (output.trace_particles, output.trace_pairs, output.trace_walls) or "
                  "take fewer snapshots",
                  bytes_text(e.bytes), bytes_text(max_bytes), e.engines, e.engines == 1 ? "" : "s",
                  bytes_text(e.engine_bytes), e.steps, e.timestep, e.duration, scene.output.trace_every, e.trace_rows,
                  e.trace_columns, e.energy_columns > 0 ? fmt::format(" + {} energy columns", e.energy_columns) : "",
                  e.snapshots, e.snapshots == 1 ? "" : "s", e.snapshot_values, bytes_text(e.text_bytes)),
      line, column);
}

std::uint64_t physical_memory_bytes() noexcept {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return kFallbackMemoryBytes;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

}  // namespace cases
