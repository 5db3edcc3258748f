// SPDX-License-Identifier: MIT
#include "reference/yade/model_mapping.hpp"

#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"

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

/// What one slot of one pair maps to: a value when expressible, else the reason.
struct SlotMapping {
  std::optional<double> value;  ///< kn for the normal slot, betan for damping, 0 for the rest
  std::string reason;
  std::string convention;       ///< "<keyword>: <registry YADE text>"
};

/// A slot whose sub-model has no YADE mapping (yet); used by the generic visitor branches.
[[maybe_unused]] SlotMapping unmapped(std::string_view slot, std::string_view keyword) {
  return {std::nullopt, fmt::format("YADE driver: {} model '{}' is not mapped yet", slot, keyword), ""};
}

/// A mapped slot with its registry text.
template <class Model>
SlotMapping mapped(const Model& m, double value) {
  return {value, "", fmt::format("{}: {}", keyword_of(m), yade_text_of(m))};
}

/// Normal slot → pair stiffness kn (Ip2 `kn` MatchMaker).
SlotMapping map_normal(const dem::NormalModel& model) {
  return std::visit(Overloaded{[](const dem::LinearNormal& m) { return mapped(m, m.stiffness); },
                               [](const auto& m) { return unmapped("normal", keyword_of(m)); }},
                    model);
}

/// Damping slot → betan = β/2, since YADE's cn = 2 betan √(m̄ kn) and ours η = β √(m* k).
SlotMapping map_damping(const dem::DampingModel& model) {
  return std::visit(
      Overloaded{[](const dem::NoDamping& m) { return mapped(m, 0.0); },
                 [](const dem::RestitutionDamping& m) { return mapped(m, 0.5 * m.factor); },
                 [](const auto& m) { return unmapped("damping", keyword_of(m)); }},
      model);
}

/// Tangential slot → shear stiffness 0 and friction angle 0 (frictionless).
SlotMapping map_tangential(const dem::TangentialModel& model) {
  return std::visit(Overloaded{[](const dem::NoTangential& m) { return mapped(m, 0.0); },
                               [](const auto& m) { return unmapped("tangential", keyword_of(m)); }},
                    model);
}

/// Cohesion slot: only `none` (no YADE law gives the workbench's cohesion natively).
SlotMapping map_cohesion(const dem::CohesionModel& model) {
  return std::visit(Overloaded{[](const dem::NoCohesion& m) { return mapped(m, 0.0); },
                               [](const auto& m) { return unmapped("cohesion", keyword_of(m)); }},
                    model);
}

/// Rolling slot: only `none`.
SlotMapping map_rolling(const dem::RollingModel& model) {
  return std::visit(Overloaded{[](const dem::NoRolling& m) { return mapped(m, 0.0); },
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
  return "damping 'restitution' via Law2_ScGeom_FrictViscoPhys_CundallStrackVisco: YADE's dashpot "
         "uses the relative translational velocity scaled by α = (r_p + r_q)/(r_p + r_q − δ) "
         "(ScGeom::getIncidentVel with avoidGranularRatcheting, not switchable), so its viscous "
         "force is α·η·u_n instead of eq 3.10's η·u_n — larger by the relative amount "
         "δ/(r_p + r_q − δ); it also acts at δ = 0 exactly, where the core has no contact. "
         "The spring and η itself (m* = the mobile mass against a fixed partner) are exact; "
         "the force is not clamped at zero, as in eq 3.10";
}

}  // namespace

double yade_mixed_damping_ratio(double a, double b) noexcept {
  if (a != 0.0 && b != 0.0) return (a + b) / 2.0;
  return b == 0.0 ? a : b;
}

YadeModelMapping map_contact_model(const cases::Scene& scene) {
  YadeModelMapping out;
  std::optional<dem::PairTable> table;
  try {
    table.emplace(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  } catch (const dem::ModelError& e) {
    out.reasons.push_back(fmt::format("YADE driver: the contact model cannot be built: {}", e.what()));
    return out;
  }
  const std::size_t n = table->material_count();
  out.material_damping_ratio.assign(n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a; b < n; ++b) {
      const dem::PairLaw& law = table->law(a, b);
      const SlotMapping normal = map_normal(law.normal);
      const SlotMapping damping = map_damping(law.damping);
      const SlotMapping slots[] = {normal, damping, map_tangential(law.tangential),
                                   map_cohesion(law.cohesion), map_rolling(law.rolling)};
      const char* names[] = {"normal", "damping", "tangential", "cohesion", "rolling"};
      bool ok = true;
      for (std::size_t s = 0; s < std::size(slots); ++s) {
        if (!slots[s].value) {
          add_reason(out.reasons, slots[s].reason);
          ok = false;
        } else {
          out.conventions[fmt::format("contact {}", names[s])] = slots[s].convention;
        }
      }
      if (!ok) continue;
      out.pairs.push_back({a, b, *normal.value, *damping.value});
      if (a == b) out.material_damping_ratio[a] = *damping.value;
    }
  }
  if (!out.reasons.empty()) return out;

  for (const auto& p : out.pairs) out.viscous = out.viscous || p.damping_ratio != 0.0;
  if (out.viscous && scene.model.clamp_tensile) {
    out.reasons.push_back(
        "YADE driver: damping 'restitution' with clamp_tensile = true is not mapped yet "
        "(ViscElMat clamps, but takes the dashpot per material, not per particle pair's m*)");
  }
  // FrictViscoMat carries betan per material; the pair value is YADE's mix of the two.
  for (const auto& p : out.pairs) {
    if (p.material_a == p.material_b) continue;
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
  return out;
}

}  // namespace reference::yade
