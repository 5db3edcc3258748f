// SPDX-License-Identifier: MIT
#include "dem/integrators/scheme.hpp"

#include <array>

#include "dem/integrators/scheme_factories.hpp"

namespace dem {
namespace {

constexpr std::array kInfos{
    SchemeInfo{SchemeId::fe, "fe", "forward Euler", 1, false, "1", 1, "thesis eq D.2"},
    SchemeInfo{SchemeId::se, "se", "symplectic Euler", 1, false, "1", 1, "thesis eq D.3"},
    SchemeInfo{SchemeId::rk2, "rk2", "Runge–Kutta 2 (midpoint)", 2, false, "2", 1,
               "thesis eq D.4"},
    SchemeInfo{SchemeId::rk4, "rk4", "Runge–Kutta 4", 4, false, "4", 1, "thesis eq D.5"},
    SchemeInfo{SchemeId::ab2, "ab2", "Adams–Bashforth 2", 2, false, "1", 2, "thesis eq D.6"},
    SchemeInfo{SchemeId::ab4, "ab4", "Adams–Bashforth 4", 4, false, "1", 4, "thesis eq D.7"},
    SchemeInfo{SchemeId::abm, "abm", "Adams–Bashforth–Moulton", 4, false, "2", 3,
               "thesis eq D.8"},
    SchemeInfo{SchemeId::bd1, "bd1", "back-differenced 1 (backward Euler)", 1, true,
               "iterations", 1, "thesis eq D.10"},
    SchemeInfo{SchemeId::bd2, "bd2", "back-differenced 2", 2, true, "iterations", 2,
               "thesis eq D.11"},
    SchemeInfo{SchemeId::velocity_verlet, "velocity_verlet", "velocity Verlet", 2, false, "1", 1,
               "LAMMPS fix nve/sphere"},
    SchemeInfo{SchemeId::leapfrog, "leapfrog", "leapfrog (half-step velocities)", 2, false, "1",
               1, "YADE NewtonIntegrator"},
};

// Thesis order of table 4.1.
constexpr std::array kThesisSchemes{SchemeId::fe,  SchemeId::se,  SchemeId::rk2,
                                    SchemeId::rk4, SchemeId::ab2, SchemeId::ab4,
                                    SchemeId::abm, SchemeId::bd1, SchemeId::bd2};

}  // namespace

std::span<const SchemeInfo> scheme_infos() noexcept { return kInfos; }

std::span<const SchemeId> thesis_schemes() noexcept { return kThesisSchemes; }

const SchemeInfo& scheme_info(SchemeId id) noexcept {
  for (const auto& info : kInfos) {
    if (info.id == id) return info;
  }
  return kInfos.front();
}

std::optional<SchemeId> parse_scheme(std::string_view keyword) noexcept {
  for (const auto& info : kInfos) {
    if (info.keyword == keyword) return info.id;
  }
  return std::nullopt;
}

void Scheme::set_past(const std::vector<KinematicState>&, ForceEvaluator&, double) {
  // Single-step schemes start from the initial state alone.
}

void Scheme::permute(std::span<const std::uint32_t>) {
  // Single-step schemes keep nothing per sphere between steps.
}

std::unique_ptr<Scheme> make_scheme(SchemeId id, const SchemeSettings& settings) {
  switch (id) {
    case SchemeId::fe: return detail::make_forward_euler(settings);
    case SchemeId::se: return detail::make_symplectic_euler(settings);
    case SchemeId::rk2: return detail::make_runge_kutta_2(settings);
    case SchemeId::rk4: return detail::make_runge_kutta_4(settings);
    case SchemeId::ab2: return detail::make_adams_bashforth_2(settings);
    case SchemeId::ab4: return detail::make_adams_bashforth_4(settings);
    case SchemeId::abm: return detail::make_adams_bashforth_moulton(settings);
    case SchemeId::bd1: return detail::make_backward_difference_1(settings);
    case SchemeId::bd2: return detail::make_backward_difference_2(settings);
    case SchemeId::velocity_verlet: return detail::make_velocity_verlet(settings);
    case SchemeId::leapfrog: return detail::make_leapfrog(settings);
  }
  return detail::make_forward_euler(settings);
}

}  // namespace dem
