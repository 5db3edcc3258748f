// SPDX-License-Identifier: MIT
#include "reference/lammps/deck_writer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/pair_table.hpp"
#include "reference/common/atom_data.hpp"
#include "reference/common/deck_comment.hpp"
#include "reference/common/dump_snapshots.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"
#include "reference/lammps/prescribed_motion.hpp"
#include "reference/lammps/simulation_box.hpp"
#include "reference/lammps/trace_columns.hpp"
#include "reference/lammps/wall_mapping.hpp"

namespace reference::lammps {
namespace {

/// A number written so that LAMMPS reads back the same double.
std::string num(double v) { return fmt::format("{:.17g}", v); }

/// Appends one deck line: a command padded to 16 columns, then its arguments.
void line(std::string& deck, std::string_view command, std::string_view args) {
  deck += fmt::format("{:<15} {}\n", command, args);
}

/// Appends a whole command ("name args") laid out like line().
void command_line(std::string& deck, std::string_view command) {
  const auto space = command.find(' ');
  line(deck, command.substr(0, space),
       space == std::string_view::npos ? std::string_view{} : command.substr(space + 1));
}

/// LAMMPS types (1-based) of the fixed or mobile classes, space-separated.
std::string types_where(const AtomTypes& types, bool fixed) {
  std::string out;
  for (std::size_t t = 0; t < types.types.size(); ++t) {
    if (types.types[t].fixed == fixed) out += fmt::format("{}{}", out.empty() ? "" : " ", t + 1);
  }
  return out;
}

/// One-line description of an atom type for comments.
std::string describe(const cases::Scene& scene, const AtomType& t) {
  return fmt::format("material '{}', r = {} m, {}, m = {} kg",
                     deck_comment_text(scene.materials.at(t.material).name), num(t.radius),
                     t.fixed ? "fixed" : "mobile", num(t.mass));
}

/// Units, atom style, boundaries and communication settings.
void write_header(std::string& deck, const cases::Scene& scene, const DeckSettings& s) {
  deck += fmt::format("# dem-workbench LAMMPS deck for case '{}' (generated, do not edit)\n",
                      deck_comment_text(scene.name));
  deck += fmt::format("# {} steps of {} s; written for LAMMPS 29 Sep 2021 (pair_style granular)\n",
                      s.steps, num(s.timestep));
  line(deck, "units", "si");
  line(deck, "atom_style", "sphere");
  if (atoms_in_data_file(scene)) {
    line(deck, "atom_modify", "map array  # x[i] in variables; LAMMPS sorts atoms in memory as usual");
  } else {
    line(deck, "atom_modify", "map array sort 0 0.0  # x[i] in variables; atoms stay in id order");
  }
  line(deck, "dimension", "3");
  line(deck, "boundary", "f f f");
  line(deck, "newton", "off");
  line(deck, "comm_modify", "vel yes  # granular pairs need ghost velocities");
}

/// The groups of mobile and of fixed atoms.
void write_groups(std::string& deck, const AtomTypes& types) {
  if (const std::string mobile = types_where(types, false); !mobile.empty()) {
    line(deck, "group", "tr_mobile type " + mobile);
  }
  if (const std::string fixed = types_where(types, true); !fixed.empty()) {
    line(deck, "group", "tr_fixed type " + fixed);
  }
}

/// Box, atom types, atoms with diameter, density, velocities; mobile and fixed groups.
void write_atoms(std::string& deck, const cases::Scene& scene, const AtomTypes& types,
                 double duration, const DeckSettings& s) {
  if (atoms_in_data_file(scene)) {
    deck += fmt::format("# {} atoms (more than {}): box, types, diameters, densities, positions and velocities "
                        "come from the data file\n",
                        scene.particles.size(), kMaxInlineAtoms);
    if (types.per_atom_diameter) {
      deck += fmt::format("# more than {} (material, radius) classes: one atom type per material, diameter per atom\n",
                          kMaxAtomTypes);
    }
    for (std::size_t t = 0; t < types.types.size(); ++t) {
      deck += fmt::format("#   type {}: material '{}', {}\n", t + 1, deck_comment_text(scene.materials.at(types.types[t].material).name),
                          types.types[t].fixed ? "fixed" : "mobile");
    }
    line(deck, "read_data", s.data_file);
    write_groups(deck, types);
    return;
  }
  const Box box = simulation_box(scene, duration);
  deck += "# box: the bodies' bounding box widened by 2 v_max T + |g| T^2 + 2 r_max per side\n";
  line(deck, "region", fmt::format("tr_box block {} {} {} {} {} {} units box", num(box.low[0]),
                                   num(box.high[0]), num(box.low[1]), num(box.high[1]),
                                   num(box.low[2]), num(box.high[2])));
  line(deck, "create_box", fmt::format("{} tr_box", types.types.size()));
  deck += "# atom types, one per (material, radius, fixed) class:\n";
  for (std::size_t t = 0; t < types.types.size(); ++t) {
    deck += fmt::format("#   type {}: {}\n", t + 1, describe(scene, types.types[t]));
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    line(deck, "create_atoms",
         fmt::format("{} single {} {} {} units box  # particle {} = atom {}",
                     types.lammps_type(i), num(p.position[0]), num(p.position[1]),
                     num(p.position[2]), i, i + 1));
  }
  for (std::size_t t = 0; t < types.types.size(); ++t) {
    const AtomType& type = types.types[t];
    line(deck, "set", fmt::format("type {} diameter {}  # before density: mass = 4/3 pi r^3 rho",
                                  t + 1, num(2.0 * type.radius)));
    line(deck, "set", fmt::format("type {} density {}", t + 1,
                                  num(scene.materials.at(type.material).density)));
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    line(deck, "set",
         fmt::format("atom {} vx {} vy {} vz {} omega {} {} {}", i + 1, num(p.velocity[0]),
                     num(p.velocity[1]), num(p.velocity[2]), num(p.angular_velocity[0]),
                     num(p.angular_velocity[1]), num(p.angular_velocity[2])));
  }
  write_groups(deck, types);
}

/// `pair_style granular`, one `pair_coeff` per type pair, neighbour settings.
void write_pairs(std::string& deck, const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types) {
  line(deck, "pair_style", "granular");
  deck += "# explicit pair_coeff for every type pair: LAMMPS' own i-j mixing is never used\n";
  for (std::size_t a = 0; a < types.types.size(); ++a) {
    for (std::size_t b = a; b < types.types.size(); ++b) {
      const GranularCoeff coeff = map_pair_law(
          table.law(types.types[a].material, types.types[b].material),
          pair_context(scene, types, a, b));
      if (!coeff.normal_note.empty()) {
        deck += fmt::format("# types {}-{}: {}\n", a + 1, b + 1, deck_comment_text(coeff.normal_note));
      }
      deck += fmt::format("# types {}-{}: {}\n", a + 1, b + 1, deck_comment_text(coeff.damping_note));
      line(deck, "pair_coeff",
           fmt::format("{} {} {}", a + 1, b + 1, pair_coeff_arguments(coeff)));
    }
  }
  line(deck, "neighbor", fmt::format("{} bin", num(neighbour_skin(scene))));
  line(deck, "neigh_modify", "delay 0 every 1 check yes");
}

/// One `fix wall/gran granular` (planes) or `fix wall/gran/region granular` (cylinders and cones,
/// on a `region … open 1 open 2`) per (wall, mobile atom type): η depends on the type's mass. A wall
/// removed at t ≤ 0 stood only through the preparation and is left out.
void write_walls(std::string& deck, const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types) {
  if (scene.walls.empty()) return;
  deck += "# walls: parameters belong to the particle-wall interaction (E_in = 2(1-nu) E*, "
          "explicit k_t; lever arm r; delta = 0 counts as contact)\n";
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    const cases::WallSpec& wall = scene.walls[w];
    if (!wall_in_run(wall)) {
      deck += fmt::format("# wall {} ('{}') is removed at t <= 0: only the preparation met it\n", w, deck_comment_text(wall.name));
      continue;
    }
    if (const auto region = wall_region_arguments(wall)) {
      deck += fmt::format("# wall {} ('{}'): open at both ends, two-sided; R* uses the region's curvature (-2 rho)\n",
                          w, deck_comment_text(wall.name));
      line(deck, "region", fmt::format("{} {}", wall_region_id(w), *region));
    }
  }
  for (std::size_t t = 0; t < types.types.size(); ++t) {
    const AtomType& type = types.types[t];
    if (type.fixed) continue;
    line(deck, "group", fmt::format("tr_type_{0} type {0}", t + 1));
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      const cases::WallSpec& wall = scene.walls[w];
      if (!wall_in_run(wall)) continue;
      const std::optional<WallPlane> plane = wall_plane(wall);
      const std::optional<std::string> region = wall_region_arguments(wall);
      if (!plane && !region) continue;  // supports() reports it
      PairContext context;
      context.reduced_mass = type.mass;
      context.per_atom_masses = types.per_atom_diameter;
      context.poisson_ratio = written_poisson(scene, type.material, wall.material);
      context.wall = true;
      const GranularCoeff coeff =
          map_pair_law(table.law(type.material, wall.material), context);
      deck += fmt::format("# wall {} ('{}') x type {}: {}; {}\n", w, deck_comment_text(wall.name), t + 1,
                          deck_comment_text(coeff.normal_note), deck_comment_text(coeff.damping_note));
      if (plane) {
        line(deck, "fix",
             fmt::format("{} tr_type_{} wall/gran granular {} {}", wall_fix_id(w, t + 1), t + 1,
                         pair_coeff_arguments(coeff), wall_plane_arguments(*plane)));
      } else {
        line(deck, "fix",
             fmt::format("{} tr_type_{} wall/gran/region granular {} region {}", wall_fix_id(w, t + 1), t + 1,
                         pair_coeff_arguments(coeff), wall_region_id(w)));
      }
    }
  }
}

/// Pair-force store, walls, contact-force store, gravity, motion, integration, freeze (in that
/// order) and the time step.
void write_fixes(std::string& deck, const cases::Scene& scene, const dem::PairTable& table, const AtomTypes& types,
                 const DeckSettings& s) {
  const bool any_mobile = !types_where(types, false).empty();
  const bool any_fixed = !types_where(types, true).empty();
  if (s.timing_only) {
    write_walls(deck, scene, table, types);
  } else {
    deck += "# the pair forces alone, stored before gravity is added and frozen atoms are zeroed\n";
    line(deck, "fix", fmt::format("{} all store/force", kPairForceFix));
    write_walls(deck, scene, table, types);
  }
  if (!s.timing_only && !scene.walls.empty()) {
    deck += "# pair + wall forces (the wall force is the difference of the two stores)\n";
    line(deck, "fix", fmt::format("{} all store/force", kContactForceFix));
  }
  const cases::Vector3& g = scene.gravity;
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (any_mobile && g_norm > 0.0) {
    line(deck, "fix", fmt::format("tr_gravity tr_mobile gravity {} vector {} {} {}", num(g_norm),
                                  num(g[0]), num(g[1]), num(g[2])));
  }
  const std::vector<std::string> motion = motion_commands(scene);
  if (!motion.empty()) deck += "# prescribed motion (fix move variable: x = x(0) + d(time))\n";
  for (const auto& command : motion) command_line(deck, command);
  if (any_mobile) {
    if (scene.integration.rotation) {
      line(deck, "fix", "tr_integrate tr_mobile nve/sphere  # velocity Verlet of x and omega");
    } else {
      line(deck, "fix",
           "tr_integrate tr_mobile nve  # velocity Verlet of x; omega held (rotation = false)");
    }
  }
  if (any_fixed) {
    line(deck, "fix", "tr_freeze tr_fixed freeze  # pairs then use m_eff = the mobile mass");
  }
  line(deck, "timestep", num(s.timestep));
}

/// The trace (`fix print`) and the snapshots (`dump custom` at the snapshot steps).
void write_outputs(std::string& deck, const cases::Scene& scene, const AtomTypes& types,
                   const DeckSettings& s) {
  const TracePrintPlan plan = trace_print_plan(scene, types);
  for (const auto& command : plan.computes) command_line(deck, command);
  deck += "# trace columns (each formula in full: a v_name reference would round to 15 digits)\n";
  command_line(deck, fix_print_command(plan, scene.output.trace_every, s.trace_file));

  const SnapshotSchedule schedule = snapshot_schedule(scene.output.snapshot_times, s.timestep, s.steps);
  if (schedule.next_step.empty()) return;
  line(deck, "variable", fmt::format("tr_snapshot_step equal \"{}\"", schedule.next_step));
  line(deck, "dump", fmt::format("tr_snapshots all custom 1 {} id x y z vx vy vz omegax omegay "
                                 "omegaz",
                                 s.snapshot_file));
  line(deck, "dump_modify",
       fmt::format("tr_snapshots sort id format float %.17g every v_tr_snapshot_step{}",
                   schedule.first ? " first yes" : ""));
}

}  // namespace

double written_poisson(const cases::Scene& scene, std::size_t material_a,
                       std::size_t material_b) {
  for (const std::size_t m : {material_a, material_b}) {
    if (const auto nu = scene.materials.at(m).poisson_ratio) return *nu;
  }
  return 0.0;
}

PairContext pair_context(const cases::Scene& scene, const AtomTypes& types, std::size_t a,
                         std::size_t b) {
  PairContext c;
  c.reduced_mass = types.reduced_mass(a, b);
  c.per_atom_masses = types.per_atom_diameter;
  c.poisson_ratio = written_poisson(scene, types.types[a].material, types.types[b].material);
  return c;
}

std::string wall_region_id(std::size_t wall) { return fmt::format("tr_wall_region_{}", wall); }

std::string wall_fix_id(std::size_t wall, std::size_t lammps_type) {
  return fmt::format("tr_wall_{}_{}", wall, lammps_type);
}

std::string write_deck(const cases::Scene& scene, const DeckSettings& settings) {
  return write_deck(PreparedScene(scene), settings);
}

std::string write_deck(const PreparedScene& prepared, const DeckSettings& settings) {
  const cases::Scene& scene = prepared.scene();
  const AtomTypes types = classify_particles(scene);
  std::string deck;
  write_header(deck, scene, settings);
  write_atoms(deck, scene, types, static_cast<double>(settings.steps) * settings.timestep, settings);
  write_pairs(deck, scene, prepared.pair_table(), types);
  write_fixes(deck, scene, prepared.pair_table(), types, settings);
  if (settings.timing_only) {
    line(deck, "thermo", fmt::format("{}", std::max<std::uint64_t>(settings.steps, 1)));
  } else {
    write_outputs(deck, scene, types, settings);
  }
  if (!settings.extra_commands.empty()) {
    deck += "# extra commands\n" + settings.extra_commands;
    if (deck.back() != '\n') deck += '\n';
  }
  line(deck, "run", fmt::format("{}", settings.steps));
  return deck;
}

std::string write_atom_data(const cases::Scene& scene, const DeckSettings& settings) {
  const AtomTypes types = classify_particles(scene);
  const Box box = simulation_box(scene, static_cast<double>(settings.steps) * settings.timestep);
  std::string out = fmt::format("dem-workbench atoms of case '{}' (generated, do not edit)\n\n{} atoms\n{} atom types\n\n",
                                deck_comment_text(scene.name), scene.particles.size(), types.types.size());
  out += atom_data_body(scene, types.type_of, box.low, box.high, "Atoms # sphere");
  return out;
}

}  // namespace reference::lammps
