// SPDX-License-Identifier: MIT
#pragma once
// The case's contact model as LIGGGHTS 3.8 `pair_style gran` / `fix wall/gran` settings and
// `fix property/global` tables (docs/engines.md, "LIGGGHTS").

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "dem/contact/pair_table.hpp"
#include "reference/liggghts/atom_types.hpp"

namespace reference::liggghts {

/// What the deck declares for contacts: the model words, their options and one value per atom
/// type or per atom-type pair (row-major T × T, symmetric) for every global property it reads.
struct ContactSettings {
  std::string normal;                   ///< "hertz", "hertz/stiffness" or "hooke/stiffness"
  std::string tangential;               ///< "history" or "no_history"
  std::string rolling;                  ///< "cdt", or empty without rolling resistance
  std::vector<std::string> options;     ///< model settings, e.g. "tangential_damping off"
  bool hard_particles = false;          ///< a Young's modulus above LIGGGHTS' 1e9 Pa sanity limit
  bool soft_particles = false;          ///< one below its 5e6 Pa limit
  std::vector<double> youngs_modulus;   ///< per type (hertz)
  std::vector<double> poisson_ratio;    ///< per type (hertz)
  std::vector<double> restitution;      ///< per type pair (hertz)
  std::vector<double> friction;         ///< per type pair
  /// per type pair: hooke/stiffness k [N/m]; hertz/stiffness 4/3 E* and 8 G* [Pa], scaled by √(R* δ) in the law
  std::vector<double> kn, kt;
  /// per type pair: hooke/stiffness γ [kg/s] (absolute); hertz/stiffness η₀ [1/(m·s)], scaled by √(R* δ) m*
  std::vector<double> gamman, gammat;
  std::vector<double> rolling_friction; ///< μ_r per type pair (rolling_friction cdt)
};

/// The model words of `pair_style gran` and `fix wall/gran`: "model hertz tangential history …".
std::string model_words(const ContactSettings& c);

/// The settings, or every reason the scene's contact model has no LIGGGHTS counterpart.
struct ContactMapping {
  std::optional<ContactSettings> settings;  ///< what the deck declares, when every reason is absent
  std::vector<std::string> reasons;         ///< one per thing LIGGGHTS cannot express, "LIGGGHTS driver: …"
};

/// Young's modulus written for a rigid wall's type: LIGGGHTS mixes a wall like a particle, and
/// (1 − ν²)/Y of this value vanishes next to any particle's compliance, so E* and G* are the
/// particle's alone.
inline constexpr double kRigidYoungsModulus = 1e300;

/// Maps the scene's model (pure). Only the type pairs that can meet are checked: two walls, or
/// a wall and a frozen particle, get neutral values.
ContactMapping map_contacts(const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types);

/// LIGGGHTS' effective modulus 1/((1 − ν_a²)/Y_a + (1 − ν_b²)/Y_b) (global_properties.cpp).
double liggghts_effective_modulus(double ya, double nua, double yb, double nub) noexcept;
/// LIGGGHTS' effective shear modulus 1/(2(2 − ν_a)(1 + ν_a)/Y_a + 2(2 − ν_b)(1 + ν_b)/Y_b).
double liggghts_effective_shear_modulus(double ya, double nua, double yb, double nub) noexcept;

}  // namespace reference::liggghts
