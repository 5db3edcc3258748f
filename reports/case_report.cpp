// SPDX-License-Identifier: MIT
#include "reports/case_report.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "cases/catalogue.hpp"
#include "cases/mixed_pairs.hpp"
#include "dem/integrators/scheme_id.hpp"
#include "reports/energy_plot.hpp"
#include "reports/gnuplot.hpp"
#include "reports/markdown.hpp"
#include "reports/packing_plot.hpp"
#include "reports/snapshot_view.hpp"

namespace reports {
namespace {

std::string heading(int level, const std::string& text) {
  return std::string(static_cast<std::size_t>(level), '#') + " " + text + "\n\n";
}

std::string unit_of(const std::string& metric) {
  for (const auto& m : cases::metric_catalogue()) {
    if (m.name == metric) return std::string(m.unit);
  }
  return "";
}

std::string model_section(const cases::Scene& scene, int level) {
  std::string md = heading(level, "Model and parameters");
  MarkdownTable slots({"slot", "sub-model"});
  slots.add_row({"normal", scene.model.normal});
  slots.add_row({"damping", scene.model.damping});
  slots.add_row({"tangential", scene.model.tangential});
  slots.add_row({"cohesion", scene.model.cohesion});
  slots.add_row({"rolling", scene.model.rolling});
  md += slots.render() + "\n";
  MarkdownTable pairs({"pair", "property", "value", "origin"});
  for (const auto& p : cases::mixed_pairs(scene)) {
    for (const auto& v : p.values) {
      pairs.add_row({p.material_a + "–" + p.material_b, v.key, format_number(v.value), v.origin});
    }
  }
  if (pairs.rows() > 0) md += "Mixed pair table:\n\n" + pairs.render() + "\n";
  const auto& in = scene.integration;
  md += fmt::format(
      "Integration: `{}`, Δt = {}, duration {} s, {} particles ({} fixed), trace every {} "
      "step(s).\n\n",
      dem::scheme_info(in.scheme).keyword, in.timestep ? fmt::format("{:.6g} s", *in.timestep) : "auto",
      in.duration, scene.particles.size(),
      std::count_if(scene.particles.begin(), scene.particles.end(),
                    [](const auto& p) { return p.fixed; }),
      scene.output.trace_every);
  return md;
}

/// The preparation stages and what they did (empty without stages).
std::string stages_section(const cases::Scene& scene, int level) {
  if (scene.stage_log.empty()) return {};
  std::string md = heading(level, "Preparation stages");
  md += "Run in the core before any engine; every engine starts from their result "
        "(`prepared_particles.csv`).\n\n";
  MarkdownTable t({"stage", "kind", "figures", "source"});
  for (const cases::StageRecord& st : scene.stage_log) {
    std::string figures;
    for (const auto& [name, value] : st.figures) {
      figures += (figures.empty() ? "" : ", ") + fmt::format("{} = {}", name, format_number(value));
    }
    t.add_row({st.name, st.kind, figures, st.cached ? "stage cache" : "run"});
  }
  return md + t.render() + "\n";
}

std::string runs_section(const comparison::CaseOutcome& o, int level) {
  std::string md = heading(level, "Engines");
  MarkdownTable t({"engine", "status", "version", "result", "wall time (s)", "note"});
  for (const auto& r : o.runs) {
    const auto original = r.conventions.find("original wall time");
    const std::string source = r.source == "cache" ? "cached" : r.source == "baseline" ? "committed baseline" : "ran";
    t.add_row({r.engine, std::string(cases::to_string(r.status)), r.version, source,
               fmt::format("{:.3f}{}", r.wall_time_s,
                           original != r.conventions.end() ? " (ran in " + original->second + ")" : ""),
               r.reason});
  }
  return md + t.render() + "\n";
}

/// The reference codes the case does not list, with their drivers' verdicts (empty when the
/// command did not ask them).
std::string unlisted_section(const comparison::CaseOutcome& o, int level) {
  if (o.unlisted.empty()) return {};
  std::string md = heading(level, "Reference codes not among the engines");
  md += "Each driver was asked whether its code can express the prepared scene; none of them ran.";
  if (std::any_of(o.unlisted.begin(), o.unlisted.end(), [](const auto& u) { return u.reason.empty(); })) {
    md += " A code that can is not run here because the run's engines (the case's `[compare] engines`, or "
          "`--engines`) leave it out (a many-body case is compared over seeds in cross-code ensembles instead).";
  }
  md += "\n\n";
  MarkdownTable t({"code", "verdict", "reason"});
  for (const auto& u : o.unlisted) {
    t.add_row({u.engine, unlisted_verdict(u), u.reason.empty() ? "—" : u.reason});
  }
  return md + t.render() + "\n";
}

std::string metrics_section(const comparison::CaseOutcome& o, int level) {
  if (o.scene.compare.metrics.empty()) return "";
  std::vector<std::string> header{"metric", "unit"};
  for (const auto& r : o.runs) header.push_back(r.engine);
  MarkdownTable t(header);
  for (const auto& name : o.scene.compare.metrics) {
    std::vector<std::string> row{name, unit_of(name)};
    for (const auto& r : o.runs) {
      const auto& set = o.metrics.at(r.engine);
      const auto it = set.find(name);
      if (it == set.end() || !it->second.value) {
        row.push_back(r.status == cases::RunStatus::ok && it != set.end() ? "— (" + it->second.problem + ")"
                                                                          : "—");
      } else {
        row.push_back(format_number(it->second.value) +
                      (it->second.source == "closed form" ? " (closed form)" : ""));
      }
    }
    t.add_row(row);
  }
  return heading(level, "Metrics") + t.render() + "\n";
}

/// Overlay plots of every engine's trace; returns the markdown image lines.
std::string plots_section(const comparison::CaseOutcome& o, const std::filesystem::path& plot_dir,
                          const std::filesystem::path& report_dir, int level) {
  Plot position;
  position.title = "Subject displacement along the collision axis";
  position.xlabel = "time (s)";
  position.ylabel = "displacement (m)";
  Plot overlap;
  overlap.title = "Overlap of the compared pair";
  overlap.xlabel = "time (s)";
  overlap.ylabel = "overlap (m)";
  Plot force;
  force.title = "Normal force against overlap";
  force.xlabel = "overlap (m)";
  force.ylabel = "normal force (N)";
  Plot energy;
  energy.title = "Energy ledger (in-house)";
  energy.xlabel = "time (s)";
  energy.ylabel = "energy (J)";
  const auto contact_column = [&](std::string_view q) -> std::optional<std::string> {
    if (o.scene.compare.pair) return cases::pair_column(o.scene.compare.pair->first, o.scene.compare.pair->second, q);
    if (o.scene.compare.wall_contact) {
      return cases::wall_column(o.scene.compare.wall_contact->first, o.scene.compare.wall_contact->second, q);
    }
    return std::nullopt;
  };
  for (const auto& r : o.runs) {
    if (r.status != cases::RunStatus::ok) continue;
    const auto* t = r.trace.column("time");
    if (t == nullptr) continue;
    const std::string style = r.engine == "analytic" ? "lines dt 2" : "lines";
    if (const auto d = comparison::axis_displacement(o.scene, r.trace)) {
      position.series.push_back({r.engine, *t, *d, style, {}});
    }
    if (const auto ov_name = contact_column("overlap")) {
      const auto* ov = r.trace.column(*ov_name);
      const auto* fn = r.trace.column(*contact_column("fn"));
      if (ov != nullptr) overlap.series.push_back({r.engine, *t, *ov, style, {}});
      if (ov != nullptr && fn != nullptr) force.series.push_back({r.engine, *ov, *fn, style, {}});
    }
    if (!r.energy.empty()) {
      const std::vector<Series> curves = energy_series(r, energy.series.empty());
      energy.series.insert(energy.series.end(), curves.begin(), curves.end());
    }
  }
  std::string md;
  // Difference of each engine's displacement from the reference's, sample by sample, relative to
  // the reference's largest overlap (only where both traces share their sample times).
  Plot difference;
  difference.title = "Displacement difference from " + o.scene.compare.reference + " / its max overlap";
  difference.xlabel = "time (s)";
  difference.ylabel = "relative difference";
  const cases::RunResult* ref = nullptr;
  for (const auto& r : o.runs) {
    if (r.engine == o.scene.compare.reference && r.status == cases::RunStatus::ok) ref = &r;
  }
  const auto ref_overlap = ref != nullptr ? contact_column("overlap") : std::nullopt;
  const auto* ref_ov = ref_overlap ? ref->trace.column(*ref_overlap) : nullptr;
  const auto ref_d = ref != nullptr ? comparison::axis_displacement(o.scene, ref->trace) : std::nullopt;
  if (ref_ov != nullptr && ref_d && !ref_ov->empty()) {
    const double scale = *std::max_element(ref_ov->begin(), ref_ov->end());
    for (const auto& r : o.runs) {
      if (&r == ref || r.status != cases::RunStatus::ok || !(scale > 0.0)) continue;
      const auto d = comparison::axis_displacement(o.scene, r.trace);
      const auto* t = r.trace.column("time");
      if (!d || t == nullptr || d->size() != ref_d->size()) continue;
      reports::Series series{r.engine, *t, {}, "lines", {}};
      for (std::size_t k = 0; k < d->size(); ++k) series.y.push_back(((*d)[k] - (*ref_d)[k]) / scale);
      difference.series.push_back(std::move(series));
    }
  }
  const std::optional<Plot> fluidisation = fluidisation_plot(o);
  const Plot none;
  const std::array<std::pair<const Plot*, const char*>, 6> plots{
      {{&position, "position.png"}, {&overlap, "overlap.png"}, {&force, "force_overlap.png"},
       {&difference, "difference.png"}, {&energy, "energy.png"},
       {fluidisation ? &*fluidisation : &none, "fluidisation.png"}}};
  for (const auto& [plot, file] : plots) {
    if (plot->series.empty()) continue;
    const std::filesystem::path png = plot_dir / file;
    if (const auto problem = render_png(*plot, png)) {
      md += fmt::format("- plot `{}` not drawn: {}\n", file, *problem);
    } else {
      md += fmt::format("![{}]({})\n\n", plot->title,
                        std::filesystem::relative(png, report_dir).generic_string());
    }
  }
  return md.empty() ? "" : heading(level, "Plots") + md + "\n";
}

/// Pictures of the bed (cases with a compare.packing region): up to six snapshots of the reference
/// engine's run (else the first that ran), seen along x and coloured by speed — the first, then
/// those of the fluidisation when the bed empties (fluidisation_frames).
std::string snapshots_section(const comparison::CaseOutcome& o, const std::filesystem::path& plot_dir,
                              const std::filesystem::path& report_dir, int level) {
  if (!o.scene.compare.packing) return "";
  const cases::RunResult* shown = nullptr;
  for (const auto& r : o.runs) {
    if (r.status != cases::RunStatus::ok || r.snapshots.empty()) continue;
    if (shown == nullptr || r.engine == o.scene.compare.reference) shown = &r;
  }
  if (shown == nullptr) return "";
  const ProjectionWindow window = packing_window(o.scene, shown->snapshots);
  std::string md = fmt::format("Engine `{}`, seen along x (the ORF's view); the outline is the packing region, the "
                               "colour the speed (0 to {:.3g} m/s), nearer spheres over farther ones.\n\n",
                               shown->engine, window.speed_max);
  std::filesystem::create_directories(plot_dir);
  std::vector<double> orf;
  const auto bed = comparison::packing_series(o.scene, *shown);
  if (const auto* samples = std::get_if<std::vector<comparison::PackingSample>>(&bed)) {
    for (const auto& sample : *samples) orf.push_back(sample.orf);
  }
  const std::vector<std::size_t> frames =
      orf.size() == shown->snapshots.size() ? fluidisation_frames(orf, 6) : frame_indices(shown->snapshots.size(), 6);
  for (const std::size_t k : frames) {
    const cases::Snapshot& snap = shown->snapshots[k];
    const std::filesystem::path png = plot_dir / fmt::format("snapshot_{:04d}.png", k);
    const std::string title = fmt::format("t = {:.4g} s", snap.time);
    if (const auto problem = render_projection(o.scene, snap, window, title, png)) {
      md += fmt::format("- snapshot at {} not drawn: {}\n", title, *problem);
    } else {
      md += fmt::format("![{}]({}) ", title, std::filesystem::relative(png, report_dir).generic_string());
    }
  }
  return heading(level, "Snapshots") + md + "\n\n";
}

std::string conventions_section(const comparison::CaseOutcome& o, int level) {
  MarkdownTable t({"engine", "convention", "value"});
  for (const auto& r : o.runs) {
    for (const auto& [k, v] : r.conventions) t.add_row({r.engine, k, v});
    if (!r.scratch_dir.empty()) t.add_row({r.engine, "scratch directory", r.scratch_dir});
  }
  return t.rows() == 0 ? "" : heading(level, "Conventions") + t.render() + "\n";
}

/// The restitution calibrations of every engine: what was tuned, the e_in → e_out samples and
/// the input chosen (issue "Reference engines" §4).
std::string calibrations_section(const comparison::CaseOutcome& o, int level) {
  std::string md;
  for (const auto& r : o.runs) {
    for (const auto& c : r.calibrations) {
      md += fmt::format("**{}** — {}: target restitution {}, chosen input {}. {}\n\n", r.engine, c.parameter,
                        format_number(c.target), format_number(c.chosen), c.method);
      MarkdownTable t({"input", "restitution measured", "minus target"});
      for (const auto& [input, measured] : c.samples) {
        t.add_row({format_number(input), format_number(measured), format_ratio(measured - c.target)});
      }
      md += t.render() + "\n";
    }
  }
  return md.empty() ? "" : heading(level, "Restitution calibration") + md;
}

/// Metrics an engine cannot express in this case, with the reason.
std::string inexpressible_section(const comparison::CaseOutcome& o, int level) {
  MarkdownTable t({"engine", "metric", "why it is not compared"});
  for (const auto& r : o.runs) {
    for (const auto& [metric, why] : r.inexpressible_metrics) t.add_row({r.engine, metric, why});
  }
  return t.rows() == 0 ? "" : heading(level, "Metrics an engine cannot express") + t.render() + "\n";
}

std::string warnings_section(const comparison::CaseOutcome& o, int level) {
  std::string md;
  for (const auto& w : o.scene.warnings) md += "- case: " + w + "\n";
  for (const auto& r : o.runs) {
    for (const auto& w : r.warnings) md += "- " + r.engine + ": " + w + "\n";
  }
  return md.empty() ? "" : heading(level, "Warnings") + md + "\n";
}

}  // namespace

std::string discrepancy_table(const comparison::CaseOutcome& o) {
  MarkdownTable t({"metric", "engine", "value", "reference", "ref. value", "abs. diff",
                   "rel. diff", "tolerance", "own Δt error (Δt used)", "status", "note"});
  for (const auto& c : o.comparisons) {
    std::string tol;
    if (c.tolerance.rel > 0.0) tol += fmt::format("rel {:.1e}", c.tolerance.rel);
    if (c.tolerance.abs > 0.0) tol += fmt::format("{}abs {:.1e}", tol.empty() ? "" : ", ", c.tolerance.abs);
    // A native reference-code row: the code's own discretisation error at the Δt of its value.
    std::string own;
    if (c.error_estimate) {
      own = fmt::format("{:.2e} ({:.4g} s)", *c.error_estimate, c.timestep.value_or(0.0));
    } else if (c.timestep) {
      own = fmt::format("— ({:.4g} s)", *c.timestep);
    }
    t.add_row({c.metric, c.engine, format_number(c.value), c.reference,
               format_number(c.reference_value), format_ratio(c.abs_diff), format_ratio(c.rel_diff),
               tol, own, status_cell(c.status), c.note});
  }
  return t.render();
}

std::string unlisted_verdict(const comparison::UnlistedCode& code) {
  return code.reason.empty() ? "expresses it" : "n/a";
}

std::string case_section(const comparison::CaseOutcome& o, const std::filesystem::path& plot_dir,
                         const std::filesystem::path& report_dir, int level) {
  const cases::Scene& s = o.scene;
  std::string md = heading(level, fmt::format("`{}` — {}", s.name, status_cell(comparison::worst_status(o))));
  if (!s.description.empty()) md += inert_text(s.description) + "\n\n";
  if (!s.thesis_reference.empty()) md += "Thesis: " + inert_text(s.thesis_reference) + ".  \n";
  md += fmt::format("Case file: `{}` (sha256 `{}`), tier `{}`.\n\n", s.source_path, s.source_sha256.substr(0, 16),
                    cases::to_string(s.tier));
  md += model_section(s, level + 1);
  md += stages_section(s, level + 1);
  md += runs_section(o, level + 1);
  md += unlisted_section(o, level + 1);
  md += metrics_section(o, level + 1);
  if (!o.comparisons.empty()) {
    md += heading(level + 1, fmt::format("Discrepancies against `{}`", s.compare.reference));
    md += discrepancy_table(o) + "\n";
  }
  md += plots_section(o, plot_dir, report_dir, level + 1);
  md += snapshots_section(o, plot_dir, report_dir, level + 1);
  md += inexpressible_section(o, level + 1);
  md += calibrations_section(o, level + 1);
  md += conventions_section(o, level + 1);
  md += warnings_section(o, level + 1);
  return md;
}

}  // namespace reports
