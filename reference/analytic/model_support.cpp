// SPDX-License-Identifier: MIT
#include "reference/analytic/model_support.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace reference::analytic {
namespace {

/// "'a', 'b'" of a list of names.
template <class T, class Name>
std::string listed(const std::vector<T>& values, Name name) {
  std::string out;
  for (const T& v : values) out += fmt::format("{}'{}'", out.empty() ? "" : ", ", name(v));
  return out;
}

}  // namespace

std::vector<std::string> model_reasons(const dem::ModelChoice& m, const ModelSupport& s) {
  std::vector<std::string> reasons;
  const auto reason = [&](const std::string& why) { reasons.push_back(fmt::format("analytic ({}): {}", s.solver, why)); };
  const auto keyword = [](std::string_view k) { return k; };
  const auto slot = [&](std::string_view name, const std::string& chosen, const std::vector<std::string_view>& solved) {
    if (!solved.empty() && std::find(solved.begin(), solved.end(), chosen) == solved.end()) {
      reason(fmt::format("{} model '{}' is not solved here (only {})", name, chosen, listed(solved, keyword)));
    }
  };
  slot("normal", m.normal, s.normal);
  slot("damping", m.damping, s.damping);
  slot("tangential", m.tangential, s.tangential);
  slot("cohesion", m.cohesion, s.cohesion);
  slot("rolling", m.rolling, s.rolling);
  if (m.clamp_tensile && !s.clamp_tensile) reason("clamp_tensile = true changes the dashpot law and is not solved here");
  const auto policy = [&](std::string_view name, auto chosen, const auto& solved) {
    if (std::find(solved.begin(), solved.end(), chosen) == solved.end()) {
      reason(fmt::format("{} = '{}' is not solved here (only {})", name, dem::to_string(chosen),
                         listed(solved, [](auto v) { return dem::to_string(v); })));
    }
  };
  policy("wall_lever_arm", m.wall_lever_arm, s.wall_lever_arm);
  policy("pair_lever_arm", m.pair_lever_arm, s.pair_lever_arm);
  policy("jkr_rupture", m.jkr_rupture, s.jkr_rupture);
  return reasons;
}

}  // namespace reference::analytic
