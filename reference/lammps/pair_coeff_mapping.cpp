// SPDX-License-Identifier: MIT
#include "reference/lammps/pair_coeff_mapping.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/registry.hpp"
#include "reference/lammps/tsuji_input.hpp"

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

/// The reason given for a sub-model without a translation, with why LAMMPS lacks it.
template <class Model>
std::string not_mapped(dem::Slot slot, std::string_view why) {
  return fmt::format("LAMMPS driver: {} model '{}' is not mapped ({})", dem::to_string(slot),
                     Model::kKeyword, why);
}

/// E to write so that LAMMPS' E* equals `modulus`: pair_coeff reads E* = E/(2(1 − ν²)) for
/// every pair (measured: hertz/material E = 1e7, ν = 0.3 gives E* = 5.4945e6), this build's fix
/// wall/gran E* = E/(2(1 − ν)) (B3, docs/engines.md).
double lammps_youngs_modulus(double modulus, const PairContext& c) {
  const double nu = c.poisson_ratio;
  return c.wall ? 2.0 * (1.0 - nu) * modulus : 2.0 * (1.0 - nu * nu) * modulus;
}

/// True for the cohesion sub-models LAMMPS folds into the normal model (jkr, dmt); a JKR pair
/// with γ = 0 is plain Hertz and is written as hertz/material.
bool adhesive_normal(const dem::CohesionModel& cohesion) {
  if (const auto* jkr = std::get_if<dem::JkrCohesion>(&cohesion)) return jkr->adhesive();
  return std::holds_alternative<dem::DmtCohesion>(cohesion);
}

/// Normal slot → `hooke k_e` or `hertz/material E_in η ν` (η inserted by the damping slot).
SlotProblem map_normal(const dem::PairLaw& law, const PairContext& c, GranularCoeff& out) {
  return std::visit(
      Overloaded{
          [&](const dem::LinearNormal& m) -> SlotProblem {
            out.normal_style = "hooke";
            out.normal_elastic = {m.stiffness};
            out.normal_note = fmt::format("k_e = {:.17g} N/m", m.stiffness);
            return std::nullopt;
          },
          [&](const dem::HertzNormal& m) -> SlotProblem {
            out.normal_style = "hertz/material";
            out.normal_elastic = {lammps_youngs_modulus(m.effective_modulus, c)};
            out.normal_trailing = {c.poisson_ratio};
            out.normal_note = fmt::format(
                "E = {} E* = {:.17g} Pa with E* = {:.17g} Pa, nu = {}",
                c.wall ? "2(1-nu)" : "2(1-nu^2)", out.normal_elastic[0], m.effective_modulus,
                c.poisson_ratio);
            return std::nullopt;
          },
          [](const auto& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(
                dem::Slot::normal, "pair granular offers hooke, hertz, hertz/material, dmt, jkr");
          }},
      law.normal);
}

/// Cohesion slot: jkr / dmt replace the Hertz normal keyword and append γ per surface.
SlotProblem map_cohesion(const dem::PairLaw& law, const PairContext& c, GranularCoeff& out) {
  // `modulus` empty: keep the Hertz slot's E (DMT adds only the constant adhesion).
  const auto adhesive = [&](std::string_view style, std::optional<double> modulus, double gamma,
                            std::string_view keyword) -> SlotProblem {
    if (out.normal_style != "hertz/material") {
      return fmt::format("LAMMPS driver: cohesion '{}' needs normal = 'hertz' (LAMMPS `{}` is a "
                         "Hertz-based normal model)",
                         keyword, style);
    }
    out.normal_style = std::string(style);
    if (modulus) out.normal_elastic = {lammps_youngs_modulus(*modulus, c)};
    out.normal_trailing.push_back(gamma);
    out.normal_note += fmt::format("; gamma = {:.17g} J/m^2 per surface (LAMMPS' convention too)",
                                   gamma);
    return std::nullopt;
  };
  return std::visit(
      Overloaded{
          [](const dem::NoCohesion&) -> SlotProblem { return std::nullopt; },
          [&](const dem::JkrCohesion& m) -> SlotProblem {
            // γ = 0: JKR is Hertz (a non-adhesive wall in a JKR model): hertz/material, and the
            // friction limit LAMMPS uses for it (elastic + damping) is the core's for such a pair.
            if (!m.adhesive()) return std::nullopt;
            if (c.wall) {
              return std::string(
                  "LAMMPS driver: cohesion 'jkr' on a wall is not mapped (fix wall/gran jkr in "
                  "this build never releases the contact and produces NaN)");
            }
            return adhesive("jkr", m.modulus, m.surface_energy, m.kKeyword);
          },
          [&](const dem::DmtCohesion& m) -> SlotProblem {
            return adhesive("dmt", std::nullopt, m.surface_energy, m.kKeyword);
          },
          [](const dem::LinearCohesion& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(
                dem::Slot::cohesion,
                "LAMMPS has no linear cohesion over an interaction radius; pair_style "
                "hybrid/overlay granular table could emulate it per type pair but this driver "
                "does not write it");
          },
          [](const dem::CoulombCohesion& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(
                dem::Slot::cohesion, "pair_style granular has no electrostatics; a coul/cut "
                                     "overlay is not written by this driver");
          }},
      law.cohesion);
}

/// Records `style` with `value` and a note; returns no problem.
SlotProblem set_damping(GranularCoeff& out, std::string_view style, double value,
                        std::string note) {
  out.damping_style = std::string(style);
  out.damping_coefficient = value;
  out.damping_note = std::move(note);
  return std::nullopt;
}

/// `damping tsuji` with e_in such that α_L(e_in) = factor (the core's dashpot factor per
/// √(m* F_el/δ)). A factor of exactly 0 (ε = 1) is no dashpot at all: `damping velocity` with
/// η_n0 = 0 gives exactly zero, where α_L would leave a round-off residue. A problem when no
/// e_in gives the factor.
SlotProblem tsuji_with_factor(GranularCoeff& out, double factor, std::string_view what) {
  if (factor == 0.0) {
    return set_damping(out, "velocity", 0.0,
                       fmt::format("damping velocity with eta_n0 = 0: {} is 0 (no dashpot)", what));
  }
  const std::optional<double> e_in = tsuji_input_for_factor(factor);
  if (!e_in) {
    return fmt::format("LAMMPS driver: {} needs a Tsuji factor {} that no input of LAMMPS' Tsuji polynomial "
                       "gives (it covers [0, {:.4g}] for e_in in [{}, {:.6g}])",
                       what, factor, dem::laws::lammps_tsuji_factor(kTsujiInputLowest), kTsujiInputLowest,
                       tsuji_input_zero());
  }
  return set_damping(
      out, "tsuji", *e_in,
      fmt::format("damping tsuji with e_in = {:.17g}: alpha_L(e_in) = {:.17g} = {} (inverse of "
                  "LAMMPS' Tsuji polynomial, so LAMMPS' dashpot is the core's)",
                  *e_in, factor, what));
}

/// Damping slot. LAMMPS 2021 has no restitution-based damping: the core's η (or the Tsuji
/// input that yields the core's dashpot) is computed here for this pair's m*.
SlotProblem map_damping(const dem::PairLaw& law, const PairContext& c, GranularCoeff& out) {
  const bool hooke = out.normal_style == "hooke";
  const bool jkr = out.normal_style == "jkr";
  const auto no_jkr = [&](std::string_view keyword) -> SlotProblem {
    if (!jkr) return std::nullopt;
    return fmt::format("LAMMPS driver: damping '{}' with cohesion 'jkr' is not mapped exactly "
                       "(LAMMPS scales it with the JKR contact radius a, the core with "
                       "sqrt(R* delta))",
                       keyword);
  };
  return std::visit(
      Overloaded{
          [&](const dem::NoDamping&) -> SlotProblem {
            return set_damping(out, "velocity", 0.0, "eta = 0 (damping 'none')");
          },
          [&](const dem::RestitutionDamping& m) -> SlotProblem {
            if (!c.reduced_mass) {
              return set_damping(out, "velocity", 0.0,
                                 "eta = 0 (both types fixed: the pair never moves)");
            }
            if (hooke && c.per_atom_masses) {
              return std::string(
                  "LAMMPS driver: damping 'restitution' on a linear spring needs eta from each pair's m*; "
                  "with more than 16 size classes the deck has one atom type per material, so no pair_coeff "
                  "can carry it (use damping 'lammps_mass_velocity', 'lammps_velocity' or a Hertz normal)");
            }
            if (hooke) {
              const double k = out.normal_elastic.at(0);
              const double eta =
                  dem::laws::restitution_damping_coefficient(m.restitution, *c.reduced_mass, k);
              return set_damping(
                  out, "velocity", eta,
                  fmt::format("eta = -2 ln(e) sqrt(m* k_e/(pi^2 + ln(e)^2)) = {:.17g} kg/s with "
                              "e = {}, m* = {:.17g} kg, k_e = {} N/m (the core's exact formula)",
                              eta, m.restitution, *c.reduced_mass, k));
            }
            if (auto p = no_jkr(m.kKeyword)) return p;
            // Core: η = f √(m* 2E*a); LAMMPS tsuji: α_L √(m* 4/3 E* a) ⇒ α_L = f √1.5.
            return tsuji_with_factor(out, m.factor * std::sqrt(1.5),
                                     fmt::format("sqrt(1.5) * beta(e = {})", m.restitution));
          },
          [&](const dem::TsujiDamping& m) -> SlotProblem {
            if (auto p = no_jkr(m.kKeyword)) return p;
            return tsuji_with_factor(out, m.factor,
                                     fmt::format("alpha(e = {}) of the core's tsuji", m.restitution));
          },
          [&](const dem::LammpsVelocityDamping& m) -> SlotProblem {
            return set_damping(out, "velocity", m.damping, "eta given (damping velocity)");
          },
          [&](const dem::LammpsMassVelocityDamping& m) -> SlotProblem {
            return set_damping(out, "mass_velocity", m.rate, "eta/m* given (damping mass_velocity)");
          },
          [&](const dem::LammpsViscoelasticDamping& m) -> SlotProblem {
            // Under jkr both codes use the JKR contact radius a (η = η₀ a m*).
            return set_damping(out, "viscoelastic", m.rate_per_length,
                               "eta_0 given (damping viscoelastic, eta = eta_0 a m*)");
          },
          [&](const dem::LammpsTsujiDamping& m) -> SlotProblem {
            // Under jkr both codes take the stiffness (4/3) E* a with the JKR contact radius a.
            return set_damping(out, "tsuji", m.restitution, "nominal e given (damping tsuji as is)");
          },
          [](const auto& m) -> SlotProblem {
            return not_mapped<std::decay_t<decltype(m)>>(
                dem::Slot::damping,
                "LAMMPS 2021 offers velocity, mass_velocity, viscoelastic and tsuji damping only");
          }},
      law.damping);
}

/// Tangential slot → linear_nohistory 0 0 (none), linear_history (spring_coulomb), or mindlin
/// (mindlin_form 'total') / mindlin/force ('incremental') with the stiffness prefactor written explicitly (NULL is wrong for walls, B4,
/// docs/engines.md).
SlotProblem map_tangential(const dem::PairLaw& law, GranularCoeff& out) {
  const bool adhesive = adhesive_normal(law.cohesion);
  if (std::holds_alternative<dem::DmtCohesion>(law.cohesion) && !std::holds_alternative<dem::NoTangential>(law.tangential)) {
    // pair granular (and fix wall/gran) of 29 Sep 2021 take the DMT Coulomb limit as
    // |F_ne + 2·4πγR| with γ read from a variable that only the JKR branches assign: for a DMT
    // pair it is uninitialised, so LAMMPS' friction limit is undefined (docs/engines.md, B11).
    return std::string(
        "LAMMPS driver: a tangential law with cohesion 'dmt' is not mapped (pair granular 29 Sep 2021 "
        "computes the DMT friction limit |F_ne + 2 F_pulloff| from a surface-energy variable it sets "
        "only for jkr pairs, so LAMMPS' Coulomb limit is undefined for dmt)");
  }
  // pair granular's mindlin multiplies k_t by its normal model's contact radius: the JKR one
  // under jkr, which the core uses only under mindlin_radius = 'contact_radius'.
  const auto jkr_radius = [&](std::string_view keyword) -> SlotProblem {
    if (!std::holds_alternative<dem::JkrCohesion>(law.cohesion) ||
        law.policies.mindlin_radius != dem::MindlinRadius::overlap) {
      return std::nullopt;
    }
    return fmt::format(
        "LAMMPS driver: tangential '{}' with cohesion 'jkr' is not mapped with mindlin_radius = 'overlap': "
        "pair granular scales k_t with the JKR contact radius a, not sqrt(R* delta) (set model.mindlin_radius = "
        "'contact_radius' to compare)",
        keyword);
  };
  // `mindlin` keeps the slip and loads all of it at today's k_t (mindlin_form 'total');
  // `mindlin/force` keeps the spring force and adds −k_t(a) v_t Δt each step (pg 449–481, the
  // force branch), then caps it as the slip (pg 510–527): mindlin_form 'incremental'.
  const std::string_view mindlin_keyword =
      law.policies.mindlin_form == dem::MindlinForm::incremental ? "mindlin/force" : "mindlin";
  return std::visit(
      Overloaded{
          [&](const dem::NoTangential&) -> SlotProblem {
            // jkr/dmt with linear_nohistory crash with "Neighbor history overflow" (B2,
            // docs/engines.md).
            out.tangential = adhesive ? "linear_history 0 0 0" : "linear_nohistory 0 0";
            return std::nullopt;
          },
          [&](const dem::SpringCoulombTangential& m) -> SlotProblem {
            out.tangential = fmt::format("linear_history {:.17g} {:.17g} {:.17g}", m.stiffness,
                                         m.damping_ratio, m.friction);
            return std::nullopt;
          },
          [&](const dem::MindlinTangential& m) -> SlotProblem {
            out.tangential = fmt::format("{} {:.17g} {:.17g} {:.17g}", mindlin_keyword,
                                         16.0 / 3.0 * m.p.shear_modulus, m.p.damping_ratio,
                                         m.p.friction);
            return jkr_radius(m.kKeyword);
          },
          [&](const dem::Mindlin8GTangential& m) -> SlotProblem {
            out.tangential = fmt::format("{} {:.17g} {:.17g} {:.17g}", mindlin_keyword,
                                         8.0 * m.p.shear_modulus, m.p.damping_ratio, m.p.friction);
            return jkr_radius(m.kKeyword);
          }},
      law.tangential);
}

/// Rolling slot: `none` adds nothing, `spring_dashpot_slider` → `rolling sds k_r γ_r μ_r`.
SlotProblem map_rolling(const dem::RollingModel& rolling, GranularCoeff& out) {
  return std::visit(
      Overloaded{[](const dem::NoRolling&) -> SlotProblem { return std::nullopt; },
                 [&](const dem::SpringDashpotSliderRolling& m) -> SlotProblem {
                   out.extras.push_back(fmt::format("rolling sds {:.17g} {:.17g} {:.17g}",
                                                    m.stiffness, m.damping, m.rolling_friction));
                   return std::nullopt;
                 },
                 [](const auto& m) -> SlotProblem {
                   return not_mapped<std::decay_t<decltype(m)>>(
                       dem::Slot::rolling,
                       "LAMMPS 2021 has only the spring-dashpot-slider rolling model sds");
                 }},
      rolling);
}

/// Model policies: `clamp_tensile` → `limit_damping`. The friction-limit basis, the JKR rupture
/// point and the wall lever arm are LAMMPS' own (run conventions; matched_scene adopts them).
void map_policies(const dem::ContactPolicies& policies, GranularCoeff& out) {
  if (policies.clamp_tensile) out.extras.emplace_back("limit_damping");
}

/// Translates every slot, collecting one reason per slot that cannot be translated.
std::vector<std::string> translate(const dem::PairLaw& law, const PairContext& c,
                                   GranularCoeff& out) {
  std::vector<std::string> problems;
  const auto note = [&](SlotProblem p) {
    if (p) problems.push_back(std::move(*p));
  };
  note(map_normal(law, c, out));
  note(map_cohesion(law, c, out));
  note(map_damping(law, c, out));
  note(map_tangential(law, out));
  note(map_rolling(law.rolling, out));
  map_policies(law.policies, out);
  return problems;
}

}  // namespace

std::vector<std::string> unmapped_sub_models(const dem::PairLaw& law, bool wall, bool per_atom_masses) {
  GranularCoeff ignored;
  PairContext c;
  c.reduced_mass = 1.0;
  c.wall = wall;
  c.per_atom_masses = per_atom_masses;
  return translate(law, c, ignored);
}

GranularCoeff map_pair_law(const dem::PairLaw& law, const PairContext& context) {
  GranularCoeff out;
  const std::vector<std::string> problems = translate(law, context, out);
  if (!problems.empty()) {
    std::string message;
    for (const auto& p : problems) message += (message.empty() ? "" : "; ") + p;
    throw std::invalid_argument(message);
  }
  return out;
}

GranularCoeff map_pair_law(const dem::PairLaw& law, std::optional<double> reduced_mass) {
  PairContext c;
  c.reduced_mass = reduced_mass;
  return map_pair_law(law, c);
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
