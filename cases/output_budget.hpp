// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "cases/scene.hpp"

namespace cases {

/// Bytes of CSV text a recorded number takes when a trace is written (reports/trace_csv.cpp
/// builds the whole file in memory: up to 24 characters for `{:.17g}` and a separator).
inline constexpr std::uint64_t kCsvBytesPerValue = 25;

/// What a run of a scene keeps in memory for its outputs, and how that was counted
/// (docs/case-format.md, "Limits"). Every number is a double (8 bytes); each engine holds its
/// own trace, energy trace and snapshots until the comparison is done, and one trace at a time
/// is also turned into CSV text.
struct OutputEstimate {
  double duration = 0.0;            ///< simulated time [s] (run_duration: estimated for "launch")
  double timestep = 0.0;            ///< Δt [s] (run_timestep; +∞: "auto" without a possible contact)
  std::uint64_t steps = 0;          ///< ⌈duration / Δt⌉, at least 1 (as the in-house engine counts)
  std::uint64_t trace_rows = 0;     ///< 1 + steps / output.trace_every
  /// Columns of the trace: time, 12 per traced particle, 2 per traced pair or wall contact, 1 per
  /// aggregate.
  std::uint64_t trace_columns = 0;
  std::uint64_t energy_columns = 0;   ///< 14 with output.trace_energy (time and the ledger), else 0
  std::uint64_t snapshots = 0;        ///< output.snapshot_times (+2 at 0 and the end of a launched run)
  std::uint64_t snapshot_values = 0;  ///< numbers per snapshot: time and 9 per particle
  std::uint64_t engines = 0;          ///< compare.engines plus one inhouse@<code> per compare.matched
  double traced_numbers = 0.0;        ///< rows × (trace + energy columns), per engine
  double snapshot_numbers = 0.0;      ///< snapshots × snapshot_values, per engine
  std::uint64_t engine_bytes = 0;     ///< 8 × (rows × (trace + energy columns) + snapshots × values)
  std::uint64_t text_bytes = 0;       ///< kCsvBytesPerValue × rows × (trace + energy columns)
  std::uint64_t bytes = 0;            ///< engines × engine_bytes + text_bytes (saturates at 2⁶⁴ − 1)
};

/// The output memory of a run of `scene`, as OutputEstimate counts it. Pure: resolves the time
/// step like the in-house engine (an automatic step builds the scene's pair table, which throws
/// dem::ModelError when it cannot be built, never for a scene load_case returned).
[[nodiscard]] OutputEstimate estimate_output(const Scene& scene);

/// estimate_output(scene).bytes.
[[nodiscard]] std::uint64_t estimate_output_bytes(const Scene& scene);

/// Throws CaseError when estimate_output(scene).bytes exceeds `max_bytes`. The error names
/// `file`, the key that contributes most (output.trace_every for the traces, output.snapshot_every
/// or output.snapshot_times for the snapshots) at its line in scene.source_text when it is there,
/// the estimate with its parts, the limit, and the keys that shrink it (integration.duration,
/// output.trace_every, output.trace_particles, …). Call it again on a prepared scene: a launch
/// stage fixes its duration only then.
void check_output_budget(const Scene& scene, std::uint64_t max_bytes, const std::string& file);

/// Physical memory of this machine [bytes] (sysconf(_SC_PHYS_PAGES) × sysconf(_SC_PAGESIZE)), or
/// 16 GiB when the system does not say: load_case's default output budget.
[[nodiscard]] std::uint64_t physical_memory_bytes() noexcept;

}  // namespace cases
