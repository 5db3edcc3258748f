// SPDX-License-Identifier: MIT
#include "reports/packing_plot.hpp"

#include <algorithm>
#include <variant>

#include <fmt/format.h>

#include "cases/packing_region.hpp"

namespace reports {

std::string packing_series_csv(const std::vector<comparison::PackingSample>& samples) {
  std::string out = "time,orf,dose_remaining\n";
  for (const comparison::PackingSample& s : samples) {
    out += fmt::format("{:.17g},{:.17g},{:.17g}\n", s.time, s.orf, s.dose_remaining);
  }
  return out;
}

std::optional<Plot> fluidisation_plot(const comparison::CaseOutcome& outcome) {
  const cases::Scene& scene = outcome.scene;
  if (!scene.compare.packing) return std::nullopt;
  Plot plot;
  plot.title = "Obscured reservoir fraction and dose remaining";
  plot.xlabel = "time (s)";
  plot.ylabel = "share";
  double end = 0.0;
  for (const cases::RunResult& r : outcome.runs) {
    if (r.status != cases::RunStatus::ok || r.snapshots.size() < cases::kMinFluidisationSnapshots) continue;
    const auto series = comparison::packing_series(scene, r);
    const auto* samples = std::get_if<std::vector<comparison::PackingSample>>(&series);
    if (samples == nullptr) continue;
    Series orf{"ORF (" + r.engine + ")", {}, {}, "linespoints", {}};
    Series dose{"dose remaining (" + r.engine + ")", {}, {}, "lines dt 2", {}};
    for (const comparison::PackingSample& s : *samples) {
      orf.x.push_back(s.time);
      orf.y.push_back(s.orf);
      dose.x.push_back(s.time);
      dose.y.push_back(s.dose_remaining);
      end = std::max(end, s.time);
    }
    plot.series.push_back(std::move(orf));
    plot.series.push_back(std::move(dose));
  }
  if (plot.series.empty()) return std::nullopt;
  if (scene.fluid && scene.fluid->plug_speed > 0.0) {
    // |u|(t)/|u|max: a ramp over ramp_time, then the plateau (thesis §6.5).
    const double ramp = scene.fluid->ramp_time;
    Series speed{fmt::format("plug speed / {:g} m/s", scene.fluid->plug_speed), {}, {}, "lines dt 3", {}};
    speed.x = {0.0};
    speed.y = {ramp > 0.0 ? 0.0 : 1.0};
    if (ramp > 0.0 && ramp < end) {
      speed.x.push_back(ramp);
      speed.y.push_back(1.0);
    }
    speed.x.push_back(end);
    speed.y.push_back(ramp > 0.0 ? std::min(end / ramp, 1.0) : 1.0);
    plot.series.push_back(std::move(speed));
  }
  return plot;
}

}  // namespace reports
