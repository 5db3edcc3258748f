// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "bench/lammps_data.hpp"
#include "dem/simulation/simulation.hpp"

namespace bench {

/// LAMMPS's own granular benchmark `in.chute` (32,000 spheres of diameter 1 in LJ units,
/// gran/hooke/history k_n = 2e5, γ_n = 50, k_t = 2/7 k_n, μ = 0.5, dampflag 0 so γ_t = 0; frozen
/// rough base of type 2; gravity 1 tilted 26°, periodic x and y; Δt = 1e-4, skin 0.1): the
/// core's set-up with LAMMPS's numerics (velocity Verlet, m* of the free sphere against a frozen
/// one, full radii as lever arms, shear added then projected, Coulomb cap on |F_el + F_damp|).
/// Frozen atoms keep the velocities of the data file in their contacts but never move, as under
/// LAMMPS's `fix freeze`.
dem::SimulationSetup chute_setup(const LammpsData& data, int threads);

/// The chute's step-100 thermo as LAMMPS's reference log prints it (log.*.chute.*).
struct ChuteReference {
  double kinetic_energy = 784292.08;     ///< thermo `ke`, all atoms, `thermo_modify norm no`
  double rotational_energy = 1571.0968;  ///< `c_1` = compute erotate/sphere
};

/// Where the chute deck lives: `given` when not empty, else $DEMWB_CHUTE_DIR, else
/// ../shared/bench/lammps-chute beside the source tree or the working directory. Empty when no
/// candidate holds in.chute and data.chute.
std::optional<std::filesystem::path> find_chute_dir(const std::string& given);

/// Translational and rotational kinetic energy of every sphere, fixed ones included (LAMMPS's
/// thermo `ke` and compute erotate/sphere over group all).
struct AllKinetic {
  double translational = 0.0;
  double rotational = 0.0;
};
/// Kinetic energies of the spheres of `sim` (summed in setup order).
AllKinetic all_kinetic_energy(const dem::Simulation& sim);

/// `value` printed to `digits` significant digits the way LAMMPS's thermo output does (%.*g).
std::string lammps_digits(double value, int digits = 8);

}  // namespace bench
