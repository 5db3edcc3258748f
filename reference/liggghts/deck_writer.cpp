// SPDX-License-Identifier: MIT
#include "reference/liggghts/deck_writer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "reference/common/atom_data.hpp"
#include "reference/common/deck_comment.hpp"
#include "reference/common/dump_snapshots.hpp"
#include "reference/liggghts/primitive_walls.hpp"

namespace reference::liggghts {
namespace {

/// A number written so that LIGGGHTS reads back the same double.
std::string num(double v) { return fmt::format("{:.17g}", v); }

/// Appends one deck line: a command padded to 16 columns, then its arguments.
void line(std::string& deck, std::string_view command, std::string_view args) {
  deck += fmt::format("{:<15} {}\n", command, args);
}

/// The values of one per-type or per-type-pair table, space-separated.
std::string values(const std::vector<double>& v) {
  std::string out;
  for (const double x : v) out += (out.empty() ? "" : " ") + num(x);
  return out;
}

/// Types (1-based) of the mobile or frozen particle classes, space-separated.
std::string particle_types(const AtomTypes& types, bool fixed) {
  std::string out;
  for (std::size_t t = 0; t < types.particles.size(); ++t) {
    if (types.particles[t].fixed == fixed) out += fmt::format("{}{}", out.empty() ? "" : " ", t + 1);
  }
  return out;
}

/// The groups of mobile and of frozen particles.
void write_groups(std::string& deck, const AtomTypes& types) {
  if (const std::string mobile = particle_types(types, false); !mobile.empty()) {
    line(deck, "group", "tr_mobile type " + mobile);
  }
  if (const std::string fixed = particle_types(types, true); !fixed.empty()) {
    line(deck, "group", "tr_fixed type " + fixed);
  }
}

/// The fix holding mesh `m`'s facets (one fix wall/gran, tr_mesh_walls, makes them all granular walls).
std::string mesh_fix_id(std::size_t m) { return fmt::format("tr_mesh_{}", m); }

/// The model settings ("limitForce on", …): after the model words on pair_style gran, at the end
/// of fix wall/gran (before `primitive` they end the model words too early).
std::string model_settings(const ContactSettings& c) {
  std::string out;
  for (const std::string& o : c.options) out += " " + o;
  return out;
}

/// A box holding every trajectory: the bodies' bounding box widened along each axis k by
/// 2 v_max T + |g_k| T² + 2 r_max, and ended 2 r_max beyond a resting plane wall across that axis
/// (atoms leaving it stop the run: `thermo_modify lost error`); then widened to hold every corner
/// of every mesh in the run, 2 r_max beyond.
std::pair<cases::Vector3, cases::Vector3> simulation_box(const cases::Scene& scene, double duration) {
  cases::Vector3 lo{}, hi{};
  double v_max = 0.0, r_max = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    lo[k] = scene.particles.empty() ? -1.0 : scene.particles.front().position[k];
    hi[k] = lo[k];
  }
  for (const cases::ParticleSpec& p : scene.particles) {
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p.position[k]);
      hi[k] = std::max(hi[k], p.position[k]);
    }
    v_max = std::max(v_max, std::sqrt(p.velocity[0] * p.velocity[0] + p.velocity[1] * p.velocity[1] +
                                      p.velocity[2] * p.velocity[2]));
    r_max = std::max(r_max, p.radius);
  }
  const double skin = 2.0 * std::max(r_max, 1e-9);
  for (std::size_t k = 0; k < 3; ++k) {
    const double margin = 2.0 * v_max * duration + std::abs(scene.gravity[k]) * duration * duration + skin;
    lo[k] -= margin;
    hi[k] += margin;
  }
  for (const cases::WallSpec& wall : scene.walls) {
    const std::optional<WallPlane> plane = wall_plane(wall);
    if (!plane || !wall_in_run(wall)) continue;
    const auto k = static_cast<std::size_t>(plane->axis);
    if (plane->sign > 0.0) {
      lo[k] = std::max(lo[k], std::min(plane->position, hi[k]) - skin);
    } else {
      hi[k] = std::min(hi[k], std::max(plane->position, lo[k]) + skin);
    }
  }
  // Last, so that no plane's clip cuts a mesh: LIGGGHTS drops the facets whose centres lie outside
  // the box and stops ("mesh elements have been lost").
  for (const cases::WallSpec& wall : scene.walls) {
    if (!wall.mesh || !wall_in_run(wall)) continue;
    for (const cases::Vector3& corner : wall.corners) {
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], corner[k] - skin);
        hi[k] = std::max(hi[k], corner[k] + skin);
      }
    }
  }
  return {lo, hi};
}

/// Units, atom style, newton, ghost velocities and the sanity-limit switches.
void write_header(std::string& deck, const cases::Scene& scene, const ContactSettings& c, const DeckSettings& s) {
  deck += fmt::format("# dem-workbench LIGGGHTS deck for case '{}' (generated, do not edit)\n", deck_comment_text(scene.name));
  deck += fmt::format("# {} steps of {} s; written for LIGGGHTS-PUBLIC 3.8.0\n", s.steps, num(s.timestep));
  line(deck, "units", "si");
  line(deck, "atom_style", "granular");
  line(deck, "atom_modify", "map array sort 0 0.0  # x[i] in formulas; atoms stay in id order");
  line(deck, "boundary", "f f f");
  line(deck, "newton", "off  # pair gran with history needs it");
  line(deck, "communicate", "single vel yes  # granular pairs need ghost velocities");
  if (c.hard_particles) line(deck, "hard_particles", "yes  # a Young's modulus above 1e9 Pa (or a rigid wall)");
  if (c.soft_particles) line(deck, "soft_particles", "yes  # a Young's modulus below 5e6 Pa");
}

/// The box (or the data file), the atom types' comments, the property tables, pair_style gran and
/// the neighbour settings.
void write_box_and_properties(std::string& deck, const cases::Scene& scene, const AtomTypes& types,
                              const ContactSettings& c, const DeckSettings& s) {
  if (atoms_in_data_file(scene, types)) {
    deck += fmt::format("# {} atoms (more than {}): box, types, diameters, densities, positions and velocities come "
                        "from the data file\n",
                        scene.particles.size(), kMaxInlineAtoms);
    line(deck, "read_data", s.data_file);
  } else {
    const auto [lo, hi] = simulation_box(scene, static_cast<double>(s.steps) * s.timestep);
    line(deck, "region", fmt::format("tr_box block {} {} {} {} {} {} units box", num(lo[0]), num(hi[0]), num(lo[1]),
                                     num(hi[1]), num(lo[2]), num(hi[2])));
    line(deck, "create_box", fmt::format("{} tr_box", types.count()));
  }
  deck += types.per_atom_diameter
              ? fmt::format("# atom types: more than {} (material, radius) classes, so one per (material, fixed) "
                            "class with diameters per atom, then one per wall material\n",
                            kMaxParticleTypes)
              : std::string("# atom types: one per (material, radius, fixed) particle class, then one per wall "
                            "material\n");
  for (std::size_t t = 0; t < types.particles.size(); ++t) {
    const ParticleType& p = types.particles[t];
    if (types.per_atom_diameter) {
      deck += fmt::format("#   type {}: material '{}', {}\n", t + 1, deck_comment_text(scene.materials.at(p.material).name),
                          p.fixed ? "frozen" : "mobile");
    } else {
      deck += fmt::format("#   type {}: material '{}', r = {} m, {}, m = {} kg\n", t + 1,
                          deck_comment_text(scene.materials.at(p.material).name), num(p.radius),
                          p.fixed ? "frozen" : "mobile", num(p.mass));
    }
  }
  for (std::size_t w = 0; w < types.wall_materials.size(); ++w) {
    const dem::MaterialProperties& m = scene.materials.at(types.wall_materials[w]);
    deck += fmt::format("#   type {}: wall material '{}'{}\n", types.particles.size() + w + 1, deck_comment_text(m.name),
                        m.rigid ? " (rigid: E = 1e300 Pa)" : "");
  }
  const std::size_t n = types.count();
  const auto table = [&](std::string_view id, std::string_view property, const std::vector<double>& v) {
    line(deck, "fix", fmt::format("{} all property/global {} peratomtypepair {} {}", id, property, n, values(v)));
  };
  if (c.normal == "hertz") {
    line(deck, "fix", fmt::format("tr_youngs all property/global youngsModulus peratomtype {}", values(c.youngs_modulus)));
    line(deck, "fix", fmt::format("tr_poisson all property/global poissonsRatio peratomtype {}", values(c.poisson_ratio)));
    table("tr_restitution", "coefficientRestitution", c.restitution);
  } else {  // hertz/stiffness scales each by √(R* δ) (and γ by m*); hooke/stiffness takes γ absolute
    const std::string gamma = c.normal == "hertz/stiffness" ? "" : "_abs";
    table("tr_kn", "kn", c.kn);
    table("tr_kt", "kt", c.kt);
    table("tr_gamman", "gamman" + gamma, c.gamman);
    table("tr_gammat", "gammat" + gamma, c.gammat);
  }
  table("tr_friction", "coefficientFriction", c.friction);
  if (!c.rolling.empty()) table("tr_rolling", "coefficientRollingFriction", c.rolling_friction);
  line(deck, "pair_style", "gran " + model_words(c) + model_settings(c));
  line(deck, "pair_coeff", "* *");
  double r_max = 0.0;
  for (const cases::ParticleSpec& p : scene.particles) r_max = std::max(r_max, p.radius);
  line(deck, "neighbor", fmt::format("{} bin", num(s.skin > 0.0 ? s.skin : std::max(r_max, 1e-9))));
  // LIGGGHTS zeroes a pair's slip history when it separates only while the pair is within
  // contact_distance_factor × (r_p + r_q); at the default 1 never, so a pair that touches again
  // before the next list build would resume its old slip.
  line(deck, "neigh_modify", "delay 0 contact_distance_factor 1.1  # a separating pair forgets its slip");
}

/// The atoms inline (create_atoms, set) or nothing beyond the groups when a data file holds them.
void write_atoms(std::string& deck, const cases::Scene& scene, const AtomTypes& types) {
  if (atoms_in_data_file(scene, types)) {
    write_groups(deck, types);
    return;
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    line(deck, "create_atoms", fmt::format("{} single {} {} {} units box  # particle {} = atom {}",
                                           types.particle_type(i), num(p.position[0]), num(p.position[1]),
                                           num(p.position[2]), i, i + 1));
  }
  for (std::size_t t = 0; t < types.particles.size(); ++t) {
    const ParticleType& type = types.particles[t];
    line(deck, "set", fmt::format("type {} diameter {} density {}", t + 1, num(2.0 * type.radius),
                                  num(scene.materials.at(type.material).density)));
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    line(deck, "set", fmt::format("atom {} vx {} vy {} vz {} omegax {} omegay {} omegaz {}", i + 1,
                                  num(p.velocity[0]), num(p.velocity[1]), num(p.velocity[2]),
                                  num(p.angular_velocity[0]), num(p.angular_velocity[1]),
                                  num(p.angular_velocity[2])));
  }
  write_groups(deck, types);
}

/// Frozen pairs excluded, the pair-force store, walls, gravity, integration, freeze (in that order)
/// and the time step.
void write_fixes(std::string& deck, const cases::Scene& scene, const AtomTypes& types, const ContactSettings& c,
                 const DeckSettings& s) {
  const bool any_mobile = !particle_types(types, false).empty();
  if (!particle_types(types, true).empty()) {
    line(deck, "neigh_modify", "exclude group tr_fixed tr_fixed  # as the core: two frozen spheres never interact");
  }
  if (!s.timing_only) {
    deck += "# the pair forces alone, stored before walls and gravity add theirs and freeze zeroes them\n";
    line(deck, "fix", fmt::format("{} all store/force", kPairForceFix));
  }
  for (std::size_t w = 0; w < scene.walls.size() && any_mobile; ++w) {
    const std::string primitive = primitive_arguments(scene.walls[w]);
    if (primitive.empty()) continue;  // supports() reports it
    if (!wall_in_run(scene.walls[w])) {
      deck += fmt::format("# wall {} ('{}') is removed at t <= 0: only the preparation met it\n", w,
                          deck_comment_text(scene.walls[w].name));
      continue;
    }
    deck += fmt::format("# wall {} ('{}'): a two-sided primitive {} of type {}{}\n", w,
                        deck_comment_text(scene.walls[w].name),
                        wall_plane(scene.walls[w]) ? "plane" : "cylinder, unbounded along its axis", types.wall_type(w),
                        s.timing_only ? "" : "; its force on each atom is stored");
    line(deck, "fix", fmt::format("{} tr_mobile wall/gran {} primitive type {} {}{}{}", wall_fix_id(w), model_words(c),
                                  types.wall_type(w), primitive,
                                  s.timing_only ? "" : " store_force yes", model_settings(c)));
  }
  std::string meshes;  // LIGGGHTS 3.8 takes one fix wall/gran of type mesh, holding every mesh
  std::size_t mesh_count = 0;
  for (std::size_t m = 0; m < scene.meshes.size() && any_mobile; ++m) {
    const cases::WallSpec* first = first_facet(scene, m);
    if (first == nullptr) continue;
    const auto w = static_cast<std::size_t>(first - scene.walls.data());
    if (!wall_in_run(*first)) {
      deck += fmt::format("# mesh {} ('{}') is removed at t <= 0: only the preparation met it\n", m,
                          deck_comment_text(scene.meshes[m].name));
      continue;
    }
    deck += fmt::format("# mesh {} ('{}'): {} facets of type {}, two-sided, from {}\n", m,
                        deck_comment_text(scene.meshes[m].name), scene.meshes[m].facets, types.wall_type(w),
                        mesh_file(m));
    line(deck, "fix", fmt::format("{} all mesh/surface file {} type {}", mesh_fix_id(m), mesh_file(m), types.wall_type(w)));
    meshes += " " + mesh_fix_id(m);
    ++mesh_count;
  }
  if (mesh_count > 0) {
    line(deck, "fix", fmt::format("tr_mesh_walls tr_mobile wall/gran {} mesh n_meshes {} meshes{}{}", model_words(c),
                                  mesh_count, meshes, model_settings(c)));
  }
  const cases::Vector3& g = scene.gravity;
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (any_mobile && g_norm > 0.0) {
    line(deck, "fix", fmt::format("tr_gravity tr_mobile gravity {} vector {} {} {}", num(g_norm), num(g[0]),
                                  num(g[1]), num(g[2])));
  }
  if (any_mobile) {
    line(deck, "fix", scene.integration.rotation
                          ? "tr_integrate tr_mobile nve/sphere  # velocity Verlet of x and omega"
                          : "tr_integrate tr_mobile nve  # velocity Verlet of x; omega held (rotation = false)");
  }
  if (!particle_types(types, true).empty()) {
    line(deck, "fix", "tr_freeze tr_fixed freeze  # pairs then use m* = the mobile mass");
  }
  line(deck, "timestep", num(s.timestep));
}

/// The trace's computes, variables and thermo settings, and the snapshot dump.
void write_outputs(std::string& deck, const cases::Scene& scene, const TracePlan& plan, const DeckSettings& s) {
  for (const std::string& command : plan.commands) {
    const auto space = command.find(' ');
    line(deck, command.substr(0, space), command.substr(space + 1));
  }
  deck += "# trace columns: each formula written out (a v_name inside a formula keeps 15 digits)\n";
  std::string thermo = "custom step";
  for (std::size_t k = 0; k < plan.columns.size(); ++k) {
    line(deck, "variable", fmt::format("{} equal \"{}\"  # {}", column_variable(k), plan.columns[k].formula,
                                       plan.columns[k].name));
    thermo += " v_" + column_variable(k);
  }
  line(deck, "thermo_style", thermo);
  line(deck, "thermo_modify", "format float %.17g norm no lost error  # atoms leaving the box stop the run");
  line(deck, "thermo", fmt::format("{}", scene.output.trace_every));

  const SnapshotSchedule schedule = snapshot_schedule(scene.output.snapshot_times, s.timestep, s.steps);
  if (schedule.next_step.empty()) return;
  line(deck, "variable", fmt::format("tr_snapshot_step equal \"{}\"", schedule.next_step));
  line(deck, "dump", fmt::format("tr_snapshots all custom 1 {} id x y z vx vy vz omegax omegay omegaz", s.snapshot_file));
  // This LIGGGHTS takes only a whole-line dump format (its dumps default to 6 digits).
  line(deck, "dump_modify",
       fmt::format("tr_snapshots sort id every v_tr_snapshot_step{} format \"%d{}\"", schedule.first ? " first yes" : "",
                   " %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"));
}

}  // namespace

std::string write_deck(const cases::Scene& scene, const AtomTypes& types, const ContactSettings& contacts,
                       const TracePlan& plan, const DeckSettings& settings) {
  std::string deck;
  write_header(deck, scene, contacts, settings);
  write_box_and_properties(deck, scene, types, contacts, settings);
  write_atoms(deck, scene, types);
  write_fixes(deck, scene, types, contacts, settings);
  if (settings.timing_only) {
    line(deck, "thermo_modify", "lost error  # atoms leaving the box stop the run");
    line(deck, "thermo", fmt::format("{}", std::max<std::uint64_t>(settings.steps, 1)));
  } else {
    write_outputs(deck, scene, plan, settings);
  }
  line(deck, "run", fmt::format("{}", settings.steps));
  return deck;
}

std::string write_atom_data(const cases::Scene& scene, const AtomTypes& types, const DeckSettings& settings) {
  const auto [lo, hi] = simulation_box(scene, static_cast<double>(settings.steps) * settings.timestep);
  std::string out = fmt::format("dem-workbench atoms of case '{}' (generated, do not edit)\n\n{} atoms\n{} atom types\n\n",
                                deck_comment_text(scene.name), scene.particles.size(), types.count());
  out += atom_data_body(scene, types.type_of, lo, hi, "Atoms");
  return out;
}

std::string mesh_file(std::size_t m) { return fmt::format("mesh_{}.stl", m); }

std::string write_mesh_stl(const cases::Scene& scene, std::size_t m) {
  std::string stl = fmt::format("solid mesh_{}\n", m);
  for (const cases::WallSpec& w : scene.walls) {
    if (w.mesh != m) continue;
    // The facet normal is LIGGGHTS' to recompute; the corners' order orients the triangle.
    stl += "  facet normal 0 0 0\n    outer loop\n";
    for (const cases::Vector3& c : w.corners) stl += fmt::format("      vertex {} {} {}\n", num(c[0]), num(c[1]), num(c[2]));
    stl += "    endloop\n  endfacet\n";
  }
  return stl + fmt::format("endsolid mesh_{}\n", m);
}

std::vector<std::pair<std::string, std::string>> mesh_files(const cases::Scene& scene) {
  std::vector<std::pair<std::string, std::string>> files;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) files.emplace_back(mesh_file(m), write_mesh_stl(scene, m));
  return files;
}

}  // namespace reference::liggghts
