// SPDX-License-Identifier: MIT
#include "reports/energy_plot.hpp"

#include <algorithm>
#include <string>

#include "cases/trace.hpp"

namespace reports {

std::vector<Series> energy_series(const cases::RunResult& run, bool first) {
  std::vector<Series> out;
  const std::vector<double>* time = run.energy.column("time");
  if (time == nullptr) return out;
  for (const auto q : cases::kEnergyQuantities) {
    const std::vector<double>* v = run.energy.column(q);
    if (v == nullptr || std::all_of(v->begin(), v->end(), [](double x) { return x == 0.0; })) continue;
    std::string title(q.substr(q.find('.') + 1));  // "energy.kinetic" → "kinetic"
    if (!first) title += " (" + run.engine + ")";
    out.push_back({title, *time, *v, first ? "lines" : "lines dt 2", {}});
  }
  return out;
}

}  // namespace reports
