// SPDX-License-Identifier: MIT
#include "reference/liggghts/contact_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/contact_model.hpp"

namespace reference::liggghts {
namespace {

/// Relative agreement demanded between the core's pair value and what LIGGGHTS mixes.
constexpr double kMixTolerance = 1e-12;
/// Relative agreement demanded between a case's tangential_damping_ratio and LIGGGHTS' own
/// 2 √(G*/E*): a ratio typed with ten digits maps.
constexpr double kRatioTolerance = 1e-9;

/// True when a and b agree to kMixTolerance.
bool close(double a, double b) noexcept {
  return std::abs(a - b) <= kMixTolerance * std::max(std::abs(a), std::abs(b));
}

/// Appends `reason` unless it is already listed.
void add_reason(std::vector<std::string>& reasons, std::string reason) {
  if (std::find(reasons.begin(), reasons.end(), reason) == reasons.end()) reasons.push_back(std::move(reason));
}

/// True when types a and b (1-based) can touch: at least one is a mobile particle.
bool can_meet(const AtomTypes& types, std::size_t a, std::size_t b) {
  const auto mobile = [&](std::size_t t) { return t >= 1 && t <= types.particles.size() && !types.particles[t - 1].fixed; };
  return mobile(a) || mobile(b);
}

/// Young's modulus and Poisson ratio of type t for `model hertz`, or the reason there are none.
std::optional<std::pair<double, double>> elastic_constants(const cases::Scene& scene, std::size_t material) {
  const dem::MaterialProperties& m = scene.materials.at(material);
  if (m.rigid) return std::make_pair(kRigidYoungsModulus, m.poisson_ratio.value_or(0.0));
  if (!m.youngs_modulus || !m.poisson_ratio) return std::nullopt;
  return std::make_pair(*m.youngs_modulus, *m.poisson_ratio);
}

}  // namespace

std::string model_words(const ContactSettings& c) {
  return fmt::format("model {} tangential {}{}", c.normal, c.tangential,
                     c.rolling.empty() ? "" : " rolling_friction " + c.rolling);
}

double liggghts_effective_modulus(double ya, double nua, double yb, double nub) noexcept {
  return 1.0 / ((1.0 - nua * nua) / ya + (1.0 - nub * nub) / yb);
}

double liggghts_effective_shear_modulus(double ya, double nua, double yb, double nub) noexcept {
  return 1.0 / (2.0 * (2.0 - nua) * (1.0 + nua) / ya + 2.0 * (2.0 - nub) * (1.0 + nub) / yb);
}

ContactMapping map_contacts(const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types) {
  ContactMapping out;
  std::vector<std::string>& reasons = out.reasons;
  const dem::ModelChoice& model = scene.model;
  const std::size_t n = types.count();
  ContactSettings s;
  const bool hertz = model.normal == "hertz";
  // Hertz with LAMMPS' viscoelastic dashpot η = η₀ √(R* δ) m* is hertz/stiffness, whose k_n, k_t and
  // γ_n per type pair are the core's 4/3 E*, 8 G* and η₀ (normal_model_hertz_stiffness.h).
  const bool hertz_stiffness = hertz && model.damping == "lammps_viscoelastic";
  if (model.normal != "hertz" && model.normal != "linear") {
    add_reason(reasons, fmt::format("LIGGGHTS driver: normal = '{}' is not mapped (model hertz and hooke/stiffness "
                                    "express 'hertz' and 'linear')",
                                    model.normal));
  }
  s.normal = hertz_stiffness ? "hertz/stiffness" : hertz ? "hertz" : "hooke/stiffness";
  if (model.cohesion != "none") {
    add_reason(reasons, fmt::format("LIGGGHTS driver: cohesion = '{}' has no LIGGGHTS counterpart here: its sjkr "
                                    "and sjkr2 pull with k·A (k an energy density, A the contact area) and only "
                                    "while the bodies overlap",
                                    model.cohesion));
  }
  if (model.rolling == "constant_torque") {
    s.rolling = "cdt";  // the directional torque of Ai et al.; its form is a convention (matched: projected)
  } else if (model.rolling != "none") {
    add_reason(reasons, fmt::format("LIGGGHTS driver: rolling = '{}' has no LIGGGHTS counterpart: its epsd2 is a "
                                    "torque spring k_t R*² (the tangential stiffness, not a rolling one) fed by the "
                                    "tangent spin, capped at μ_r R* |F_n|, stored without turning with the contact "
                                    "and without a dashpot; epsd adds a dashpot of its own",
                                    model.rolling));
  }
  if (model.pair_lever_arm != dem::PairLeverArm::contact_point) {
    add_reason(reasons, fmt::format("LIGGGHTS driver: pair_lever_arm = '{}' is another code's convention; LIGGGHTS "
                                    "uses r − δ/2 for the torque and the contact-point velocity (contact_point)",
                                    dem::to_string(model.pair_lever_arm)));
  }
  if (model.wall_lever_arm != dem::WallLeverArm::contact_point) {
    add_reason(reasons, fmt::format("LIGGGHTS driver: wall_lever_arm = '{}' is another code's convention; LIGGGHTS' "
                                    "fix wall/gran uses r − δ/2 (contact_point)",
                                    dem::to_string(model.wall_lever_arm)));
  }
  if (model.tangential_history == dem::TangentialHistory::yade_rotate) {
    add_reason(reasons, "LIGGGHTS driver: tangential_history = 'yade_rotate' is YADE's rule; LIGGGHTS adds the "
                        "increment and projects (increment_project)");
  }
  if (model.tangential == "mindlin_8g" && model.mindlin_form == dem::MindlinForm::incremental) {
    add_reason(reasons, "LIGGGHTS driver: mindlin_form = 'incremental' is YADE's; LIGGGHTS' tangential history "
                        "applies −k_t(δ) ς to the whole slip (set mindlin_form = 'total')");
  }
  bool history = true;
  if (model.tangential == "none") {
    history = false;
  } else if (!((hertz && model.tangential == "mindlin_8g") || (!hertz && model.tangential == "spring_coulomb"))) {
    add_reason(reasons, fmt::format("LIGGGHTS driver: tangential = '{}' with normal = '{}' is not expressible: model "
                                    "hertz has k_t = 8 G* √(R* δ) (mindlin_8g), hooke/stiffness a constant k_t "
                                    "(spring_coulomb)",
                                    model.tangential, model.normal));
  }
  s.tangential = history ? "history" : "no_history";
  if (!hertz) s.options.emplace_back("absolute_damping on");
  if (model.clamp_tensile) s.options.emplace_back("limitForce on");

  s.youngs_modulus.assign(n, 0.0);
  s.poisson_ratio.assign(n, 0.0);
  s.restitution.assign(n * n, 1.0);  // e = 1: no dashpot where nothing meets
  for (std::vector<double>* v : {&s.friction, &s.kn, &s.kt, &s.gamman, &s.gammat, &s.rolling_friction}) {
    v->assign(n * n, 0.0);
  }
  if (hertz && !hertz_stiffness) {
    for (std::size_t t = 1; t <= n; ++t) {
      const std::size_t material = types.material_of(t);
      const auto yn = elastic_constants(scene, material);
      if (!yn) {
        add_reason(reasons, fmt::format("LIGGGHTS driver: material '{}' needs youngs_modulus and poisson_ratio: "
                                        "model hertz mixes E* and G* from them per atom type",
                                        scene.materials.at(material).name));
        continue;
      }
      if (!(yn->second >= 0.0 && yn->second <= 0.5)) {
        add_reason(reasons, fmt::format("LIGGGHTS driver: material '{}': Poisson ratio {} is outside LIGGGHTS' "
                                        "[0, 0.5]",
                                        scene.materials.at(material).name, yn->second));
      }
      s.youngs_modulus[t - 1] = yn->first;
      s.poisson_ratio[t - 1] = yn->second;
      if (yn->first > 1e9) s.hard_particles = true;
      if (yn->first < 5e6) s.soft_particles = true;
    }
  }
  // Whether the tangential dashpot is on: one switch for the whole deck.
  std::optional<bool> tangential_dashpot;
  const auto want_tangential_dashpot = [&](bool on, const std::string& why) {
    if (tangential_dashpot && *tangential_dashpot != on) {
      add_reason(reasons, "LIGGGHTS driver: tangential_damping is one switch for all pairs, but " + why);
    }
    tangential_dashpot = on;
  };
  for (std::size_t a = 1; a <= n; ++a) {
    for (std::size_t b = a; b <= n; ++b) {
      if (!can_meet(types, a, b)) continue;
      const std::size_t ma = types.material_of(a);
      const std::size_t mb = types.material_of(b);
      const dem::PairLaw& law = table.law(ma, mb);
      // No single m* with diameters per atom: the one dashpot that needs it is refused below.
      const double m_star = types.reduced_mass(a, b).value_or(0.0);
      const std::string pair = fmt::format("types {}-{} ('{}'-'{}')", a, b, scene.materials.at(ma).name,
                                           scene.materials.at(mb).name);
      double e = 1.0, mu = 0.0, kn = 0.0, kt = 0.0, gn = 0.0, ratio = 0.0, mu_r = 0.0;
      if (const auto* rolling = std::get_if<dem::ConstantTorqueRolling>(&law.rolling)) mu_r = rolling->rolling_friction;
      std::visit(
          [&](const auto& normal) {
            using N = std::decay_t<decltype(normal)>;
            if constexpr (std::is_same_v<N, dem::HertzNormal>) {
              if (hertz_stiffness) {
                kn = dem::laws::hertz_secant_stiffness_at_radius(normal.effective_modulus, 1.0);  // F = kn √(R* δ) δ
                return;
              }
              const double ya = s.youngs_modulus[a - 1], yb = s.youngs_modulus[b - 1];
              if (ya > 0.0 && yb > 0.0 &&
                  !close(liggghts_effective_modulus(ya, s.poisson_ratio[a - 1], yb, s.poisson_ratio[b - 1]),
                         normal.effective_modulus)) {
                add_reason(reasons, fmt::format("LIGGGHTS driver: {}: E* = {:.6g} Pa is not what LIGGGHTS mixes from "
                                                "the types' E and ν (a [[pairs]] override or another mixing rule)",
                                                pair, normal.effective_modulus));
              }
            } else if constexpr (std::is_same_v<N, dem::LinearNormal>) {
              kn = normal.stiffness;
            }
          },
          law.normal);
      std::visit(
          [&](const auto& damping) {
            using D = std::decay_t<decltype(damping)>;
            if constexpr (std::is_same_v<D, dem::NoDamping>) {
              e = 1.0;
              gn = 0.0;
            } else if constexpr (std::is_same_v<D, dem::TsujiDamping>) {
              if (!hertz) {
                add_reason(reasons, "LIGGGHTS driver: damping = 'tsuji' on a linear spring has no hooke/stiffness "
                                    "counterpart (its dashpot would depend on δ)");
              }
              e = damping.restitution;
              if (!(e > 0.05)) {
                add_reason(reasons, fmt::format("LIGGGHTS driver: {}: restitution {} is outside LIGGGHTS' (0.05, 1]",
                                                pair, e));
              }
            } else if constexpr (std::is_same_v<D, dem::RestitutionDamping>) {
              if (types.per_atom_diameter && !hertz) {
                add_reason(reasons, fmt::format("LIGGGHTS driver: more than {} (material, radius, fixed) classes: the "
                                                "restitution dashpot β √(m* k) of hooke/stiffness needs one m* per "
                                                "type pair",
                                                kMaxParticleTypes));
              }
              if (hertz) {
                add_reason(reasons, "LIGGGHTS driver: damping = 'restitution' on Hertz (η = β √(m* k), k the "
                                    "tangent stiffness) is √(6/5) times LIGGGHTS' Hertz dashpot; use 'tsuji', "
                                    "which is LIGGGHTS' dashpot");
              }
              gn = damping.factor * std::sqrt(m_star * kn);
            } else if constexpr (std::is_same_v<D, dem::LammpsViscoelasticDamping>) {
              gn = damping.rate_per_length;  // η₀ of hertz/stiffness; on a linear spring refused here
              if (!hertz) {
                add_reason(reasons, "LIGGGHTS driver: damping = 'lammps_viscoelastic' on a linear spring has no "
                                    "LIGGGHTS counterpart (hertz/stiffness carries it on Hertz)");
              }
            } else if constexpr (std::is_same_v<D, dem::LammpsVelocityDamping>) {
              if (hertz) {
                add_reason(reasons, "LIGGGHTS driver: a constant dashpot (lammps_velocity) on Hertz has no "
                                    "LIGGGHTS counterpart");
              }
              gn = damping.damping;
            } else {
              add_reason(reasons, fmt::format("LIGGGHTS driver: damping = '{}' is not mapped (LIGGGHTS takes a "
                                              "restitution coefficient, or a dashpot in kg/s with hooke/stiffness)",
                                              D::kKeyword));
            }
          },
          law.damping);
      std::visit(
          [&](const auto& tangential) {
            using T = std::decay_t<decltype(tangential)>;
            if constexpr (std::is_same_v<T, dem::SpringCoulombTangential>) {
              kt = tangential.stiffness;
              mu = tangential.friction;
              ratio = tangential.damping_ratio;
            } else if constexpr (std::is_same_v<T, dem::Mindlin8GTangential>) {
              mu = tangential.p.friction;
              ratio = tangential.p.damping_ratio;
              if (hertz_stiffness) {
                kt = tangential.stiffness_per_radius();  // k_t = kt √(R* δ)
                return;
              }
              const double ya = s.youngs_modulus[a - 1], yb = s.youngs_modulus[b - 1];
              if (ya > 0.0 && yb > 0.0 &&
                  !close(liggghts_effective_shear_modulus(ya, s.poisson_ratio[a - 1], yb, s.poisson_ratio[b - 1]),
                         tangential.p.shear_modulus)) {
                add_reason(reasons, fmt::format("LIGGGHTS driver: {}: G* = {:.6g} Pa is not what LIGGGHTS mixes from "
                                                "the types' E and ν",
                                                pair, tangential.p.shear_modulus));
              }
            }
          },
          law.tangential);
      // The tangential dashpot: hooke/stiffness takes it per pair (γ_t = ratio γ_n); model hertz derives it from e
      // as γ_t/γ_n = √(8G*/(2E*)), so the case's ratio must be that (or the dashpot off).
      if (history && !hertz_stiffness) {
        if (hertz && e < 1.0) {
          const auto* normal = std::get_if<dem::HertzNormal>(&law.normal);
          const auto* mindlin = std::get_if<dem::Mindlin8GTangential>(&law.tangential);
          if (normal != nullptr && mindlin != nullptr) {
            const double implied = 2.0 * std::sqrt(mindlin->p.shear_modulus / normal->effective_modulus);
            if (ratio == 0.0) {
              want_tangential_dashpot(false, "some pairs have a tangential dashpot and some none");
            } else if (std::abs(ratio - implied) <= kRatioTolerance * implied) {
              want_tangential_dashpot(true, "some pairs have a tangential dashpot and some none");
            } else {
              add_reason(reasons, fmt::format("LIGGGHTS driver: {}: tangential_damping_ratio {} is not LIGGGHTS' "
                                              "2 √(G*/E*) = {:.17g} (model hertz derives the tangential dashpot "
                                              "from e); set it to that or to 0",
                                              pair, ratio, implied));
            }
          }
        }
      }
      const std::size_t ab = (a - 1) * n + (b - 1);
      const std::size_t ba = (b - 1) * n + (a - 1);
      for (const std::size_t k : {ab, ba}) {
        s.restitution[k] = e;
        s.friction[k] = mu;
        s.kn[k] = kn;
        s.kt[k] = kt;
        s.gamman[k] = gn;
        s.gammat[k] = ratio * gn;
        s.rolling_friction[k] = mu_r;
      }
    }
  }
  if (!history || (tangential_dashpot && !*tangential_dashpot)) s.options.emplace_back("tangential_damping off");
  if (reasons.empty()) out.settings = std::move(s);
  return out;
}

}  // namespace reference::liggghts
