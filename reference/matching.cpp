// SPDX-License-Identifier: MIT
#include "reference/matching.hpp"

#include <stdexcept>
#include <string>

#include "reference/registry.hpp"

namespace reference {

cases::Scene matched_scene(const cases::Scene& scene, std::string_view engine) {
  if (const CodeConventions* c = code_conventions(engine)) return c->matched_scene(PreparedScene(scene));
  std::string known;
  for (const EngineEntry& e : engine_registry()) {
    if (e.conventions != nullptr) known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw std::invalid_argument("no matched-numerics variant for engine '" + std::string(engine) + "' (known: " +
                              known + ")");
}

}  // namespace reference
