// SPDX-License-Identifier: MIT
#include "reference/lammps/run_conventions.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/contact/pair_table.hpp"
#include "dem/contact/registry.hpp"
#include "dem/integrators/scheme.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"
#include "reference/lammps/simulation_box.hpp"
#include "reference/lammps/trace_columns.hpp"

namespace reference::lammps {
namespace {

/// "normal 'linear' → …; damping 'none' → …" from the registry rows of the chosen model.
std::string model_mapping(const dem::ModelChoice& model) {
  std::string out;
  const auto add = [&](dem::Slot slot, const std::string& keyword) {
    const dem::SubModelInfo* row = dem::find_sub_model(slot, keyword);
    if (!out.empty()) out += "; ";
    out += fmt::format("{} '{}' → {}", dem::to_string(slot), keyword,
                       row != nullptr ? row->lammps : "(unknown sub-model)");
  };
  add(dem::Slot::normal, model.normal);
  add(dem::Slot::damping, model.damping);
  add(dem::Slot::tangential, model.tangential);
  add(dem::Slot::cohesion, model.cohesion);
  add(dem::Slot::rolling, model.rolling);
  return out;
}

/// The pair_coeff of every type pair with how its damping and normal values were obtained.
std::string coefficients_per_type_pair(const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types) {
  std::string out;
  for (std::size_t a = 0; a < types.types.size(); ++a) {
    for (std::size_t b = a; b < types.types.size(); ++b) {
      const GranularCoeff c =
          map_pair_law(table.law(types.types[a].material, types.types[b].material),
                       pair_context(scene, types, a, b));
      if (!out.empty()) out += "; ";
      out += fmt::format("types {}-{}: `{}` ({}{}{})", a + 1, b + 1, pair_coeff_arguments(c),
                         c.normal_note, c.normal_note.empty() ? "" : "; ", c.damping_note);
    }
  }
  return out;
}

/// True when the model has JKR cohesion.
bool has_jkr(const cases::Scene& scene) { return scene.model.cohesion == "jkr"; }

}  // namespace

std::map<std::string, std::string> run_conventions(const PreparedScene& prepared, double dt,
                                                   std::uint64_t steps,
                                                   const std::string& version) {
  const cases::Scene& scene = prepared.scene();
  const AtomTypes types = classify_particles(scene);
  std::map<std::string, std::string> c;
  std::string integrator = fmt::format(
      "velocity Verlet ({}): half kick, drift, forces with the half-step velocities v(t+Δt/2), "
      "half kick",
      scene.integration.rotation ? "fix nve/sphere" : "fix nve");
  if (scene.integration.scheme != dem::SchemeId::velocity_verlet) {
    integrator += fmt::format(
        " — the case's scheme '{}' does not exist in LAMMPS (matched numerics: run the core on "
        "reference::matched_scene(scene, \"lammps\"))",
        dem::scheme_info(scene.integration.scheme).keyword);
  }
  c["integrator"] = integrator;
  c["timestep"] =
      fmt::format("{:.6g} s × {} steps (the in-house core's resolved step)", dt, steps);
  c["rotation"] = scene.integration.rotation
                      ? "integrated (fix nve/sphere)"
                      : "held at initial values (fix nve: x and v only)";
  c["contact onset"] = "pair granular interacts while δ > 0 strictly (rsq < (r_i + r_j)²)";
  c["trace velocity"] = "velocity at the sample time (fix print at the end of the step)";
  c["fixed particles"] =
      "one fix freeze group, not integrated (pair granular then uses m_eff = the mobile mass)";
  c["mixing"] = "explicit pair_coeff for every type pair (LAMMPS' own i-j mixing never used)";
  c["atom types"] = fmt::format("{} type(s), one per (material, radius, fixed) class, so m* and "
                                "η are exact per type pair",
                                types.types.size());
  c["damping"] = coefficients_per_type_pair(scene, prepared.pair_table(), types);
  c["friction limit"] =
      has_jkr(scene) || scene.model.cohesion == "dmt"
          ? "LAMMPS: mu |F_ne + 2 F_pulloff| for jkr/dmt pairs (the dashpot not included), mu |F_ne + "
            "F_damping| for pairs without adhesion: the core's 'jkr_shifted'"
          : "LAMMPS: mu |F_elastic + F_damping| (the core's 'elastic_damping'; equals 'total' "
            "without cohesion)";
  c["tangential history"] =
      "displacement, projected onto the tangent plane and rescaled to its old length when "
      "|xi.n| k_t > 1e-10 F_crit, then xi += v_t dt; when capped xi = -(F_crit t + eta_t v_t)/k_t; "
      "pair contact velocity uses the full radii, the torque lever r - delta/2 (the core's "
      "pair_lever_arm 'radius_velocity')";
  if (scene.model.tangential != "none" || scene.model.rolling != "none") {
    c["unloaded slider"] = fmt::format(
        "a tangential or rolling slider with no stored displacement (a contact touching at t = 0: "
        "the setup force integrates none) whose dashpot alone exceeds the Coulomb limit gets no "
        "force at all (`shrmag != 0` branch): the core's unloaded_slider 'zero'; this case uses '{}'",
        dem::to_string(scene.model.unloaded_slider));
  }
  if (!scene.walls.empty()) {
    c["walls"] =
        "fix wall/gran granular per (wall, mobile atom type) for axis-aligned planes, fix "
        "wall/gran/region on a region open at both ends for cylinders and cones about x, y or z; "
        "E_in = 2(1-nu)E* (this build's wall E* = E/(2(1-nu))), k_t explicit, m* = the particle "
        "mass, R* = r on planes but 2 r rho / (2 rho - r) on a region of radius rho (the core: r); "
        "lever arm and contact-point velocity use r (the core's wall_lever_arm 'radius'); "
        "delta = 0 counts as contact (pairs need delta > 0); a wall removed at t <= 0 is left out";
  }
  bool driven = false;
  for (const auto& p : scene.particles) driven = driven || !p.motion.empty();
  if (driven) {
    c["prescribed motion"] =
        "fix move variable: x = x(0) + sum_k v_k clamp(time - t_k, 0, d_k), v = the stretch's "
        "velocity; the driven atom is also in the fix freeze group (forces zeroed, m_eff of the "
        "partner)";
  }
  if (has_jkr(scene)) {
    c["JKR rupture"] =
        "LAMMPS breaks the neck at the load-controlled pull-off overlap delta_f (r >= r_p + r_q - "
        "delta_f), i.e. the core's jkr_rupture 'load'; a contact forms only at delta > 0";
  }
  c["model mapping"] = model_mapping(scene.model);
  const Box box = simulation_box(scene, static_cast<double>(steps) * dt);
  c["box"] =
      fmt::format("boundary f f f, [{:.6g}, {:.6g}] × [{:.6g}, {:.6g}] × [{:.6g}, {:.6g}] m",
                  box.low[0], box.high[0], box.low[1], box.high[1], box.low[2], box.high[2]);
  const double g = std::sqrt(scene.gravity[0] * scene.gravity[0] +
                             scene.gravity[1] * scene.gravity[1] +
                             scene.gravity[2] * scene.gravity[2]);
  c["gravity"] = g > 0.0 ? "fix gravity on the mobile atoms (after fix store/force)" : "none";
  const TracePrintPlan plan = trace_print_plan(scene, types);
  std::string sources;
  for (const auto& s : plan.sources) sources += (sources.empty() ? "" : "; ") + s;
  c["trace columns"] = sources;
  c["trace precision"] =
      "every column printed as $(formula:%.17g) with its formula written out: LAMMPS 2021 "
      "passes v_name references through %.15g";
  c["LAMMPS version"] = version;
  return c;
}

std::map<std::string, std::string> inexpressible_metrics(const cases::Scene& scene) {
  std::map<std::string, std::string> out;
  if (!scene.walls.empty() && scene.model.tangential != "none" && scene.integration.rotation &&
      scene.model.wall_lever_arm == dem::WallLeverArm::contact_point) {
    const std::string why =
        "fix wall/gran applies the wall's tangential force at lever arm r (and takes the "
        "contact-point velocity with r); the case asks for r - delta/2 (wall_lever_arm = "
        "'contact_point'), which LAMMPS 2021 cannot express (run with wall_lever_arm = 'radius' "
        "to compare)";
    for (const char* m : {"spin_after", "tangential_restitution", "angular_velocity_after_x",
                          "angular_velocity_after_y", "angular_velocity_after_z"}) {
      out[m] = why;
    }
  }
  if (!has_jkr(scene) || scene.model.jkr_rupture != dem::JkrRupture::displacement) return out;
  const std::string why =
      "LAMMPS 2021 breaks a JKR contact at the load-controlled pull-off point delta_f, not at the "
      "displacement-controlled delta_c the case asks for (jkr_rupture = 'displacement')";
  for (const char* m : {"rupture_separation", "force_at_rupture", "separation_work"}) {
    out[m] = why;
  }
  return out;
}

}  // namespace reference::lammps
