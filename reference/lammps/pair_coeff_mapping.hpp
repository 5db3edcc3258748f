// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dem/contact/contact_model.hpp"

namespace reference::lammps {

/// One type pair's (or one wall's) granular coefficients, slot by slot. Each slot of a
/// dem::PairLaw is translated by one small function (pair_coeff_mapping.cpp); the human-readable
/// mapping of every sub-model lives in its registry row (kLammps in dem/contact/slots/).
struct GranularCoeff {
  std::string normal_style;              ///< normal keyword: hooke, hertz/material, jkr, dmt
  std::vector<double> normal_elastic;    ///< normal parameters before the damping coefficient
  std::vector<double> normal_trailing;   ///< normal parameters after it (ν, γ)
  double damping_coefficient = 0.0;      ///< the damping value of pair_coeff (η, η/m*, η₀ or e_in)
  std::string damping_style;             ///< damping keyword, e.g. "velocity"
  std::string damping_note;              ///< how the damping value was obtained
  std::string normal_note;               ///< how the normal parameters were obtained
  std::string tangential;                ///< tangential keyword and parameters
  std::vector<std::string> extras;       ///< rolling keywords with parameters, limit_damping
};

/// What the translation of one law needs besides the law itself.
struct PairContext {
  /// Reduced mass m* of the pair (the particle's mass against a wall); empty when both types
  /// are fixed (no dynamics: η = 0).
  std::optional<double> reduced_mass;
  /// ν written into hertz/material, jkr and dmt. Any ν gives the same force, because E is
  /// converted so that LAMMPS' E* equals the core's (see `wall`); the material's ν is used.
  double poisson_ratio = 0.0;
  /// For `fix wall/gran granular`: E_in = 2(1 − ν)E* (this build's wall reads
  /// E* = E/(2(1 − ν)), B3 in docs/engines.md); for pair_coeff E_in = 2(1 − ν²)E*.
  bool wall = false;
  /// The types hold atoms of many masses (AtomTypes::per_atom_diameter): a coefficient that
  /// depends on m* cannot be written, and the mapping says so instead of guessing.
  bool per_atom_masses = false;
};

/// One reason per sub-model of `law` that the LAMMPS driver cannot express (for a wall when
/// `wall`; with `per_atom_masses` when the types hold atoms of many masses), e.g. "LAMMPS driver:
/// rolling model 'constant_torque' ..."; empty when all are mapped.
std::vector<std::string> unmapped_sub_models(const dem::PairLaw& law, bool wall = false,
                                             bool per_atom_masses = false);

/// Translates the law of one type pair (or particle type against a wall). Throws
/// std::invalid_argument with the reasons of unmapped_sub_models when a sub-model is not mapped.
GranularCoeff map_pair_law(const dem::PairLaw& law, const PairContext& context);

/// map_pair_law for a pair with reduced mass `reduced_mass` and ν = 0.
GranularCoeff map_pair_law(const dem::PairLaw& law, std::optional<double> reduced_mass);

/// The model arguments that follow `pair_coeff i j` (and `fix … wall/gran granular`), every
/// number with 17 significant digits, e.g.
/// "hooke 100000 8.8191835579042199 tangential linear_nohistory 0 0 damping velocity".
std::string pair_coeff_arguments(const GranularCoeff& coeff);

}  // namespace reference::lammps
