// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "dem/contact/model_choice.hpp"
#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// One mobile sphere against one plane wall at rest, in the terms the sphere–wall solvers use
/// (SI units). Built from a scene that sphere_wall_reasons accepts.
struct SphereWallScene {
  double radius = 0.0;                ///< r [m]
  double mass = 0.0;                  ///< m [kg]
  double inverse_inertia = 0.0;       ///< 1/I [1/(kg m²)]; 0 when rotation is not integrated
  cases::Vector3 position{};          ///< x(0) [m]
  cases::Vector3 velocity{};          ///< v(0) [m/s]
  cases::Vector3 spin{};              ///< ω(0) [rad/s]
  cases::Vector3 wall_point{};        ///< a point of the wall [m]
  cases::Vector3 normal{};            ///< unit wall normal, into the domain
  std::size_t wall = 0;               ///< index of the wall
  double stiffness = 0.0;             ///< k_e [N/m] (eq 3.10)
  double damping = 0.0;               ///< η [kg/s] (eq 3.11), 0 for damping 'none'
  double friction = 0.0;              ///< μ, 0 for tangential 'none'
  double tangential_stiffness = 0.0;  ///< k_f [N/m], 0 for tangential 'none'
  dem::FrictionLimit limit = dem::FrictionLimit::total;
  bool lever_is_radius = false;       ///< wall_lever_arm = "radius"
};

/// Why the sphere–wall solvers cannot express `scene`, each reason starting with "analytic"
/// and naming `solver`: one mobile sphere, one plane wall at rest, linear normal law with no or
/// restitution damping, tangential 'none' or 'spring_coulomb', no cohesion, rolling, fluid,
/// charge, prescribed motion or tensile clamp.
std::vector<std::string> sphere_wall_reasons(const PreparedScene& prepared, std::string_view solver);

/// The scene in sphere–wall terms; `scene` must pass sphere_wall_reasons.
SphereWallScene sphere_wall_scene(const PreparedScene& prepared);

/// Oblique impact of a sphere on a plane wall in gross sliding (thesis §3.5.2, eq 3.10–3.11,
/// 3.23, 3.32): the normal motion is the linear spring–dashpot collision in closed form, the
/// tangential force is μ times the friction-limit basis against the constant slip direction
/// from the first instant (the k_f → ∞ limit of spring_coulomb), its impulse and moment
/// integrated by Gauss–Legendre quadrature of the closed-form basis to double precision.
class ObliqueImpactSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override {
    return "sphere–wall impact in gross sliding";
  }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

}  // namespace reference::analytic
