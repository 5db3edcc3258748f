// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"
#include "dem/contact/pair_table.hpp"
#include "reference/analytic/collinear_motion.hpp"

namespace reference::analytic {

/// Indices of the mobile and of the fixed particles of a scene.
struct ParticleRoles {
  std::vector<std::size_t> mobile;
  std::vector<std::size_t> fixed;
};

/// Splits the particles into mobile and fixed ones, in scene order.
ParticleRoles particle_roles(const cases::Scene& scene);

/// Mass of particle i [kg] (eq 3.1).
double particle_mass(const cases::Scene& scene, std::size_t i);

/// Unit vector of one mobile sphere's line of motion: along its velocity or, at rest, from the
/// first of `fixed` it touches (δ ≥ 0, eq 3.2) towards it. Empty when neither exists.
std::optional<cases::Vector3> line_of_motion(const cases::Scene& scene, std::size_t mobile,
                                             const std::vector<std::size_t>& fixed);

/// A supported scene reduced to motion along one line (the pair geometry of docs/physics.md on one
/// axis).
struct CollinearScene {
  bool two_mobile = false;   ///< true: s is the centre separation of `first` and `second`
  AxisProblem problem;       ///< the 1-D problem (m, or m* for two mobile spheres)
  cases::Vector3 axis{};     ///< unit vector e of the line of motion
  std::size_t first = 0;     ///< the mobile sphere; with two, sphere a (s = (x_a − x_b)·e)
  std::size_t second = 0;    ///< sphere b (two mobile spheres only)
  double first_share = 1.0;  ///< m_b / (m_a + m_b): how much of a change of s moves `first`
  double second_share = 0.0; ///< m_a / (m_a + m_b): how much moves `second` (the other way)
  cases::Vector3 centre_of_mass_velocity{};    ///< V, uniform (two mobile spheres; else 0)
  std::vector<std::size_t> partner_particle;   ///< particle behind each axis partner
};

/// Reduces `scene` to one axis. Throws std::invalid_argument carrying every reason when the
/// scene is unsupported (see unsupported_reasons).
CollinearScene reduce_scene(const PreparedScene& prepared);

/// The reduction of a scene whose model and layout are supported, with the pair parameters
/// from `table` (k_e, and η = β(ε) √(m* k_e), eq 3.11); the parameters are not checked.
CollinearScene build_collinear_scene(const cases::Scene& scene, const dem::PairTable& table);

/// Axis partner that stands for the contact of particles p and q, or empty when p–q is not a
/// contact the solution tracks (e.g. two fixed spheres).
std::optional<std::size_t> partner_of_pair(const CollinearScene& reduced, std::size_t p,
                                           std::size_t q) noexcept;

/// Exact state of every particle at time t, given the axis state at t.
cases::Snapshot snapshot_at(const cases::Scene& scene, const CollinearScene& reduced,
                            const AxisSample& sample, double t);

/// Total contact force on every particle [N], given the axis state (a fixed sphere receives the
/// opposite of the force it exerts, as the in-house core reports it).
std::vector<cases::Vector3> forces_at(const cases::Scene& scene, const CollinearScene& reduced,
                                      const AxisSample& sample);

}  // namespace reference::analytic
