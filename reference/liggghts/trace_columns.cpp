// SPDX-License-Identifier: MIT
#include "reference/liggghts/trace_columns.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "reference/liggghts/primitive_walls.hpp"
#include "support/text_tokens.hpp"

namespace reference::liggghts {
namespace {

constexpr std::string_view kContactCompute = "tr_contacts";  // sphere–sphere contacts per atom

/// Formula of one particle quantity of atom `id`.
std::string particle_formula(std::string_view q, std::size_t id, bool fixed) {
  if (q == "wx") return fmt::format("omegax[{}]", id);
  if (q == "wy") return fmt::format("omegay[{}]", id);
  if (q == "wz") return fmt::format("omegaz[{}]", id);
  if (fixed && (q == "fx" || q == "fy" || q == "fz")) {
    // fix freeze zeroes a frozen atom's force: its contact force is the stored one.
    return fmt::format("f_{}[{}][{}]", kPairForceFix, id, q == "fx" ? 1 : q == "fy" ? 2 : 3);
  }
  return fmt::format("{}[{}]", q, id);
}

/// The number `token` on line `line` of `file`; throws naming both when it is none.
double number(std::string_view token, std::string_view file, std::size_t line) {
  if (const std::optional<double> v = support::parse_number(token)) return *v;
  throw std::runtime_error(fmt::format("{}:{}: '{}' is not a number", file, line, token));
}

}  // namespace

std::string column_variable(std::size_t k) { return fmt::format("tr_c{}", k); }

std::string exact_column(std::size_t p, std::size_t q) { return cases::pair_column(p, q, "fn_exact"); }

AssembledTrace assemble_trace(const cases::Scene& scene, const cases::Trace& printed) {
  AssembledTrace out;
  out.trace = cases::trace_layout(scene);  // the column order every engine shares
  const auto index_of = [&](const std::string& name) {
    const auto& names = printed.columns();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error(fmt::format("LIGGGHTS trace has no column '{}'", name));
    return static_cast<std::size_t>(it - names.begin());
  };
  std::vector<std::size_t> sources;
  for (const std::string& name : out.trace.columns()) sources.push_back(index_of(name));
  std::vector<double> row(sources.size());
  for (std::size_t r = 0; r < printed.rows(); ++r) {
    for (std::size_t c = 0; c < sources.size(); ++c) row[c] = printed.values(sources[c])[r];
    out.trace.append_row(row);
  }
  const std::vector<double>& time = printed.values(index_of("time"));
  for (const auto& [p, q] : scene.output.trace_pairs) {
    const std::vector<double>* exact = printed.column(exact_column(p, q));
    if (exact == nullptr) continue;  // two bodies alone: the stored force is the pair's
    std::size_t inexact = 0;
    std::size_t first = 0;
    for (std::size_t r = 0; r < exact->size(); ++r) {
      if ((*exact)[r] != 0.0) continue;
      if (inexact == 0) first = r;
      ++inexact;
    }
    if (inexact > 0) {
      out.warnings.push_back(fmt::format(
          "{}: at {} of {} rows (first at t = {:.6g} s) both particles {} and {} also touched other spheres, so "
          "LIGGGHTS' per-atom forces do not isolate this pair; the value there is particle {}'s total contact "
          "force projected on the pair normal",
          cases::pair_column(p, q, "fn"), inexact, exact->size(), time[first], p, q, q));
    }
  }
  return out;
}

std::string wall_fix_id(std::size_t wall) { return fmt::format("tr_wall_{}", wall); }

TracePlan trace_plan(const cases::Scene& scene, const AtomTypes& types) {
  TracePlan plan;
  const auto add = [&plan](std::string name, std::string formula) {
    plan.columns.push_back({std::move(name), std::move(formula)});
  };
  add("time", "step*dt");
  for (const std::size_t i : scene.output.trace_particles) {
    const bool fixed = types.particles.at(types.type_of.at(i)).fixed;
    for (const auto q : cases::kParticleQuantities) add(cases::particle_column(i, q), particle_formula(q, i + 1, fixed));
  }
  const bool only_pair = scene.particles.size() == 2 && scene.walls.empty();
  bool contacts = false;
  std::vector<TraceColumn> exact;  // after the trace's columns: whether each pair's fn is its own
  for (const auto& [p, q] : scene.output.trace_pairs) {
    const std::size_t ip = p + 1, iq = q + 1;
    const std::string dx = fmt::format("(x[{}]-x[{}])", ip, iq);
    const std::string dy = fmt::format("(y[{}]-y[{}])", ip, iq);
    const std::string dz = fmt::format("(z[{}]-z[{}])", ip, iq);
    const std::string d = fmt::format("sqrt({0}*{0}+{1}*{1}+{2}*{2})", dx, dy, dz);
    const auto projected = [&](std::size_t id) {
      return fmt::format("(f_{0}[{1}][1]*{2}+f_{0}[{1}][2]*{3}+f_{0}[{1}][3]*{4})/{5}", kPairForceFix, id, dx, dy,
                         dz, d);
    };
    const std::string overlap = fmt::format("((r[{}]+r[{}])-{})", ip, iq, d);
    add(cases::pair_column(p, q, "overlap"), overlap);
    if (only_pair) {
      add(cases::pair_column(p, q, "fn"), projected(ip));
    } else {
      contacts = true;
      // The stored pair force of a partner whose only contact is this pair.
      add(cases::pair_column(p, q, "fn"),
          fmt::format("({0}>0)*((c_{1}[{2}]==1)*{3}+(c_{1}[{2}]!=1)*(-{4}))", overlap, kContactCompute, ip,
                      projected(ip), projected(iq)));
      exact.push_back({exact_column(p, q), fmt::format("({0}<=0)||(c_{1}[{2}]==1)||(c_{1}[{3}]==1)", overlap,
                                                        kContactCompute, ip, iq)});
    }
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    const std::optional<WallPlane> plane = wall_plane(scene.walls.at(w));
    if (!plane) throw std::invalid_argument(fmt::format("wall {} is no primitive plane", w));  // supports() rejects it
    const std::size_t id = p + 1;
    add(cases::wall_column(p, w, "overlap"), fmt::format("(r[{}]-{})", id, distance_formula(*plane, id)));
    // A wall removed at t <= 0 has no fix (and acts on nothing); a frozen sphere meets no wall.
    const bool acts = wall_in_run(scene.walls.at(w)) && !types.particles.at(types.type_of.at(p)).fixed;
    add(cases::wall_column(p, w, "fn"),
        acts ? fmt::format("{}f_force_{}[{}][{}]", plane->sign > 0.0 ? "" : "-", wall_fix_id(w), id, plane->axis + 1)
             : std::string("0"));
  }
  const bool any_mobile = std::any_of(scene.particles.begin(), scene.particles.end(),
                                      [](const cases::ParticleSpec& p) { return !p.fixed; });
  for (const std::string& a : scene.output.trace_aggregates) {
    if (a == "kinetic_energy") {
      if (any_mobile) plan.commands.emplace_back("compute tr_ke tr_mobile ke");
      add(cases::aggregate_column(a), any_mobile ? "c_tr_ke" : "0");
    } else if (a == "rotational_energy") {
      if (any_mobile) plan.commands.emplace_back("compute tr_erot tr_mobile erotate/sphere");
      add(cases::aggregate_column(a), any_mobile ? "c_tr_erot" : "0");
    } else if (a == "coordination_number") {
      contacts = true;
      plan.commands.push_back(fmt::format("compute tr_coordination all reduce ave c_{}", kContactCompute));
      add(cases::aggregate_column(a), "c_tr_coordination");
    }
  }
  for (TraceColumn& c : exact) plan.columns.push_back(std::move(c));
  if (contacts) plan.commands.insert(plan.commands.begin(), fmt::format("compute {} all contact/atom", kContactCompute));
  plan.sources = {
      "time: step·dt",
      "x … vz, wx … wz: x[i] … omegaz[i] after the step's closing half kick",
      "fx, fy, fz: fx[i] … (contacts and gravity) of a mobile sphere; of a frozen one its pair force from "
      "`fix store/force`, taken before `fix freeze` zeroes it",
      "overlap: r_p + r_q − |x_p − x_q| from LIGGGHTS radii r[i] and positions",
      "fn: the stored pair force (fix store/force before walls and gravity) projected on the pair normal; with "
      "more than two bodies, that of a partner whose only contact (compute contact/atom) is the pair",
      "wall overlap and fn: r − the centre's distance from the plane; the wall's force on the sphere along the "
      "wall's normal (fix wall/gran store_force yes)",
      "all.kinetic_energy, all.rotational_energy: compute ke and erotate/sphere of the mobile atoms; "
      "all.coordination_number: the mean of compute contact/atom"};
  return plan;
}

cases::Trace trace_from_thermo(const cases::Scene& scene, const TracePlan& plan, std::string_view log_text,
                               std::string_view file_name, std::uint64_t steps) {
  const std::size_t every = scene.output.trace_every;
  std::vector<std::string> header{"Step"};
  for (std::size_t k = 0; k < plan.columns.size(); ++k) header.push_back(column_variable(k));
  const std::vector<std::string_view> lines = support::split_lines(log_text);
  std::size_t line = 0;
  for (; line < lines.size(); ++line) {
    const std::vector<std::string_view> words = support::split_words(lines[line]);
    if (words.size() == header.size() && std::equal(words.begin(), words.end(), header.begin())) break;
  }
  if (line == lines.size()) {
    throw std::runtime_error(fmt::format("{}: no thermo table headed '{} …'", file_name, header.front() + " " +
                                                                                             header.at(1)));
  }
  cases::Trace trace;
  for (const TraceColumn& c : plan.columns) trace.add_column(c.name);
  std::vector<double> row(plan.columns.size());
  std::uint64_t expected = 0;
  // LIGGGHTS prints the last step even when it is off the output grid: one such row is not the trace's.
  bool closing_row_allowed = steps % every != 0;
  for (++line; line < lines.size(); ++line) {
    const std::string_view text = lines[line];
    if (text.substr(0, 9) == "Loop time") break;
    if (text.substr(0, 7) == "WARNING") continue;
    const std::vector<std::string_view> words = support::split_words(text);
    if (words.size() != header.size()) {
      throw std::runtime_error(fmt::format("{}:{}: a thermo row of {} values; expected {}", file_name, line + 1,
                                           words.size(), header.size()));
    }
    const double step = number(words[0], file_name, line + 1);
    if (expected <= steps && step == static_cast<double>(expected)) {
      for (std::size_t c = 0; c < row.size(); ++c) row[c] = number(words[c + 1], file_name, line + 1);
      trace.append_row(row);
      expected += every;
      continue;
    }
    if (closing_row_allowed && step == static_cast<double>(steps) && expected > steps) {
      closing_row_allowed = false;
      continue;
    }
    throw std::runtime_error(fmt::format("{}:{}: thermo row at step {}; expected {}", file_name, line + 1, step,
                                         expected <= steps ? fmt::format("step {}", expected) : "no more rows"));
  }
  const std::uint64_t wanted = steps / every + 1;
  if (trace.rows() != wanted) {
    throw std::runtime_error(fmt::format("{}: the thermo table has {} rows; expected {} (steps 0, {}, …, {})",
                                         file_name, trace.rows(), wanted, every, (wanted - 1) * every));
  }
  return trace;
}

}  // namespace reference::liggghts
