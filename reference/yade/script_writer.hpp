// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

#include "cases/scene.hpp"
#include "reference/yade/run_plan.hpp"

namespace reference::yade {

/// Names of the files the generated script writes into its working directory.
inline constexpr std::string_view kTraceFile = "trace.csv";
inline constexpr std::string_view kSnapshotFile = "snapshots.csv";

/// The YADE Python script that runs `scene` with `plan` (pure: same input, same text). It is
/// executed by the runner of runner_script.hpp, which has imported yade as a module. It writes
/// kTraceFile (header = plan.trace_columns, one '%.17g' row per trace sample) and kSnapshotFile
/// (header "time,particle,x,y,z,vx,vy,vz,wx,wy,wz", one row per particle per snapshot).
std::string write_yade_script(const cases::Scene& scene, const YadeRunPlan& plan);

}  // namespace reference::yade
