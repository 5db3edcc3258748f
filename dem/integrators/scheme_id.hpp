// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <span>
#include <string_view>

// Names and options of the integration schemes, free of Eigen so case files and reports can
// use them cheaply.
namespace dem {

/// The time-integration schemes of thesis appendix D plus the reference codes' own.
enum class SchemeId { fe, se, rk2, rk4, ab2, ab4, abm, bd1, bd2, velocity_verlet, leapfrog };

/// Facts about one scheme (thesis table 4.1 / D.1, extended with the reference codes' schemes).
struct SchemeInfo {
  SchemeId id;
  std::string_view keyword;        ///< case-file name
  std::string_view name;           ///< human name
  int local_order;                 ///< order of the local truncation error minus one
  bool implicit;                   ///< iterated to a tolerance
  std::string_view evaluations;    ///< force evaluations per step
  int memory_points;               ///< preceding time points the scheme uses
  std::string_view source;         ///< thesis equation or reference code
};

/// Every scheme in documentation order.
std::span<const SchemeInfo> scheme_infos() noexcept;
/// The nine schemes of the thesis' integrator study (appendix D), in thesis order.
std::span<const SchemeId> thesis_schemes() noexcept;
/// Facts about `id`.
const SchemeInfo& scheme_info(SchemeId id) noexcept;
/// Scheme named `keyword`, or empty.
std::optional<SchemeId> parse_scheme(std::string_view keyword) noexcept;

/// How multi-step schemes obtain the data they need before the first step (docs/integrators.md).
enum class StartupPolicy {
  rk4,    ///< take the first steps with RK4 sub-steps (default)
  exact,  ///< the caller supplies exact states at t = −Δt, −2Δt, … (thesis §4.2.2)
};

/// Where the leapfrog's staggered velocity starts.
enum class LeapfrogStart {
  half_kick,         ///< given velocity is v(0); first kick is Δt/2 (second-order start)
  given_is_half_step ///< given velocity is v(−Δt/2), as YADE's NewtonIntegrator assumes
};

/// Options shared by every scheme.
struct SchemeSettings {
  bool rotation = true;                ///< integrate ω and orientation (else hold them)
  StartupPolicy startup = StartupPolicy::rk4;
  int startup_substeps = 4;            ///< RK4 sub-steps per start-up step
  double implicit_tolerance = 1e-12;   ///< BD1/BD2: relative change that ends the iteration
  int implicit_max_iterations = 100;   ///< BD1/BD2: iterations before giving up on a step
  double length_scale = 1.0;           ///< [m] scale of position changes (smallest radius)
  LeapfrogStart leapfrog_start = LeapfrogStart::half_kick;
  /// Turn the orientation quaternions with ω (nothing in the core reads them back; a run that
  /// records no orientation may switch this off, as LAMMPS' atom_style sphere keeps none).
  bool orientation = true;
};

}  // namespace dem
