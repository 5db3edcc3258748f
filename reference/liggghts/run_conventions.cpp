// SPDX-License-Identifier: MIT
#include "reference/liggghts/run_conventions.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "reference/liggghts/primitive_walls.hpp"

namespace reference::liggghts {

std::map<std::string, std::string> run_conventions(const cases::Scene& scene, const ContactSettings& contacts,
                                                   const TracePlan& plan, const DeckSettings& settings,
                                                   const std::string& version) {
  std::map<std::string, std::string> c;
  c["version"] = version;
  c["integrator"] = scene.integration.rotation
                        ? "velocity Verlet (fix nve/sphere, I = 0.4 m r²); forces see v(t + Δt/2), ω(t + Δt/2)"
                        : "velocity Verlet (fix nve); ω held (rotation = false)";
  c["time step"] = fmt::format("{:.17g} s, {} steps (the core's)", settings.timestep, settings.steps);
  std::string words = "pair_style gran " + model_words(contacts);
  for (const std::string& o : contacts.options) words += " " + o;
  c["contact model"] = words + "; the same words on every fix wall/gran";
  if (contacts.normal == "hertz") {
    c["hertz"] =
        "k_n = 4/3 Y* √(R* δ), γ_n = −2 √(5/6) β √(2 Y* √(R* δ) m*), β = ln e/√(ln² e + π²) — the core's "
        "'tsuji' dashpot; Y*, G* mixed by LIGGGHTS from per-type E and ν (checked against the core's pair "
        "values to 1e-12); k_t = 8 G* √(R* δ), γ_t from e with 8 G* in place of 2 Y* unless tangential_damping "
        "off";
  } else if (contacts.normal == "hertz/stiffness") {
    c["hertz/stiffness"] =
        "F_n = kn √(R* δ) δ − gamman √(R* δ) m* v_n with kn = 4/3 E* and gamman = η₀ per type pair (the core's Hertz "
        "spring and 'lammps_viscoelastic' dashpot, from its pair table: [[pairs]] overrides included); "
        "k_t = kt √(R* δ) with kt = 8 G*; γ_t = gammat √(R* δ) m*, gammat = tangential_damping_ratio · η₀";
  } else {
    c["hooke/stiffness"] =
        "k_n, k_t per type pair; absolute_damping on: γ_n = the core's η per type pair (β(ε) √(m* k_n) for "
        "'restitution', m* of the type pair), γ_t = tangential_damping_ratio · γ_n";
  }
  if (std::any_of(scene.particles.begin(), scene.particles.end(), [](const cases::ParticleSpec& p) { return p.fixed; })) {
    c["frozen particles"] =
        "fix freeze; pair gran then takes m* = the mobile mass (the core's 1/m = 0); pairs of two frozen spheres "
        "excluded from the neighbour list and walls acting on the mobile spheres only, as in the core";
  }
  c["workarounds"] =
      "neigh_modify contact_distance_factor 1.1 (at 1 a separated pair keeps its slip until the next list build); "
      "thermo_modify lost error (lost atoms are ignored by default); the screen unbuffered under stdbuf (some errors "
      "reach the screen alone, unflushed); every trace formula written out as its own thermo variable (a v_name "
      "inside a formula passes through 15 digits); model settings after a wall's arguments";
  c["tangential slip"] =
      "ς += v_t Δt, then its normal part removed without rescaling (increment_project); Coulomb test "
      "k_t |ς| > μ |F_n| on the spring alone with F_n = elastic + dashpot (elastic_damping); sliding drops the "
      "tangential dashpot; sticking adds it after the test, so |F_t| may exceed μ |F_n|";
  if (contacts.rolling == "cdt") {
    c["rolling resistance"] =
        "rolling_friction cdt: τ_p = −μ_r R* k_n δ (ω̂ − (ω̂·n) n), ω̂ the unit vector of ω_p − ω_q (of ω_p at a wall, "
        "R* = r), k_n δ the elastic normal force; the twist part dropped after normalising (the core's "
        "constant_torque_form = 'projected'); μ_r per type pair (coefficientRollingFriction)";
  }
  c["lever arm"] = "r − δ/2 for the torque and the contact-point velocity, pairs and walls (contact_point)";
  if (!scene.walls.empty()) {
    c["walls"] =
        "fix wall/gran … primitive type T xplane|yplane|zplane, or xcylinder|ycylinder|zcylinder R c1 c2: a wall "
        "is an atom type mixed like a particle (rigid: E = 1e300 Pa); planes and cylinders push from both sides; "
        "R* = r, m* = m; history zeroed when the sphere leaves";
    if (std::any_of(scene.walls.begin(), scene.walls.end(),
                    [](const cases::WallSpec& w) { return wall_cylinder(w).has_value(); })) {
      c["walls"] += "; a primitive cylinder is unbounded along its axis, the core's ends where its height does, so "
                    "the two agree while no sphere passes an end (one that starts beyond an end touching the "
                    "extended surface makes the case n/a); a sphere centred on its axis (within 1e-13 m) gets a "
                    "zero-force contact there, none in the core";
    }
    if (!scene.meshes.empty()) {
      c["walls"] += "; meshes: fix mesh/surface per mesh (its facets written as ASCII STL in the scene's "
                    "coordinates, one atom type per wall material) and one fix wall/gran … mesh holding them all; a "
                    "sphere meets a facet's nearest point; a new face contact is dropped while a coplanar neighbour "
                    "already holds one, and takes over that neighbour's history";
    }
  }
  c["contact onset"] = "pairs touch while |x_p − x_q| < r_p + r_q (strict)";
  std::string sources;
  for (const std::string& s : plan.sources) sources += (sources.empty() ? "" : "; ") + s;
  c["trace columns"] = sources;
  c["precision"] = "thermo columns of equal-style variables printed with %.17g; snapshots with %.17g";
  return c;
}

}  // namespace reference::liggghts
