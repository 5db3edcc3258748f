// SPDX-License-Identifier: MIT
#pragma once
// What each analytic solver solves of a case's [model], as data: one ModelSupport per solver,
// checked by one function, so that a solver states what it supports instead of coding the check
// (docs/architecture.md, "Engines").

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "dem/contact/model_choice.hpp"

namespace reference::analytic {

/// The sub-models and policies one solver reproduces. A slot's list holds the keywords it solves
/// (empty: every sub-model of the slot); a policy's list the values it solves (by default every
/// value: the policy cannot change that solver's solution).
struct ModelSupport {
  std::string_view solver;  ///< name in the reasons: "analytic (<solver>): …"
  std::vector<std::string_view> normal;
  std::vector<std::string_view> damping;
  std::vector<std::string_view> tangential;
  std::vector<std::string_view> cohesion;
  std::vector<std::string_view> rolling;
  bool clamp_tensile = false;  ///< clamp_tensile = true is solved too
  std::vector<dem::WallLeverArm> wall_lever_arm{dem::WallLeverArm::contact_point, dem::WallLeverArm::radius,
                                                dem::WallLeverArm::yade_incident};
  std::vector<dem::PairLeverArm> pair_lever_arm{dem::PairLeverArm::contact_point, dem::PairLeverArm::radius,
                                                dem::PairLeverArm::radius_velocity, dem::PairLeverArm::yade_incident};
  std::vector<dem::JkrRupture> jkr_rupture{dem::JkrRupture::displacement, dem::JkrRupture::load};
};

/// One reason per part of `m` that `s` does not solve, each "analytic (<solver>): <slot> model
/// '<keyword>' is not solved here (only '<a>', '<b>')" or the policy's counterpart; empty when
/// the solver covers the model.
[[nodiscard]] std::vector<std::string> model_reasons(const dem::ModelChoice& m, const ModelSupport& s);

}  // namespace reference::analytic
