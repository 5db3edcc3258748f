// SPDX-License-Identifier: MIT
#include "reference/lammps/pair_coeff_mapping.hpp"

#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/registry.hpp"

namespace reference::lammps {
namespace {

/// A visitor made of one lambda per sub-model type.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

/// Why a slot could not be translated; empty when it was.
using SlotProblem = std::optional<std::string>;

/// The reason given for a sub-model without a translation.
template <class Model>
std::string not_mapped(dem::Slot slot) {
  return fmt::format("LAMMPS driver: {} model '{}' is not mapped yet", dem::to_string(slot),
                     Model::kKeyword);
}

/// Normal slot → `hooke k_e` (the damping coefficient is inserted after the elastic part).
SlotProblem map_normal(const dem::NormalModel& normal, GranularCoeff& out) {
  return std::visit(
      Overloaded{
          [&](const dem::LinearNormal& m) -> SlotProblem {
            out.normal_style = "hooke";
            out.normal_elastic = {m.stiffness};
            return std::nullopt;
          },
          [](const auto& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(dem::Slot::normal);
          }},
      normal);
}

/// Constant stiffness of a linear normal sub-model, or empty for a nonlinear one.
std::optional<double> linear_stiffness(const dem::NormalModel& normal) {
  return std::visit(Overloaded{[](const dem::LinearNormal& m) -> std::optional<double> {
                                 return m.stiffness;
                               },
                               [](const auto&) -> std::optional<double> { return std::nullopt; }},
                    normal);
}

/// Damping slot → `damping velocity` with η in kg/s. LAMMPS 2021 has no restitution-based
/// damping, so η = β(ε)√(m* k_e) is computed here for this type pair's m* (eq 3.11).
SlotProblem map_damping(const dem::PairLaw& law, std::optional<double> reduced_mass,
                        GranularCoeff& out) {
  return std::visit(
      Overloaded{
          [&](const dem::NoDamping&) -> SlotProblem {
            out.damping_style = "velocity";
            out.damping_coefficient = 0.0;
            out.damping_note = "eta = 0 (damping 'none')";
            return std::nullopt;
          },
          [&](const dem::RestitutionDamping& m) -> SlotProblem {
            const auto stiffness = linear_stiffness(law.normal);
            if (!stiffness) {
              return fmt::format(
                  "LAMMPS driver: damping model '{}' is mapped only with normal model 'linear' "
                  "(a constant η)",
                  dem::RestitutionDamping::kKeyword);
            }
            out.damping_style = "velocity";
            if (!reduced_mass) {
              out.damping_coefficient = 0.0;
              out.damping_note = "eta = 0 (both types fixed: the pair never moves)";
              return std::nullopt;
            }
            out.damping_coefficient = dem::laws::restitution_damping_coefficient(
                m.restitution, *reduced_mass, *stiffness);
            out.damping_note =
                fmt::format("eta = -2 ln(e) sqrt(m* k_e/(pi^2 + ln(e)^2)) = {:.17g} kg/s with "
                            "e = {}, m* = {:.17g} kg, k_e = {} N/m",
                            out.damping_coefficient, m.restitution, *reduced_mass, *stiffness);
            return std::nullopt;
          },
          [](const auto& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(dem::Slot::damping);
          }},
      law.damping);
}

/// Tangential slot → `tangential linear_nohistory 0 0` for a frictionless contact.
SlotProblem map_tangential(const dem::TangentialModel& tangential, GranularCoeff& out) {
  return std::visit(Overloaded{[&](const dem::NoTangential&) -> SlotProblem {
                                 out.tangential = "linear_nohistory 0 0";
                                 return std::nullopt;
                               },
                               [](const auto& m) -> SlotProblem {
                                 return not_mapped<std::decay_t<decltype(m)>>(
                                     dem::Slot::tangential);
                               }},
                    tangential);
}

/// Cohesion slot: `none` adds nothing.
SlotProblem map_cohesion(const dem::CohesionModel& cohesion, GranularCoeff&) {
  return std::visit(Overloaded{[](const dem::NoCohesion&) -> SlotProblem { return std::nullopt; },
                               [](const auto& m) -> SlotProblem {
                                 return not_mapped<std::decay_t<decltype(m)>>(
                                     dem::Slot::cohesion);
                               }},
                    cohesion);
}

/// Rolling slot: `none` adds nothing.
SlotProblem map_rolling(const dem::RollingModel& rolling, GranularCoeff&) {
  return std::visit(Overloaded{[](const dem::NoRolling&) -> SlotProblem { return std::nullopt; },
                               [](const auto& m) -> SlotProblem {
                                 return not_mapped<std::decay_t<decltype(m)>>(dem::Slot::rolling);
                               }},
                    rolling);
}

/// Model policies: `clamp_tensile` → `limit_damping` (LAMMPS sets F_n = 0 where the elastic plus
/// damping force would attract, as the core's clamp does). The friction-limit and JKR-rupture
/// policies act only through sub-models this phase does not map.
void map_policies(const dem::ContactPolicies& policies, GranularCoeff& out) {
  if (policies.clamp_tensile) out.extras.emplace_back("limit_damping");
}

/// Translates every slot, collecting one reason per slot that cannot be translated.
std::vector<std::string> translate(const dem::PairLaw& law, std::optional<double> reduced_mass,
                                   GranularCoeff& out) {
  std::vector<std::string> problems;
  for (const SlotProblem& p :
       {map_normal(law.normal, out), map_damping(law, reduced_mass, out),
        map_tangential(law.tangential, out), map_cohesion(law.cohesion, out),
        map_rolling(law.rolling, out)}) {
    if (p) problems.push_back(*p);
  }
  map_policies(law.policies, out);
  return problems;
}

}  // namespace

std::vector<std::string> unmapped_sub_models(const dem::PairLaw& law) {
  GranularCoeff ignored;
  return translate(law, 1.0, ignored);
}

GranularCoeff map_pair_law(const dem::PairLaw& law, std::optional<double> reduced_mass) {
  GranularCoeff out;
  const std::vector<std::string> problems = translate(law, reduced_mass, out);
  if (!problems.empty()) {
    std::string message;
    for (const auto& p : problems) message += (message.empty() ? "" : "; ") + p;
    throw std::invalid_argument(message);
  }
  return out;
}

std::string pair_coeff_arguments(const GranularCoeff& c) {
  std::string args = c.normal_style;
  for (const double v : c.normal_elastic) args += fmt::format(" {:.17g}", v);
  args += fmt::format(" {:.17g}", c.damping_coefficient);
  for (const double v : c.normal_trailing) args += fmt::format(" {:.17g}", v);
  args += " tangential " + c.tangential;
  for (const auto& e : c.extras) args += " " + e;
  args += " damping " + c.damping_style;
  return args;
}

}  // namespace reference::lammps
