// SPDX-License-Identifier: MIT
#include "reference/matching.hpp"

#include <stdexcept>
#include <string>

#include "reference/lammps/matched_scene.hpp"
#include "reference/yade/matched_scene.hpp"

namespace reference {

cases::Scene matched_scene(const cases::Scene& scene, std::string_view engine) {
  if (engine == "lammps") return lammps::matched_scene(scene);
  if (engine == "yade") return yade::matched_scene(scene);
  throw std::invalid_argument("no matched-numerics variant for engine '" + std::string(engine) +
                              "' (known: lammps, yade)");
}

}  // namespace reference
