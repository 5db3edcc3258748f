// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace reference::yade {

/// One material pair's contact parameters, taken from the workbench's pair table and written
/// into the script explicitly (YADE's own mixing is never used).
struct YadePairParameters {
  std::size_t material_a = 0;
  std::size_t material_b = 0;
  double normal_stiffness = 0.0;  ///< kn [N/m] of the pair (MatchMaker value)
  double damping_ratio = 0.0;     ///< betan = η / (2 √(m* kn)) the pair needs; 0 without dashpot
};

/// How the scene's contact model is expressed in YADE 2023.02a (phase 1: linear spring with an
/// optional restitution dashpot, frictionless, no cohesion, no rolling resistance).
struct YadeModelMapping {
  bool viscous = false;                     ///< FrictViscoMat family (dashpot) instead of FrictMat
  std::vector<double> material_damping_ratio;  ///< FrictViscoMat.betan per scene material
  std::vector<YadePairParameters> pairs;    ///< every material pair a ≤ b
  std::vector<std::string> reasons;         ///< why the model cannot be expressed (empty: it can)
  std::vector<std::string> warnings;        ///< where YADE's law differs from the workbench's
  std::map<std::string, std::string> conventions;  ///< "contact <slot>" → registry mapping text
};

/// Maps the scene's contact model, one small function per slot. Never throws: a model the core
/// cannot build gives a reason.
YadeModelMapping map_contact_model(const cases::Scene& scene);

/// Pair damping ratio YADE forms from two FrictViscoMat.betan values (Ip2_FrictViscoMat_…:
/// the mean when both are non-zero, else the non-zero one).
[[nodiscard]] double yade_mixed_damping_ratio(double betan_a, double betan_b) noexcept;

}  // namespace reference::yade
