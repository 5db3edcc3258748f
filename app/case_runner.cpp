// SPDX-License-Identifier: MIT
#include "app/case_runner.hpp"

#include <stdexcept>

namespace app {

comparison::CaseOutcome run_case(const cases::Scene& scene, const std::vector<std::string>& engines,
                                 const reference::RunOptions& options) {
  std::vector<cases::RunResult> runs;
  for (const auto& name : engines) {
    const auto engine = reference::make_engine(name);
    if (!engine) throw std::invalid_argument("unknown engine '" + name + "'");
    reference::RunOptions o = options;
    o.work_dir = options.work_dir / name;
    runs.push_back(reference::run_engine(*engine, scene, o));
  }
  return comparison::evaluate_runs(scene, std::move(runs));
}

}  // namespace app
