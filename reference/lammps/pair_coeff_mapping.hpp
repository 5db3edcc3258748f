// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dem/contact/contact_model.hpp"

namespace reference::lammps {

/// One type pair's `pair_coeff` for `pair_style granular`, slot by slot. Each slot of a
/// dem::PairLaw is translated by one small function (pair_coeff_mapping.cpp); the human-readable
/// mapping of every sub-model lives in its registry row (kLammps in dem/contact/slots/).
struct GranularCoeff {
  std::string normal_style;              ///< normal keyword, e.g. "hooke"
  std::vector<double> normal_elastic;    ///< normal parameters before the damping coefficient
  std::vector<double> normal_trailing;   ///< normal parameters after it (none for hooke)
  double damping_coefficient = 0.0;      ///< η [kg/s] for `damping velocity`
  std::string damping_style;             ///< damping keyword, e.g. "velocity"
  std::string damping_note;              ///< how η was obtained, for the deck and reports
  std::string tangential;                ///< tangential keyword and parameters
  std::vector<std::string> extras;       ///< rolling / twisting keywords with parameters
};

/// One reason per sub-model of `law` that the LAMMPS driver cannot express, e.g.
/// "LAMMPS driver: normal model 'hertz' is not mapped yet"; empty when all are mapped.
std::vector<std::string> unmapped_sub_models(const dem::PairLaw& law);

/// Translates the law of one type pair whose reduced mass is `reduced_mass` (empty when both
/// types are fixed: no dynamics, η = 0). Throws std::invalid_argument with the reasons of
/// unmapped_sub_models when a sub-model is not mapped.
GranularCoeff map_pair_law(const dem::PairLaw& law, std::optional<double> reduced_mass);

/// The arguments that follow `pair_coeff i j`, every number with 17 significant digits, e.g.
/// "hooke 100000 8.8191835579042199 tangential linear_nohistory 0 0 damping velocity".
std::string pair_coeff_arguments(const GranularCoeff& coeff);

}  // namespace reference::lammps
