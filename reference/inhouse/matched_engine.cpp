// SPDX-License-Identifier: MIT
#include "reference/inhouse/matched_engine.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cases/catalogue.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace reference {

MatchedInhouseEngine::MatchedInhouseEngine(const CodeConventions& conventions)
    : conventions_(conventions), name_(cases::matched_engine_name(conventions.code)) {}

std::optional<std::string> MatchedInhouseEngine::version() const {
  return InhouseEngine().version();
}

Support MatchedInhouseEngine::supports(const PreparedScene& prepared) const {
  try {
    static_cast<void>(conventions_.matched_scene(prepared));
  } catch (const std::exception& e) {
    return Support{{std::string("no matched numerics for ") + std::string(conventions_.code) + ": " + e.what()}};
  }
  return {};
}

namespace {

/// `scene` with every nonzero initial velocity and spin component of every sphere moved to the
/// next double away from zero; false when there is none (the twin would be the same run).
bool nudge_start(cases::Scene& scene) {
  bool moved = false;
  const auto nudge = [&](double& v) {
    if (v == 0.0 || !std::isfinite(v)) return;
    v = std::nextafter(v, std::copysign(std::numeric_limits<double>::infinity(), v));
    moved = true;
  };
  for (cases::ParticleSpec& p : scene.particles) {
    for (double& v : p.velocity) nudge(v);
    for (double& w : p.angular_velocity) nudge(w);
  }
  return moved;
}

}  // namespace

cases::RunResult MatchedInhouseEngine::run(const PreparedScene& prepared, const RunOptions& options) const {
  const cases::Scene matched = conventions_.matched_scene(prepared);
  cases::RunResult result = InhouseEngine().run(matched, options);
  result.conventions["matched to"] = std::string(conventions_.code) + " (reference::matched_scene: its integrator, velocity "
                                             "convention, damping formula, friction-limit basis and "
                                             "tangential-history rule)";
  // The round-off twin: how far one ulp at the start carries in this scene bounds how long two
  // codes that round differently can agree at round-off (docs/metrics.md, "Round-off horizon").
  cases::Scene nudged = matched;
  if (result.status == cases::RunStatus::ok && nudge_start(nudged)) {
    cases::RunResult twin = InhouseEngine().run(nudged, options);
    if (twin.status == cases::RunStatus::ok) {
      result.roundoff_twin = std::move(twin.trace);
    } else {
      result.warnings.push_back("the round-off twin run failed (" + twin.reason +
                                "): trace_deviation compares every row");
    }
  }
  return result;
}

}  // namespace reference
