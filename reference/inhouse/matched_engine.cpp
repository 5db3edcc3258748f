// SPDX-License-Identifier: MIT
#include "reference/inhouse/matched_engine.hpp"

#include <stdexcept>

#include "cases/catalogue.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/matching.hpp"

namespace reference {

MatchedInhouseEngine::MatchedInhouseEngine(std::string code)
    : code_(std::move(code)), name_(cases::matched_engine_name(code_)) {}

std::optional<std::string> MatchedInhouseEngine::version() const {
  return InhouseEngine().version();
}

Support MatchedInhouseEngine::supports(const cases::Scene& scene) const {
  try {
    static_cast<void>(matched_scene(scene, code_));
  } catch (const std::exception& e) {
    return Support{{std::string("no matched numerics for ") + code_ + ": " + e.what()}};
  }
  return {};
}

cases::RunResult MatchedInhouseEngine::run(const cases::Scene& scene, const RunOptions& options) const {
  cases::RunResult result = InhouseEngine().run(matched_scene(scene, code_), options);
  result.conventions["matched to"] = code_ + " (reference::matched_scene: its integrator, velocity "
                                             "convention, damping formula, friction-limit basis and "
                                             "tangential-history rule)";
  return result;
}

}  // namespace reference
