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

constexpr std::array<std::pair<FrictionLimit, std::string_view>, 5> kFriction{{
    {FrictionLimit::total, "total"},
    {FrictionLimit::elastic, "elastic"},
    {FrictionLimit::elastic_damping, "elastic_damping"},
    {FrictionLimit::jkr_shifted, "jkr_shifted"},
    {FrictionLimit::total_plus_pulloff, "total_plus_pulloff"},
}};
constexpr std::array<std::pair<JkrRupture, std::string_view>, 2> kRupture{{
    {JkrRupture::displacement, "displacement"},
    {JkrRupture::load, "load"},
}};
constexpr std::array<std::pair<WallLeverArm, std::string_view>, 3> kLever{{
    {WallLeverArm::contact_point, "contact_point"},
    {WallLeverArm::radius, "radius"},
    {WallLeverArm::yade_incident, "yade_incident"},
}};

constexpr std::array<std::pair<PairLeverArm, std::string_view>, 4> kPairLever{{
    {PairLeverArm::contact_point, "contact_point"},
    {PairLeverArm::radius, "radius"},
    {PairLeverArm::radius_velocity, "radius_velocity"},
    {PairLeverArm::yade_incident, "yade_incident"},
}};
constexpr std::array<std::pair<TangentialHistory, std::string_view>, 3> kHistory{{
    {TangentialHistory::project_rescale, "project_rescale"},
    {TangentialHistory::increment_project, "increment_project"},
    {TangentialHistory::yade_rotate, "yade_rotate"},
}};
constexpr std::array<std::pair<MindlinRadius, std::string_view>, 2> kMindlinRadius{{
    {MindlinRadius::overlap, "overlap"},
    {MindlinRadius::contact_radius, "contact_radius"},
}};
constexpr std::array<std::pair<UnloadedSlider, std::string_view>, 2> kUnloaded{{
    {UnloadedSlider::cap, "cap"},
    {UnloadedSlider::zero, "zero"},
}};
constexpr std::array<std::pair<MindlinForm, std::string_view>, 2> kMindlinForm{{
    {MindlinForm::total, "total"},
    {MindlinForm::incremental, "incremental"},
}};
constexpr std::array<std::pair<CoulombTest, std::string_view>, 2> kCoulombTest{{
    {CoulombTest::total, "total"},
    {CoulombTest::spring, "spring"},
}};
constexpr std::array<std::pair<ConstantTorqueForm, std::string_view>, 2> kConstantTorqueForm{{
    {ConstantTorqueForm::tangent, "tangent"},
    {ConstantTorqueForm::projected, "projected"},
}};
constexpr std::array<std::pair<AdhesiveDashpot, std::string_view>, 2> kAdhesiveDashpot{{
    {AdhesiveDashpot::clamp, "clamp"},
    {AdhesiveDashpot::pulloff_cap, "pulloff_cap"},
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
std::string_view to_string(UnloadedSlider p) noexcept { return name_of(kUnloaded, p); }
std::optional<UnloadedSlider> parse_unloaded_slider(std::string_view k) noexcept { return value_of(kUnloaded, k); }
std::string_view to_string(MindlinForm p) noexcept { return name_of(kMindlinForm, p); }
std::optional<MindlinForm> parse_mindlin_form(std::string_view k) noexcept { return value_of(kMindlinForm, k); }
std::string_view to_string(CoulombTest p) noexcept { return name_of(kCoulombTest, p); }
std::optional<CoulombTest> parse_coulomb_test(std::string_view k) noexcept { return value_of(kCoulombTest, k); }
std::string_view to_string(ConstantTorqueForm p) noexcept { return name_of(kConstantTorqueForm, p); }
std::optional<ConstantTorqueForm> parse_constant_torque_form(std::string_view k) noexcept {
  return value_of(kConstantTorqueForm, k);
}
std::string_view to_string(AdhesiveDashpot p) noexcept { return name_of(kAdhesiveDashpot, p); }
std::optional<AdhesiveDashpot> parse_adhesive_dashpot(std::string_view k) noexcept {
  return value_of(kAdhesiveDashpot, k);
}

}  // namespace dem
