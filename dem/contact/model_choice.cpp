// SPDX-License-Identifier: MIT
#include "dem/contact/model_choice.hpp"

#include <array>
#include <utility>

namespace dem {
namespace {

template <class E, std::size_t N>
std::string_view name_of(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
  for (const auto& [v, name] : table) {
    if (v == value) return name;
  }
  return "?";
}

template <class E, std::size_t N>
std::optional<E> value_of(const std::array<std::pair<E, std::string_view>, N>& table,
                          std::string_view keyword) {
  for (const auto& [v, name] : table) {
    if (name == keyword) return v;
  }
  return std::nullopt;
}

constexpr std::array<std::pair<FrictionLimit, std::string_view>, 4> kFriction{{
    {FrictionLimit::total, "total"},
    {FrictionLimit::elastic, "elastic"},
    {FrictionLimit::elastic_damping, "elastic_damping"},
    {FrictionLimit::jkr_shifted, "jkr_shifted"},
}};
constexpr std::array<std::pair<JkrRupture, std::string_view>, 2> kRupture{{
    {JkrRupture::displacement, "displacement"},
    {JkrRupture::load, "load"},
}};
constexpr std::array<std::pair<WallLeverArm, std::string_view>, 2> kLever{{
    {WallLeverArm::contact_point, "contact_point"},
    {WallLeverArm::radius, "radius"},
}};

constexpr std::array<std::pair<PairLeverArm, std::string_view>, 3> kPairLever{{
    {PairLeverArm::contact_point, "contact_point"},
    {PairLeverArm::radius, "radius"},
    {PairLeverArm::radius_velocity, "radius_velocity"},
}};
constexpr std::array<std::pair<TangentialHistory, std::string_view>, 2> kHistory{{
    {TangentialHistory::project_rescale, "project_rescale"},
    {TangentialHistory::increment_project, "increment_project"},
}};
constexpr std::array<std::pair<MindlinRadius, std::string_view>, 2> kMindlinRadius{{
    {MindlinRadius::overlap, "overlap"},
    {MindlinRadius::contact_radius, "contact_radius"},
}};

}  // namespace

std::string_view to_string(FrictionLimit p) noexcept { return name_of(kFriction, p); }
std::optional<FrictionLimit> parse_friction_limit(std::string_view k) noexcept { return value_of(kFriction, k); }
std::string_view to_string(JkrRupture p) noexcept { return name_of(kRupture, p); }
std::optional<JkrRupture> parse_jkr_rupture(std::string_view k) noexcept { return value_of(kRupture, k); }
std::string_view to_string(WallLeverArm p) noexcept { return name_of(kLever, p); }
std::optional<WallLeverArm> parse_wall_lever_arm(std::string_view k) noexcept { return value_of(kLever, k); }
std::string_view to_string(PairLeverArm p) noexcept { return name_of(kPairLever, p); }
std::optional<PairLeverArm> parse_pair_lever_arm(std::string_view k) noexcept { return value_of(kPairLever, k); }
std::string_view to_string(TangentialHistory p) noexcept { return name_of(kHistory, p); }
std::optional<TangentialHistory> parse_tangential_history(std::string_view k) noexcept {
  return value_of(kHistory, k);
}
std::string_view to_string(MindlinRadius p) noexcept { return name_of(kMindlinRadius, p); }
std::optional<MindlinRadius> parse_mindlin_radius(std::string_view k) noexcept { return value_of(kMindlinRadius, k); }

}  // namespace dem
