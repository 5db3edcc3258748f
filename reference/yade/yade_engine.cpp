// SPDX-License-Identifier: MIT
#include "reference/yade/yade_engine.hpp"

#include <utility>

#include <fmt/format.h>

#include "reference/yade/model_mapping.hpp"
#include "reference/yade/output_parser.hpp"
#include "reference/yade/restitution_calibration.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/scene_support.hpp"
#include "reference/yade/script_writer.hpp"
#include "reference/yade/yade_process.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace reference {
namespace {

/// Reads and parses the trace, checking that it has the in-house columns and row count.
cases::Trace read_trace(const std::filesystem::path& dir, const yade::YadeRunPlan& plan,
                        std::size_t trace_every) {
  const auto path = dir / yade::kTraceFile;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw yade::YadeOutputError(fmt::format("YADE wrote no trace file ({})", path.string()));
  }
  cases::Trace trace = yade::parse_trace_csv(support::read_file(path), yade::kTraceFile);
  if (trace.columns() != plan.trace_columns) {
    throw yade::YadeOutputError(fmt::format("{}: the header does not list the expected {} columns",
                                            yade::kTraceFile, plan.trace_columns.size()));
  }
  const std::size_t rows = static_cast<std::size_t>(plan.steps / trace_every) + 1;
  if (trace.rows() != rows) {
    throw yade::YadeOutputError(fmt::format("{}: {} rows, expected {} (steps {}, trace_every {})",
                                            yade::kTraceFile, trace.rows(), rows, plan.steps,
                                            trace_every));
  }
  return trace;
}

/// Reads the snapshots and checks their number.
std::vector<cases::Snapshot> read_snapshots(const std::filesystem::path& dir,
                                            const yade::YadeRunPlan& plan, std::size_t particles) {
  const auto path = dir / yade::kSnapshotFile;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw yade::YadeOutputError(fmt::format("YADE wrote no snapshot file ({})", path.string()));
  }
  auto snapshots = yade::parse_snapshot_csv(support::read_file(path), yade::kSnapshotFile, particles);
  if (snapshots.size() != plan.snapshot_iterations.size()) {
    throw yade::YadeOutputError(fmt::format("{}: {} snapshots, expected {}", yade::kSnapshotFile,
                                            snapshots.size(), plan.snapshot_iterations.size()));
  }
  return snapshots;
}

}  // namespace

YadeEngine::YadeEngine(yade::YadeInstallation install) : install_(std::move(install)) {}

YadeEngine YadeEngine::from_launcher(const std::string& program) {
  const yade::LauncherLookup found = yade::find_yade_installation(program);
  YadeEngine engine(found.install.value_or(yade::YadeInstallation{}));
  engine.launcher_ = found.launcher.string();
  engine.problem_ = found.problem;
  return engine;
}

std::optional<std::string> YadeEngine::version() const {
  if (!problem_.empty()) return std::nullopt;
  return yade::detect_yade_version(install_);
}

std::string YadeEngine::location() const {
  if (!problem_.empty()) return problem_;
  const std::string where = fmt::format("python {}, modules {}", install_.python.string(), install_.module_dir.string());
  if (!yade::detect_yade_version(install_)) {
    return fmt::format("{}{}: the interpreter is not executable or yade/config.py names no version",
                       launcher_.empty() ? "" : launcher_ + " → ", where);
  }
  return launcher_.empty() ? where : fmt::format("{} → {}", launcher_, where);
}

Support YadeEngine::supports(const PreparedScene& prepared) const {
  Support s;
  s.reasons = yade::unsupported_scene_features(prepared.scene());
  for (auto& r : yade::map_contact_model(prepared).reasons) s.reasons.push_back(std::move(r));
  return s;
}

std::string YadeEngine::input_fingerprint(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  try {
    const yade::YadeRunPlan plan = yade::make_run_plan(prepared);
    if (!plan.model.reasons.empty()) return {};
    return support::sha256_hex(yade::write_yade_script(scene, plan));
  } catch (const std::exception&) {
    return {};  // the run itself reports why the script cannot be written
  }
}

cases::RunResult YadeEngine::run(const PreparedScene& prepared, const RunOptions& options) const {
  const cases::Scene& scene = prepared.scene();
  const yade::YadeRunPlan plan = yade::make_run_plan(prepared);
  cases::RunResult result;
  result.status = cases::RunStatus::error;
  if (!plan.model.reasons.empty()) {
    result.status = cases::RunStatus::not_applicable;
    for (const auto& r : plan.model.reasons) result.reason += (result.reason.empty() ? "" : "; ") + r;
    return result;
  }
  const std::string script = yade::write_yade_script(scene, plan);
  const yade::YadeProcessOutcome outcome =
      yade::run_yade_script(install_, script, options.work_dir, options.timeout_s);
  result.conventions = plan.conventions;
  result.inexpressible_metrics = plan.inexpressible_metrics;
  result.scratch_dir = outcome.directory.string();
  result.warnings = plan.warnings;
  for (auto& w : yade::unproduced_outputs(scene)) result.warnings.push_back(std::move(w));
  result.log_tail = outcome.log_tail;
  if (!outcome.failure.empty()) {
    result.reason = outcome.failure;
    return result;
  }
  try {
    result.trace = read_trace(outcome.directory, plan, scene.output.trace_every);
    result.snapshots = read_snapshots(outcome.directory, plan, scene.particles.size());
    if (plan.calibration) {
      const auto path = outcome.directory / yade::kCalibrationFile;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        throw yade::YadeOutputError(fmt::format("YADE wrote no calibration file ({})", path.string()));
      }
      result.calibrations.push_back(
          yade::parse_calibration_csv(support::read_file(path), *plan.calibration));
    }
  } catch (const yade::YadeOutputError& e) {
    result.reason = e.what();
    return result;
  }
  result.status = cases::RunStatus::ok;
  result.log_tail.clear();
  if (options.work_dir.empty()) {  // no place to keep it: a temporary directory, removed
    std::error_code ec;
    std::filesystem::remove_all(outcome.directory, ec);
    result.scratch_dir.clear();
  }
  return result;
}

}  // namespace reference
