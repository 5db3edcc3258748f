// SPDX-License-Identifier: MIT
#include "reference/yade/model_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"
#include "reference/common/wall_state.hpp"

namespace reference::yade {
namespace {

/// std::visit helper: one lambda per alternative.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

/// Keyword of a sub-model value, for messages.
template <class Model>
std::string_view keyword_of(const Model&) {
  return std::decay_t<Model>::kKeyword;
}

/// YADE text of a sub-model value, from the registry row it belongs to.
template <class Model>
std::string_view yade_text_of(const Model&) {
  return std::decay_t<Model>::kYade;
}

/// What one slot of one pair maps to: the pair parameters it sets, or the reason it cannot.
struct SlotMapping {
  bool ok = false;
  std::string reason;
  std::string convention;  ///< "<keyword>: <registry YADE text>"
};

/// A slot whose sub-model has no YADE mapping, with the reason.
SlotMapping refused(std::string reason) { return {false, std::move(reason), ""}; }

/// A slot whose sub-model has no YADE mapping in this driver.
SlotMapping unmapped(std::string_view slot, std::string_view keyword) {
  return refused(fmt::format("YADE driver: {} model '{}' is not mapped", slot, keyword));
}

/// A mapped slot with its registry text.
template <class Model>
SlotMapping mapped(const Model& m) {
  return {true, "", fmt::format("{}: {}", keyword_of(m), yade_text_of(m))};
}

/// The law family the normal and damping slots of a pair ask for, or empty when unmappable.
std::optional<YadeLaw> law_of(const dem::PairLaw& law) {
  if (std::holds_alternative<dem::LinearNormal>(law.normal)) {
    if (std::holds_alternative<dem::NoDamping>(law.damping)) return YadeLaw::frict;
    if (std::holds_alternative<dem::RestitutionDamping>(law.damping) ||
        std::holds_alternative<dem::YadeFrictViscoDamping>(law.damping)) {
      return YadeLaw::frict_visco;
    }
    return std::nullopt;
  }
  if (std::holds_alternative<dem::HertzNormal>(law.normal)) return YadeLaw::mindlin;
  return std::nullopt;
}

/// Normal slot → kn (linear) or Mindlin's own E*, R* (hertz).
SlotMapping map_normal(const dem::NormalModel& model, YadePairParameters& pair) {
  return std::visit(
      Overloaded{[&](const dem::LinearNormal& m) {
                   pair.normal_stiffness = m.stiffness;
                   return mapped(m);
                 },
                 [&](const dem::HertzNormal& m) { return mapped(m); },
                 [](const auto& m) { return unmapped("normal", keyword_of(m)); }},
      model);
}

/// Damping slot → betan. FrictViscoPhys: cn = 2 betan √(m̄ kn) and ours η = β √(m* k), so
/// betan = β/2. Mindlin: cn = 2 β_n √(m̄ k_n) with the tangent k_n, as yade_mindlin.
SlotMapping map_damping(const dem::DampingModel& model, YadeLaw law, bool clamp_tensile,
                        YadePairParameters& pair) {
  const bool linear = law != YadeLaw::mindlin;
  return std::visit(
      Overloaded{
          [&](const dem::NoDamping& m) { return mapped(m); },
          [&](const dem::RestitutionDamping& m) {
            if (!linear) {
              return refused(
                  "YADE driver: damping 'restitution' with the Hertz normal model is not mapped "
                  "(Mindlin clips F_n ≥ 0 and fits β_n for the clipped law; use 'yade_mindlin')");
            }
            pair.damping_ratio = 0.5 * m.factor;
            return mapped(m);
          },
          [&](const dem::YadeFrictViscoDamping& m) {
            if (!linear) return refused("YADE driver: damping 'yade_frictvisco' needs the linear normal model");
            pair.damping_ratio = 0.5 * m.factor;
            return mapped(m);
          },
          [&](const dem::YadeMindlinDamping& m) {
            if (linear) return refused("YADE driver: damping 'yade_mindlin' needs the Hertz normal model");
            pair.damping_ratio = m.damping_ratio;
            return mapped(m);
          },
          [&](const dem::TsujiDamping& m) {
            if (linear) return refused("YADE driver: damping 'tsuji' needs the Hertz normal model");
            if (!clamp_tensile) {
              return refused(
                  "YADE driver: damping 'tsuji' with clamp_tensile = false is not mapped: YADE's "
                  "Mindlin has the same dashpot (c_n = 2 β_n √(m k_n), k_n = 3/2 k_no √δ, so "
                  "β_n = α/(2√1.5)) but Law2_ScGeom_MindlinPhys_Mindlin clips the normal force at "
                  "≥ 0, which tsuji's exact restitution does not (set clamp_tensile = true to compare "
                  "the clipped law: ε = 0.5 then rebounds at 0.5503)");
            }
            pair.damping_ratio = m.factor / (2.0 * std::sqrt(1.5));
            return mapped(m);
          },
          [](const auto& m) { return unmapped("damping", keyword_of(m)); }},
      model);
}

/// Tangential slot → ks and friction angle atan μ (CundallStrack laws); Mindlin's own k_s.
SlotMapping map_tangential(const dem::TangentialModel& model, YadeLaw law, YadePairParameters& pair) {
  return std::visit(
      Overloaded{
          [&](const dem::NoTangential& m) { return mapped(m); },
          [&](const dem::SpringCoulombTangential& m) {
            if (law == YadeLaw::mindlin) {
              return refused("YADE driver: tangential 'spring_coulomb' with the Hertz normal model "
                             "is not mapped (Mindlin's shear stiffness is 8G*√(R*δ); use 'mindlin_8g')");
            }
            if (m.damping_ratio != 0.0) {
              return refused(
                  "YADE driver: tangential 'spring_coulomb' with tangential_damping_ratio ≠ 0 is "
                  "not mapped (YADE's CundallStrack laws have no tangential dashpot)");
            }
            pair.shear_stiffness = m.stiffness;
            pair.friction_angle = std::atan(m.friction);
            return mapped(m);
          },
          [&](const dem::Mindlin8GTangential& m) {
            if (law != YadeLaw::mindlin) {
              return refused("YADE driver: tangential 'mindlin_8g' needs the Hertz normal model");
            }
            if (m.p.damping_ratio != 0.0) {
              return refused("YADE driver: tangential 'mindlin_8g' with tangential_damping_ratio ≠ 0 "
                             "is not mapped (Mindlin's betas = betan while sticking)");
            }
            pair.friction_angle = std::atan(m.p.friction);
            return mapped(m);
          },
          [](const auto& m) { return unmapped("tangential", keyword_of(m)); }},
      model);
}

/// Cohesion slot: `none`, or DMT through Mindlin's adhesion (gamma); JKR has no YADE law.
SlotMapping map_cohesion(const dem::CohesionModel& model, YadeLaw law, double& surface_energy,
                         YadePairParameters& pair) {
  return std::visit(
      Overloaded{[](const dem::NoCohesion& m) { return mapped(m); },
                 [&](const dem::LinearCohesion& m) {
                   if (law == YadeLaw::mindlin) return refused("YADE driver: cohesion 'linear' needs the linear normal model");
                   pair.cohesive_stiffness = m.stiffness;
                   return mapped(m);
                 },
                 [&](const dem::DmtCohesion& m) {
                   if (law != YadeLaw::mindlin) return refused("YADE driver: cohesion 'dmt' needs the Hertz normal model");
                   if (surface_energy != 0.0 && surface_energy != m.surface_energy) {
                     return refused(
                         "YADE driver: cohesion 'dmt' with different surface energies per pair is "
                         "not mapped (Ip2_FrictMat_FrictMat_MindlinPhys.gamma is one value for all pairs)");
                   }
                   surface_energy = m.surface_energy;
                   return mapped(m);
                 },
                 [](const dem::JkrCohesion&) { return refused("YADE 2023.02a has no JKR law"); },
                 [](const auto& m) { return unmapped("cohesion", keyword_of(m)); }},
      model);
}

/// Rolling slot: only `none`.
SlotMapping map_rolling(const dem::RollingModel& model) {
  return std::visit(Overloaded{[](const dem::NoRolling& m) { return mapped(m); },
                               [](const auto& m) { return unmapped("rolling", keyword_of(m)); }},
                    model);
}

/// Adds `reason` once.
void add_reason(std::vector<std::string>& reasons, const std::string& reason) {
  for (const auto& r : reasons) {
    if (r == reason) return;
  }
  reasons.push_back(reason);
}

/// Warning about YADE's dashpot velocity, which is not exactly eq 3.10's.
std::string dashpot_warning() {
  return "damping via Law2_ScGeom_FrictViscoPhys_CundallStrackVisco: YADE's dashpot "
         "uses the relative translational velocity scaled by α = (r_p + r_q)/(r_p + r_q − δ) "
         "(2r/(2r − δ) against a wall; ScGeom::getIncidentVel with avoidGranularRatcheting, not "
         "switchable), so its viscous force is α·η·u_n instead of eq 3.10's η·u_n — larger by the "
         "relative amount δ/(r_p + r_q − δ); it also acts at δ = 0 exactly, where the core has no "
         "contact. The spring and η itself (m* = the mobile mass against a fixed partner) are "
         "exact; the force is not clamped at zero, as in eq 3.10 (matched runs use the core's "
         "damping 'yade_frictvisco', which has α)";
}

/// Warning about YADE's tangential kinematics, which differ from eq 3.9's.
std::string tangential_warning() {
  return "tangential: YADE integrates the shear force incrementally, F_s −= k_s·Δu_s, with "
         "Δu_s = [α (u_p − u_q) − (r_p ω_p + r_q ω_q) × n]_t Δt (α as the dashpot's; full radii, "
         "not r − δ/2; Ig2 noRatch/avoidGranularRatcheting = True), rotates the stored force by "
         "n_old × n_new and the mean spin about n without re-projecting it, and scales it back "
         "to μ·|F_n| when it exceeds the cap (Cundall–Strack truncation). The torque lever arm is "
         "r − δ/2 (as the core's contact_point policy). In gross sliding only the direction of "
         "Δu_s matters, so the force equals the core's";
}

/// E* from the scene materials as YADE's Mindlin Ip2 forms it; empty when E or ν is missing.
std::optional<double> mindlin_modulus(const cases::Scene& scene, std::size_t a, std::size_t b) {
  const auto& ma = scene.materials[a];
  const auto& mb = scene.materials[b];
  if (!ma.youngs_modulus || !ma.poisson_ratio || !mb.youngs_modulus || !mb.poisson_ratio) {
    return std::nullopt;
  }
  return yade_effective_modulus(*ma.youngs_modulus, *ma.poisson_ratio, *mb.youngs_modulus,
                                *mb.poisson_ratio);
}

/// Checks that YADE's Mindlin, which mixes E* itself, gets the pair's E* of the core.
void check_mindlin_modulus(const cases::Scene& scene, const dem::PairLaw& law, std::size_t a,
                           std::size_t b, std::vector<std::string>& reasons) {
  const auto* hertz = std::get_if<dem::HertzNormal>(&law.normal);
  if (hertz == nullptr) return;
  const auto yade = mindlin_modulus(scene, a, b);
  if (!yade) {
    add_reason(reasons, fmt::format("YADE driver: Hertz–Mindlin needs youngs_modulus and "
                                    "poisson_ratio of materials '{}' and '{}'",
                                    scene.materials[a].name, scene.materials[b].name));
    return;
  }
  if (std::abs(*yade - hertz->effective_modulus) > 1e-14 * hertz->effective_modulus) {
    add_reason(reasons, fmt::format(
        "YADE driver: Hertz–Mindlin forms E* from the materials ({:.17g} Pa for '{}'–'{}'), but "
        "the pair table gives {:.17g} Pa (a pair override cannot be passed to "
        "Ip2_FrictMat_FrictMat_MindlinPhys)",
        *yade, scene.materials[a].name, scene.materials[b].name, hertz->effective_modulus));
  }
}

/// Walls other than mesh facets: YADE's utils.wall is an axis-aligned, immobile plane.
void check_walls(const cases::Scene& scene, std::vector<std::string>& reasons) {
  for (const auto& w : scene.walls) {
    // Gone when the run starts, the script leaves it out; a mesh's facets are check_meshes' part.
    if (!wall_in_run(w) || w.mesh) continue;
    if (w.shape != dem::WallShape::plane) {
      add_reason(reasons, fmt::format("YADE driver: wall '{}' is a {}; only plane walls (utils.wall) and meshes "
                                      "(utils.facet) are mapped",
                                      w.name, cases::wall_shape_name(w)));
      continue;
    }
    if (w.removed_at) {
      add_reason(reasons, fmt::format("YADE driver: wall '{}' is removed during the run; that is not mapped", w.name));
    }
    if (wall_axis(w.normal).axis < 0) {
      add_reason(reasons, fmt::format("YADE driver: wall '{}' is not normal to a coordinate axis "
                                      "(utils.wall is axis-aligned)", w.name));
    }
    if (wall_moves(w)) {
      add_reason(reasons, fmt::format("YADE driver: moving wall '{}' is not mapped", w.name));
    }
  }
}

/// Meshes, each judged by its first facet (the facets share motion and removal): immobile and
/// standing through the run for utils.facet, and not under FrictViscoPhys, whose dashpot scales by
/// α = (r₁ + r₂)/(r₁ + r₂ − δ), which a facet makes 3r/(3r − δ) (Ig2_Facet_Sphere_ScGeom: r₁ = 2r)
/// where the core's `yade_frictvisco` has YADE's plane-wall 2r/(2r − δ). Traced walls: not a
/// facet, nor a wall the script leaves out.
void check_meshes(const cases::Scene& scene, YadeLaw law, std::vector<std::string>& reasons) {
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const cases::WallSpec* first = first_facet(scene, m);
    if (first == nullptr || !wall_in_run(*first)) continue;  // gone when the run starts: left out
    const std::string& mesh = scene.meshes[m].name;
    if (first->removed_at) {
      add_reason(reasons, fmt::format("YADE driver: mesh '{}' is removed during the run; that is not mapped", mesh));
    }
    if (wall_moves(*first)) add_reason(reasons, fmt::format("YADE driver: moving mesh '{}' is not mapped", mesh));
    if (law == YadeLaw::frict_visco) {
      add_reason(reasons, fmt::format("YADE driver: mesh '{}' under the restitution dashpot (FrictViscoPhys) is "
                                      "not mapped: against a facet YADE scales the dashpot by α = 3r/(3r − δ) "
                                      "(the facet's radius is 2r), the core's yade_frictvisco by a plane "
                                      "wall's 2r/(2r − δ)",
                                      mesh));
    }
  }
  for (const auto& [particle, wall] : scene.output.trace_walls) {
    if (wall < scene.walls.size() && !wall_in_run(scene.walls[wall])) {
      add_reason(reasons, fmt::format("YADE driver: output.trace_walls names wall '{}', which is removed before the "
                                      "run starts (the script leaves it out)",
                                      scene.walls[wall].name));
    } else if (wall < scene.walls.size() && scene.walls[wall].mesh) {
      add_reason(reasons, fmt::format("YADE driver: output.trace_walls names facet '{}' of a mesh; only a plane "
                                      "wall's overlap and force are traced",
                                      scene.walls[wall].name));
    }
  }
}

/// True when wall `w` can carry a tangential force: the model has a tangential law and some
/// mobile material meeting the wall mixes with the wall's material to μ > 0. With μ = 0 the
/// Coulomb cap is zero in YADE's Mindlin law and in the core alike, so the wall is frictionless in
/// both and YADE's lever-arm convention (r − δ) never applies a torque.
bool wall_has_friction(const cases::Scene& scene, const dem::PairTable& table, const std::vector<bool>& meets_walls,
                       const cases::WallSpec& w) {
  if (scene.model.tangential == "none") return false;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    if (!meets_walls[m]) continue;
    const auto& friction = table.properties(m, w.material).friction;
    if (!friction || *friction != 0.0) return true;
  }
  return false;
}

/// G* of the pair's Mindlin tangential law, or nothing without one.
std::optional<double> mindlin_shear_modulus(const dem::PairLaw& law) {
  const auto* mindlin = std::get_if<dem::Mindlin8GTangential>(&law.tangential);
  if (mindlin == nullptr) return std::nullopt;
  return mindlin->p.shear_modulus;
}

/// Hertz–Mindlin walls: one compensated YADE material per plane wall and one per mesh
/// (compensated_wall_material), the same for every particle material that meets it, and
/// MatchMaker rows copied from the wall's scene material. Adds a reason when a wall cannot be
/// expressed.
void map_mindlin_walls(const cases::Scene& scene, const dem::PairTable& table, YadeModelMapping& out) {
  std::vector<bool> meets_walls(scene.materials.size(), false);
  for (const auto& p : scene.particles) {
    if (!p.fixed) meets_walls[p.material] = true;
  }
  const std::size_t base_pairs = out.pairs.size();
  std::map<std::size_t, std::size_t> mesh_material;  // mesh index → its compensated O.materials id
  for (std::size_t k = 0; k < scene.walls.size(); ++k) {
    const cases::WallSpec& w = scene.walls[k];
    if (!wall_in_run(w)) continue;
    const bool facet = w.mesh.has_value();
    if (facet) {
      if (const auto known = mesh_material.find(*w.mesh); known != mesh_material.end()) {
        out.wall_material_ids[k] = known->second;
        continue;
      }
    }
    const std::string name = facet ? scene.meshes.at(*w.mesh).name : w.name;
    if (out.surface_energy != 0.0) {
      add_reason(out.reasons, fmt::format("YADE driver: Hertz–Mindlin DMT adhesion against wall '{}' "
                                          "is not mapped (Ip2_FrictMat_FrictMat_MindlinPhys takes "
                                          "4πRγ with the wall's R = {})", name, facet ? "2r/3" : "r/2"));
      continue;
    }
    const bool friction = wall_has_friction(scene, table, meets_walls, w);
    if (friction && !facet) {
      // Measured on a 30° Hertz–Mindlin impact (stick, then slip): v_t after 1.1 % and ω after
      // 0.4 % away from the core, natively and in matched numerics alike.
      add_reason(out.reasons, fmt::format(
          "YADE driver: Hertz–Mindlin friction against wall '{}' is not mapped: YADE 2023.02a's "
          "wall geometry puts the contact point on the wall plane, so Law2_ScGeom_MindlinPhys_Mindlin "
          "(applyForceAtContactPoint) turns the sphere with lever arm r − δ, a convention the core "
          "has no policy for (wall_lever_arm is r − δ/2 or r), and scales the shear increment's "
          "translational part by α = 2r/(2r − δ) (ScGeom noRatch); the normal contact maps exactly "
          "(tangential = 'none', or a wall material whose friction mixes to μ = 0)", w.name));
      continue;
    }
    // Ig2_Wall_Sphere_ScGeom gives Mindlin R = r/2, Ig2_Facet_Sphere_ScGeom R = 2r/3; the case's
    // is r.
    const double radius_ratio = facet ? 1.5 : 2.0;
    std::optional<YadeWallMaterial> chosen;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
      if (!meets_walls[m]) continue;
      const dem::PairLaw& law = table.law(m, w.material);
      const auto* hertz = std::get_if<dem::HertzNormal>(&law.normal);
      if (hertz == nullptr) continue;
      // Frictionless (plane walls with friction were refused above): only k_no matters, so
      // ν′ = ν of the sphere. A mesh with friction needs k_so too.
      const auto wall = compensated_wall_material(out.material_young[m], out.material_poisson[m],
                                                  hertz->effective_modulus,
                                                  friction ? mindlin_shear_modulus(law) : std::nullopt, radius_ratio);
      if (!wall) {
        add_reason(out.reasons, fmt::format("YADE driver: no YADE material gives wall '{}' the "
                                            "Hertz–Mindlin stiffness of R* = r against material '{}'",
                                            name, scene.materials[m].name));
        chosen.reset();
        break;
      }
      if (chosen && (chosen->young != wall->young || chosen->poisson != wall->poisson)) {
        add_reason(out.reasons, fmt::format("YADE driver: wall '{}' meets particle materials that need "
                                            "different compensating wall materials (one YADE material "
                                            "per wall)", name));
        chosen.reset();
        break;
      }
      chosen = wall;
    }
    if (!chosen) continue;
    chosen->base = w.material;
    const std::size_t id = scene.materials.size() + out.wall_materials.size();
    out.wall_materials.push_back(*chosen);
    out.wall_material_ids[k] = id;
    if (facet) mesh_material[*w.mesh] = id;
    for (std::size_t i = 0; i < base_pairs; ++i) {
      const YadePairParameters p = out.pairs[i];
      if (p.material_a != w.material && p.material_b != w.material) continue;
      YadePairParameters copy = p;
      copy.material_a = p.material_a == w.material ? p.material_b : p.material_a;
      copy.material_b = id;
      out.pairs.push_back(copy);
    }
  }
  if (out.wall_materials.size() > mesh_material.size()) {  // a plane wall's material among them
    out.conventions["wall contact radius"] =
        "Ig2_Wall_Sphere_ScGeom gives the wall the sphere's radius, so Mindlin takes R = r/2; each "
        "wall gets its own YADE material whose young and poisson make YADE's E* and G* √2 times the "
        "case's, so k_no = 4/3 E* √r and k_so = 8 G* √r as for R* = r (exact to round-off; a "
        "rigid wall's young is negative)";
  }
  if (mesh_material.size() > 0) {
    out.conventions["facet contact radius"] =
        "Ig2_Facet_Sphere_ScGeom gives a facet twice the sphere's radius, so Mindlin takes R = 2r/3; "
        "each mesh gets its own YADE material whose young and poisson make YADE's E* and G* √(3/2) "
        "times the case's, so k_no = 4/3 E* √r and k_so = 8 G* √r as for R* = r";
  }
}

}  // namespace

std::optional<YadeWallMaterial> compensated_wall_material(double young_s, double poisson_s,
                                                          double effective_modulus,
                                                          std::optional<double> effective_shear_modulus,
                                                          double radius_ratio) {
  const double scale = std::sqrt(radius_ratio);
  const double c = 1.0 / (scale * effective_modulus) - (1.0 - poisson_s * poisson_s) / young_s;
  YadeWallMaterial w;
  if (effective_shear_modulus) {
    const double shear_s = young_s / (2.0 * (1.0 + poisson_s));
    const double d = 1.0 / (scale * *effective_shear_modulus) - (2.0 - poisson_s) / shear_s;
    const double rho = d / c;
    w.poisson = (rho - 4.0) / (rho - 2.0);
  } else {
    w.poisson = poisson_s;
  }
  w.young = (1.0 - w.poisson * w.poisson) / c;
  if (!std::isfinite(w.young) || !std::isfinite(w.poisson) || w.young == 0.0 || w.poisson == -1.0) {
    return std::nullopt;
  }
  return w;
}

double yade_mixed_damping_ratio(double a, double b) noexcept {
  if (a != 0.0 && b != 0.0) return (a + b) / 2.0;
  return b == 0.0 ? a : b;
}

double yade_effective_modulus(double young_a, double poisson_a, double young_b,
                              double poisson_b) noexcept {
  return young_a * young_b /
         ((1.0 - poisson_a * poisson_a) * young_b + (1.0 - poisson_b * poisson_b) * young_a);
}

WallAxis wall_axis(const cases::Vector3& n) noexcept {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    if (n[k] != 0.0 && n[i] == 0.0 && n[j] == 0.0) return {k, n[k] > 0.0 ? 1 : -1};
  }
  return {};
}

YadeModelMapping map_contact_model(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  YadeModelMapping out;
  const dem::PairTable* table = nullptr;
  try {
    table = &prepared.pair_table();
  } catch (const dem::ModelError& e) {
    out.reasons.push_back(fmt::format("YADE driver: the contact model cannot be built: {}", e.what()));
    return out;
  }
  const std::size_t n = table->material_count();
  out.material_damping_ratio.assign(n, 0.0);
  out.material_young.assign(n, 1.0);
  out.material_poisson.assign(n, 0.25);
  std::optional<YadeLaw> family;
  std::vector<bool> particle_material(n, false);
  for (const auto& p : scene.particles) particle_material[p.material] = true;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a; b < n; ++b) {
      if (!table->interacts(a, b)) continue;  // two rigid walls' materials: never in contact
      const dem::PairLaw& law = table->law(a, b);
      const auto pair_family = law_of(law);
      YadePairParameters pair{a, b};
      SlotMapping slots[5];
      slots[0] = map_normal(law.normal, pair);
      const YadeLaw f = pair_family.value_or(YadeLaw::frict);
      slots[1] = pair_family ? map_damping(law.damping, f, law.policies.clamp_tensile, pair)
                             : (slots[0].ok ? unmapped("damping", std::visit([](const auto& m) { return keyword_of(m); }, law.damping))
                                            : SlotMapping{true, "", ""});
      slots[2] = map_tangential(law.tangential, f, pair);
      slots[3] = map_cohesion(law.cohesion, f, out.surface_energy, pair);
      slots[4] = map_rolling(law.rolling);
      const char* names[] = {"normal", "damping", "tangential", "cohesion", "rolling"};
      bool ok = true;
      for (std::size_t s = 0; s < 5; ++s) {
        if (!slots[s].ok) {
          add_reason(out.reasons, slots[s].reason);
          ok = false;
        } else if (!slots[s].convention.empty()) {
          out.conventions[fmt::format("contact {}", names[s])] = slots[s].convention;
        }
      }
      if (!ok || !pair_family) continue;
      if (family && *family != *pair_family) {
        add_reason(out.reasons, "YADE driver: material pairs need different YADE law families");
        continue;
      }
      family = pair_family;
      // Sphere–sphere contacts take E* from the two materials as YADE mixes them; a material no
      // particle uses meets spheres only as a wall, whose YADE material is made for it.
      if (particle_material[a] && particle_material[b]) check_mindlin_modulus(scene, law, a, b, out.reasons);
      out.pairs.push_back(pair);
      if (a == b) out.material_damping_ratio[a] = pair.damping_ratio;
    }
  }
  if (!out.reasons.empty()) return out;
  out.law = family.value_or(YadeLaw::frict);
  out.viscous = out.law == YadeLaw::frict_visco;
  check_walls(scene, out.reasons);
  check_meshes(scene, out.law, out.reasons);
  if (std::any_of(scene.walls.begin(), scene.walls.end(), [](const auto& w) { return w.mesh && wall_in_run(w); })) {
    out.conventions["mesh facets"] =
        "each facet is a utils.facet of its own (Ig2_Facet_Sphere_ScGeom: the nearest point of the "
        "triangle — face, edge or corner — and the contact point x − (r − δ/2) n, its velocity without "
        "α, as the core's contact_point arm). YADE meets every facet within reach: a sphere on an "
        "edge or corner two facets share, or within √(2rδ) of a flat seam, is pushed by each of "
        "them, and a contact that passes to the next facet starts a new shear history; the core "
        "counts one contact per surface point and hands the history over (docs/walls.md). The runs "
        "agree while no sphere touches an edge or corner that two facets share";
  }
  for (const auto& p : out.pairs) out.python_cohesion = out.python_cohesion || p.cohesive_stiffness != 0.0;
  if (out.python_cohesion) {
    // The per-step Python force acts between spheres only: a wall may take part only when its
    // material pairs with every particle material without cohesion (k_c = 0).
    for (const auto& w : scene.walls) {
      if (!wall_in_run(w)) continue;
      bool cohesive_wall = false;
      for (std::size_t m = 0; m < n; ++m) {
        const auto* linear = std::get_if<dem::LinearCohesion>(&table->law(m, w.material).cohesion);
        cohesive_wall = cohesive_wall || (particle_material[m] && linear != nullptr && linear->stiffness != 0.0);
      }
      if (cohesive_wall) {
        add_reason(out.reasons, "YADE driver: linear cohesion against walls is not mapped (the "
                                "per-step Python force handles sphere pairs only; give the wall a "
                                "material with cohesive_stiffness = 0)");
      }
    }
    for (const auto& p : scene.particles) out.aabb_enlarge = std::max(out.aabb_enlarge, p.effect_radius / p.radius);
    out.warnings.push_back(
        "cohesion 'linear': not built into YADE; the script adds F = k_c (r̂_p + r̂_q − d) along "
        "the line of centres with O.forces.addF in a PyRunner between InteractionLoop and "
        "NewtonIntegrator, over the collider's potential interactions (sphere boxes enlarged by the "
        "largest r̂/r): exact, O(N), but Python — several times slower per step than YADE's own "
        "laws; YADE's Coulomb cap does not see it");
  }
  out.wall_material_ids.resize(scene.walls.size());
  for (std::size_t k = 0; k < scene.walls.size(); ++k) out.wall_material_ids[k] = scene.walls[k].material;
  if (out.law == YadeLaw::mindlin) {
    for (std::size_t k = 0; k < n; ++k) {
      out.material_young[k] = scene.materials[k].youngs_modulus.value_or(1.0);
      out.material_poisson[k] = scene.materials[k].poisson_ratio.value_or(0.25);
    }
    map_mindlin_walls(scene, *table, out);
  }
  if (out.viscous && scene.model.clamp_tensile) {
    out.reasons.push_back(
        "YADE driver: damping 'restitution' with clamp_tensile = true is not mapped yet "
        "(ViscElMat clamps, but takes the dashpot per material, not per particle pair's m*)");
  }
  bool damped = false;
  for (const auto& p : out.pairs) damped = damped || p.damping_ratio != 0.0;
  const bool adhesive = out.law == YadeLaw::mindlin && out.surface_energy > 0.0;
  if (adhesive && scene.model.tangential != "none" &&
      scene.model.friction_limit != dem::FrictionLimit::total_plus_pulloff) {
    out.reasons.push_back(
        "YADE driver: cohesion 'dmt' with friction is not mapped with this friction_limit: "
        "Law2_ScGeom_MindlinPhys_Mindlin(includeAdhesion) caps the shear force at tanφ (4πR*γ + |F_n|) "
        "(set model.friction_limit = 'total_plus_pulloff' to compare)");
  }
  if (adhesive && damped && scene.model.adhesive_dashpot != dem::AdhesiveDashpot::pulloff_cap) {
    out.reasons.push_back(
        "YADE driver: cohesion 'dmt' with a dashpot is not mapped with adhesive_dashpot = 'clamp': "
        "Law2_ScGeom_MindlinPhys_Mindlin(includeAdhesion) never clips the normal force but caps the "
        "dashpot at the adhesion force 4πR*γ whenever the whole normal force is tensile (set "
        "model.adhesive_dashpot = 'pulloff_cap' to compare)");
  }
  if (out.law == YadeLaw::mindlin && scene.model.tangential == "mindlin_8g" &&
      scene.model.mindlin_form != dem::MindlinForm::incremental) {
    out.warnings.push_back(
        "tangential 'mindlin_8g': YADE's Mindlin loads each shear increment at the stiffness of its "
        "step (F_s −= k_s(δ) Δu_s), the case's mindlin_form 'total' the whole slip at today's k_s: "
        "they differ while δ changes at constant slip (mindlin_form = 'incremental' is YADE's form)");
  }
  if (out.law == YadeLaw::mindlin && out.pairs.size() > 0 && !scene.model.clamp_tensile && !adhesive) {
    if (damped) {
      out.warnings.push_back("damping 'yade_mindlin': YADE's Mindlin clips F_n ≥ 0 (the case "
                             "does not set clamp_tensile)");
    }
  }
  // FrictViscoMat carries betan per material; the pair value is YADE's mix of the two.
  for (const auto& p : out.pairs) {
    if (!out.viscous || p.material_a == p.material_b) continue;
    const double yade = yade_mixed_damping_ratio(out.material_damping_ratio[p.material_a],
                                                 out.material_damping_ratio[p.material_b]);
    if (std::abs(yade - p.damping_ratio) > 1e-15 * std::abs(p.damping_ratio)) {
      out.reasons.push_back(fmt::format(
          "YADE driver: FrictViscoMat mixes betan per material ((β_a + β_b)/2); materials '{}' "
          "and '{}' would get betan = {:.17g}, but their pair restitution needs {:.17g}",
          scene.materials[p.material_a].name, scene.materials[p.material_b].name, yade,
          p.damping_ratio));
    }
  }
  if (out.viscous) out.warnings.push_back(dashpot_warning());
  bool friction = false;
  for (const auto& p : out.pairs) friction = friction || p.shear_stiffness != 0.0 || p.friction_angle != 0.0;
  if (friction) {
    out.warnings.push_back(tangential_warning());
    // What YADE's cap multiplies: CundallStrack k_n δ; CundallStrackVisco the elastic force plus
    // its dashpot; Mindlin the clipped total (with DMT adhesion). The linear cohesion the script
    // adds as a separate force is in none of them.
    const char* yade_basis = out.law == YadeLaw::frict         ? "elastic"
                             : out.law == YadeLaw::frict_visco ? "elastic + damping"
                                                               : "total (plus 4πR*γ with DMT adhesion)";
    out.conventions["friction limit"] = fmt::format(
        "YADE caps |F_s| at tan(frictAngle)·|F_n| with the {} normal force ({}); the case asks "
        "'{}'",
        yade_basis,
        out.law == YadeLaw::frict         ? "CundallStrack: k_n δ"
        : out.law == YadeLaw::frict_visco ? "CundallStrackVisco: normalForce after the dashpot, without the Python cohesion"
                                          : "normalForce after the dashpot (and the clip, Mindlin)",
        dem::to_string(scene.model.friction_limit));
    bool same = false;
    switch (scene.model.friction_limit) {
      case dem::FrictionLimit::total: same = !out.python_cohesion && !adhesive; break;
      // Mindlin adds the adhesion force to |F_n|; the linear laws have none, so this is 'total' there.
      case dem::FrictionLimit::total_plus_pulloff: same = !out.python_cohesion; break;
      case dem::FrictionLimit::elastic: same = out.law == YadeLaw::frict; break;
      case dem::FrictionLimit::elastic_damping: same = out.law != YadeLaw::mindlin || out.surface_energy == 0.0; break;
      // No pull-off force under the linear laws: the shifted rule is elastic + damping there.
      case dem::FrictionLimit::jkr_shifted: same = out.law != YadeLaw::mindlin; break;
    }
    if (!same) {
      out.warnings.push_back(fmt::format(
          "friction limit: YADE caps with the {} normal force, the case's policy is '{}'",
          yade_basis, dem::to_string(scene.model.friction_limit)));
    }
  }
  return out;
}

}  // namespace reference::yade
