// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "cases/scene.hpp"

namespace prepare {

/// What a launch did (thesis §5.2.2).
struct LaunchFigures {
  double enclosing_diameter = 0.0;  ///< L_A: smallest sphere about the centre of mass enclosing every sphere [m]
  double duration = 0.0;            ///< t_max = 4 L_A / (|u| sin θ) (eq 5.1) [s]
  cases::Vector3 centre_of_mass{};  ///< after the launch [m]
};

/// Places the mobile spheres of `particles` for an oblique impact on `wall` and gives each the
/// impact velocity (thesis §5.2.2): the centre of mass (sphere masses from `density`, one per
/// particle) moves to wall.point + height·L_A·n, every mobile sphere gets
/// u = |u| (cos θ t̂ − sin θ n) and no spin. Fixed spheres are left alone. Throws
/// std::invalid_argument when no sphere is mobile.
LaunchFigures launch(std::vector<cases::ParticleSpec>& particles, const std::vector<double>& density,
                     const cases::WallSpec& wall, const cases::LaunchStageSpec& spec);

}  // namespace prepare
