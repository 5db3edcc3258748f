// SPDX-License-Identifier: MIT
#include "reference/lammps/trace_columns.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "reference/lammps/wall_mapping.hpp"

namespace reference::lammps {
namespace {

/// IDs of the per-atom computes the trace reads.
constexpr std::string_view kAtomCompute = "tr_atom";       // radius omegax omegay omegaz
constexpr std::string_view kContactCompute = "tr_contacts";  // contacts per atom (δ ≥ 0)

/// LAMMPS per-atom expression of one particle quantity for atom `id`.
std::string particle_expression(std::string_view quantity, std::size_t id, bool fixed) {
  if (quantity == "x" || quantity == "y" || quantity == "z" || quantity == "vx" ||
      quantity == "vy" || quantity == "vz") {
    return fmt::format("{}[{}]", quantity, id);
  }
  if (quantity == "wx") return fmt::format("c_{}[{}][2]", kAtomCompute, id);
  if (quantity == "wy") return fmt::format("c_{}[{}][3]", kAtomCompute, id);
  if (quantity == "wz") return fmt::format("c_{}[{}][4]", kAtomCompute, id);
  const int axis = quantity == "fx" ? 1 : quantity == "fy" ? 2 : 3;
  if (fixed) return fmt::format("f_{}[{}][{}]", kPairForceFix, id, axis);
  return fmt::format("{}[{}]", quantity, id);
}

/// Formulas of one pair's geometry and forces for atoms ip and iq (1-based ids), written out
/// in full (no helper variables: see trace_print_plan).
struct PairFormulas {
  std::string overlap;  ///< r_p + r_q − |x_p − x_q|
  std::string fn;       ///< pair force on p along n, from a partner with a single contact
  std::string exact;    ///< 1 when fn is this pair's force alone
};

PairFormulas pair_formulas(std::size_t ip, std::size_t iq, bool only_pair) {
  const std::string dx = fmt::format("(x[{}]-x[{}])", ip, iq);
  const std::string dy = fmt::format("(y[{}]-y[{}])", ip, iq);
  const std::string dz = fmt::format("(z[{}]-z[{}])", ip, iq);
  const std::string d = fmt::format("sqrt({0}*{0}+{1}*{1}+{2}*{2})", dx, dy, dz);
  // The stored pair force of atom `id` projected on the pair vector, over its length.
  const auto projected = [&](std::size_t id) {
    return fmt::format("(f_{0}[{1}][1]*{2}+f_{0}[{1}][2]*{3}+f_{0}[{1}][3]*{4})/{5}",
                       kPairForceFix, id, dx, dy, dz, d);
  };
  PairFormulas f;
  f.overlap = fmt::format("((c_{0}[{1}][1]+c_{0}[{2}][1])-{3})", kAtomCompute, ip, iq, d);
  if (only_pair) {
    f.fn = projected(ip);
    f.exact = std::string(1, '1');
    return f;
  }
  f.fn = fmt::format("({0}>0)*((c_{1}[{2}]==1)*{3}+(c_{1}[{2}]!=1)*(-{4}))", f.overlap,
                     kContactCompute, ip, projected(ip), projected(iq));
  f.exact = fmt::format("({0}<=0)||(c_{1}[{2}]==1)||(c_{1}[{3}]==1)", f.overlap, kContactCompute,
                        ip, iq);
  return f;
}

/// Column index of `name` in `printed`; throws naming the column when it is absent.
std::size_t column_index(const cases::Trace& printed, std::string_view name) {
  const auto& names = printed.columns();
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (names[c] == name) return c;
  }
  throw std::runtime_error(fmt::format("LAMMPS trace file has no column '{}'", name));
}

/// Throws unless the step column holds 0, every, 2·every, … up to `steps`.
void check_steps(const cases::Trace& printed, std::size_t every, std::uint64_t steps) {
  const std::vector<double>& step = printed.values(column_index(printed, kStepColumn));
  const std::uint64_t expected_rows = steps / every + 1;
  if (step.size() != expected_rows) {
    throw std::runtime_error(fmt::format(
        "LAMMPS trace file has {} rows; expected {} (steps 0, {}, …, {})", step.size(),
        expected_rows, every, (expected_rows - 1) * every));
  }
  for (std::size_t k = 0; k < step.size(); ++k) {
    if (step[k] != static_cast<double>(k * every)) {
      throw std::runtime_error(fmt::format(
          "LAMMPS trace file row {} is step {}; expected step {}", k, step[k], k * every));
    }
  }
}

}  // namespace

std::string exact_column(std::size_t p, std::size_t q) {
  return cases::pair_column(p, q, "fn_exact");
}

TracePrintPlan trace_print_plan(const cases::Scene& scene, const AtomTypes& types) {
  TracePrintPlan plan;
  plan.computes.push_back(fmt::format("compute {} all property/atom radius omegax omegay omegaz",
                                      kAtomCompute));
  const auto add = [&plan](std::string name, std::string expression) {
    plan.columns.push_back({std::move(name), std::move(expression)});
  };
  add(std::string(kStepColumn), "step");
  add("time", "time");
  for (const std::size_t i : scene.output.trace_particles) {
    const bool fixed = types.types.at(types.type_of.at(i)).fixed;
    for (const auto q : cases::kParticleQuantities) {
      add(cases::particle_column(i, q), particle_expression(q, i + 1, fixed));
    }
  }
  if (!scene.output.trace_pairs.empty()) {
    plan.computes.push_back(fmt::format("compute {} all contact/atom", kContactCompute));
  }
  const bool only_pair = scene.particles.size() == 2 && scene.walls.empty();
  std::vector<PrintColumn> exact_columns;
  for (const auto& [p, q] : scene.output.trace_pairs) {
    PairFormulas f = pair_formulas(p + 1, q + 1, only_pair);
    add(cases::pair_column(p, q, "overlap"), std::move(f.overlap));
    add(cases::pair_column(p, q, "fn"), std::move(f.fn));
    exact_columns.push_back({exact_column(p, q), std::move(f.exact)});
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    const std::optional<WallPlane> plane = wall_plane(scene.walls.at(w));
    const std::size_t id = p + 1;
    if (!plane) {  // never written: supports() rejects such walls
      add(cases::wall_column(p, w, "overlap"), "0");
      add(cases::wall_column(p, w, "fn"), "0");
      continue;
    }
    add(cases::wall_column(p, w, "overlap"),
        fmt::format("(c_{}[{}][1]-{})", kAtomCompute, id, wall_distance_formula(*plane, id)));
    add(cases::wall_column(p, w, "fn"),
        fmt::format("{}(f_{}[{}][{}]-f_{}[{}][{}])", plane->lower ? "" : "-", kContactForceFix,
                    id, plane->axis + 1, kPairForceFix, id, plane->axis + 1));
  }
  for (auto& c : exact_columns) plan.columns.push_back(std::move(c));
  const bool any_mobile = std::any_of(scene.particles.begin(), scene.particles.end(),
                                      [](const cases::ParticleSpec& p) { return !p.fixed; });
  for (const std::string& a : scene.output.trace_aggregates) {
    if (a == "kinetic_energy") {
      if (any_mobile) plan.computes.emplace_back("compute tr_ke tr_mobile ke");
      add(cases::aggregate_column(a), any_mobile ? "c_tr_ke" : "0");
    } else if (a == "rotational_energy") {
      if (any_mobile) plan.computes.emplace_back("compute tr_erot tr_mobile erotate/sphere");
      add(cases::aggregate_column(a), any_mobile ? "c_tr_erot" : "0");
    } else if (a == "coordination_number") {
      if (scene.output.trace_pairs.empty()) {
        plan.computes.push_back(fmt::format("compute {} all contact/atom", kContactCompute));
      }
      plan.computes.push_back(fmt::format("compute tr_coordination all reduce ave c_{}", kContactCompute));
      add(cases::aggregate_column(a), "c_tr_coordination");
    }
  }

  plan.sources = {
      "time: LAMMPS `time` (step·Δt)",
      "x, y, z, vx, vy, vz: x[i] … vz[i] at the end of the step (after the second half kick)",
      "wx, wy, wz: `compute property/atom omegax omegay omegaz`",
      "fx, fy, fz: fx[i] … for a mobile sphere (contacts + gravity); for a fixed sphere its "
      "contact force from `fix store/force`, taken before `fix freeze` zeroes it",
      "overlap: r_p + r_q − |x_p − x_q| from LAMMPS radii and positions",
      "fn: the pair force LAMMPS applied (`fix store/force`, before gravity and freeze) on a "
      "partner whose only contact (`compute contact/atom`) is this pair, projected on n; 0 "
      "while δ ≤ 0 (two-sphere scenes: never gated, so a JKR neck's tension shows)",
      "wall overlap: r − distance of the centre from the plane; wall fn: (stored pair + wall "
      "force − stored pair force)·n, i.e. the walls' force on the sphere along the normal",
      "all.kinetic_energy, all.rotational_energy: `compute ke` and `compute erotate/sphere` of the "
      "mobile atoms; all.coordination_number: the mean of `compute contact/atom` (pairs with "
      "δ ≥ 0) over all atoms"};
  return plan;
}

std::string fix_print_command(const TracePrintPlan& plan, std::size_t every,
                              std::string_view file) {
  std::string text;
  std::string title = "#";
  for (const PrintColumn& c : plan.columns) {
    if (!text.empty()) text += ' ';
    text += fmt::format("$({}:%.17g)", c.expression);
    title += ' ' + c.name;
  }
  return fmt::format("fix tr_print all print {} \"{}\" file {} screen no title \"{}\"", every,
                     text, file, title);
}

AssembledTrace assemble_trace(const cases::Scene& scene, const cases::Trace& printed,
                              std::uint64_t steps) {
  const std::size_t every = scene.output.trace_every;
  check_steps(printed, every, steps);
  AssembledTrace out;
  out.trace = cases::trace_layout(scene);  // the column order every engine shares
  std::vector<std::size_t> sources;
  for (const std::string& name : out.trace.columns()) {
    sources.push_back(column_index(printed, name));
  }
  std::vector<double> row(sources.size());
  for (std::size_t r = 0; r < printed.rows(); ++r) {
    for (std::size_t c = 0; c < sources.size(); ++c) row[c] = printed.values(sources[c])[r];
    out.trace.append_row(row);
  }

  const std::vector<double>& time = printed.values(column_index(printed, "time"));
  for (const auto& [p, q] : scene.output.trace_pairs) {
    const std::string fn = cases::pair_column(p, q, "fn");
    const std::vector<double>& exact =
        printed.values(column_index(printed, exact_column(p, q)));
    std::size_t inexact = 0;
    std::size_t first = 0;
    for (std::size_t r = 0; r < exact.size(); ++r) {
      if (exact[r] != 0.0) continue;
      if (inexact == 0) first = r;
      ++inexact;
    }
    if (inexact > 0) {
      out.warnings.push_back(fmt::format(
          "{}: at {} of {} rows (first at t = {:.6g} s) both particles {} and {} also touched "
          "other spheres, so LAMMPS' per-atom forces do not isolate this pair; the value there is "
          "particle {}'s total contact force projected on the pair normal",
          fn, inexact, exact.size(), time[first], p, q, q));
    }
  }
  return out;
}

}  // namespace reference::lammps
