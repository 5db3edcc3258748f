// SPDX-License-Identifier: MIT
#include "sweeps/sweep_report.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "reports/gnuplot.hpp"
#include "sweeps/beverloo_fit.hpp"
#include "reports/markdown.hpp"
#include "support/text_file.hpp"

namespace sweeps {
namespace {

/// "mean ± se (n)" of one metric.
std::string cell(const SeedStatistics& s) {
  if (s.count == 0) return "—";
  if (!s.standard_error) return fmt::format("{:.4g} (n = 1)", s.mean);
  return fmt::format("{:.4g} ± {:.2g} (n = {})", s.mean, *s.standard_error, s.count);
}

/// A file-name-safe version of `s`: letters and digits kept, everything else one underscore.
std::string slug(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (keep) {
      out += c;
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

std::optional<std::size_t> metric_index(const std::vector<std::string>& metrics, const std::string& name) {
  const auto it = std::find(metrics.begin(), metrics.end(), name);
  if (it == metrics.end()) return std::nullopt;
  return static_cast<std::size_t>(it - metrics.begin());
}

/// The metrics worth a curve: the breakup measures when present, else every metric.
std::vector<std::size_t> plotted_metrics(const std::vector<std::string>& metrics) {
  std::vector<std::size_t> out;
  for (const char* name : {"kappa_vol", "kappa_damage", "fragments"}) {
    if (const auto m = metric_index(metrics, name)) out.push_back(*m);
  }
  if (out.empty()) {
    for (std::size_t m = 0; m < metrics.size(); ++m) out.push_back(m);
  }
  return out;
}

/// Renders one plot into `dir`/plots and returns the markdown that shows it (or says why not).
std::string figure(const reports::Plot& plot, const std::filesystem::path& dir, const std::string& name) {
  std::filesystem::create_directories(dir / "plots");
  const std::filesystem::path png = dir / "plots" / (name + ".png");
  if (const auto problem = reports::render_png(plot, png)) {
    return fmt::format("*Figure `plots/{}.png` not drawn: {}.*\n\n", name, *problem);
  }
  return fmt::format("![{}](plots/{}.png)\n\n", plot.title, name);
}

/// Metric `m` against one axis, a curve per family value and engine.
std::string family_figure(const SweepResults& r, const CurveFamily& f, std::size_t m, const std::filesystem::path& dir) {
  const SweepAxis& x = r.spec.axes[f.x_axis];
  reports::Plot plot;
  plot.xlabel = x.label;
  plot.ylabel = r.metrics[m];
  plot.log_x = x.log_scale;
  std::string held;
  for (std::size_t a = 0; a < r.spec.axes.size(); ++a) {
    if (a == f.x_axis || (f.family && a == *f.family) || r.spec.axes[a].values.size() < 2) continue;
    held += fmt::format("{}{} = {:.4g}", held.empty() ? "" : ", ", r.spec.axes[a].label, r.spec.axes[a].values[f.held[a]]);
  }
  plot.title = fmt::format("{} against {}{}", r.metrics[m], x.label, held.empty() ? "" : " (" + held + ")");
  const std::size_t curves = f.family ? r.spec.axes[*f.family].values.size() : 1;
  for (const auto& engine : r.engines) {
    for (std::size_t c = 0; c < curves; ++c) {
      reports::Series s;
      s.title = f.family ? fmt::format("{}, {} = {:.4g}", engine, r.spec.axes[*f.family].label,
                                       r.spec.axes[*f.family].values[c])
                         : engine;
      s.style = "linespoints";
      for (std::size_t v = 0; v < x.values.size(); ++v) {
        std::vector<std::size_t> at = f.held;
        at[f.x_axis] = v;
        if (f.family) at[*f.family] = c;
        const SeedStatistics st = point_statistics(r.rows, point_at(r.spec, at), engine, m);
        if (st.count == 0) continue;
        s.x.push_back(x.values[v]);
        s.y.push_back(st.mean);
        s.y_error.push_back(st.standard_error.value_or(0.0));
      }
      plot.series.push_back(std::move(s));
    }
  }
  // Files are named by the key's last part: labels may be symbols (μ, γ) that make poor names.
  const std::string key_name = x.key.substr(x.key.find_last_of('.') + 1);
  return figure(plot, dir, slug(r.metrics[m] + "_vs_" + key_name));
}

/// κDAMAGE against the cohesive work of the point (thesis figs 5.14, 5.16), a series per engine.
std::string damage_work_figure(const SweepResults& r, std::size_t damage, std::size_t work,
                               const std::filesystem::path& dir) {
  reports::Plot plot;
  plot.title = "kappa_damage against the cohesive work of a pair";
  plot.xlabel = "cohesive work (J)";
  plot.ylabel = "kappa_damage";
  plot.log_x = true;
  for (const auto& engine : r.engines) {
    std::vector<std::tuple<double, double, double>> points;
    for (const auto& p : r.points) {
      const SeedStatistics w = point_statistics(r.rows, p.index, engine, work);
      const SeedStatistics d = point_statistics(r.rows, p.index, engine, damage);
      if (w.count == 0 || d.count == 0) continue;
      points.emplace_back(w.mean, d.mean, d.standard_error.value_or(0.0));
    }
    std::sort(points.begin(), points.end());
    reports::Series s;
    s.title = engine;
    s.style = "points";
    for (const auto& [x, y, e] : points) {
      s.x.push_back(x);
      s.y.push_back(y);
      s.y_error.push_back(e);
    }
    plot.series.push_back(std::move(s));
  }
  return figure(plot, dir, "kappa_damage_vs_cohesive_work");
}

/// The fluidisation curves (thesis figs 6.5, 6.8): per engine, the ORF against time averaged over
/// the seeds snapshot by snapshot, a curve per point with ± one standard error.
std::string bed_figures(const SweepResults& r, const std::filesystem::path& dir) {
  std::string md;
  for (const auto& engine : r.engines) {
    reports::Plot plot;
    plot.title = fmt::format("ORF against time, mean over the seeds ({})", engine);
    plot.xlabel = "time (s)";
    plot.ylabel = "obscured reservoir fraction";
    for (const auto& p : r.points) {
      const MeanCurve curve = mean_bed_curve(r.rows, p.index, engine, false);
      if (curve.time.empty()) continue;
      reports::Series s;
      std::string label;
      for (std::size_t a = 0; a < r.spec.axes.size(); ++a) {
        label += fmt::format("{}{} = {:.4g}", label.empty() ? "" : ", ", r.spec.axes[a].label, p.values[a]);
      }
      s.title = label.empty() ? engine : label;
      s.style = "lines";
      for (std::size_t k = 0; k < curve.time.size(); ++k) {
        s.x.push_back(curve.time[k]);
        s.y.push_back(curve.value[k].mean);
        s.y_error.push_back(curve.value[k].standard_error.value_or(0.0));
      }
      plot.series.push_back(std::move(s));
    }
    if (!plot.series.empty()) md += figure(plot, dir, slug("orf_curves_" + engine));
  }
  return md;
}

}  // namespace

std::vector<EngineBeverloo> beverloo_fits(const SweepResults& r) {
  std::vector<EngineBeverloo> out;
  if (!r.spec.beverloo) return out;
  const BeverlooSpec& b = *r.spec.beverloo;
  const auto rate = metric_index(r.metrics, b.flow_rate);
  const auto phi = metric_index(r.metrics, b.packing_fraction);
  const SweepAxis& axis = r.spec.axes.at(b.axis);
  std::vector<std::size_t> held;
  for (const auto& a : r.spec.axes) held.push_back(a.values.size() / 2);
  for (const auto& engine : r.engines) {
    EngineBeverloo e;
    e.engine = engine;
    if (!rate || !phi) {
      e.problem = fmt::format("the sweep does not measure '{}' and '{}'", b.flow_rate, b.packing_fraction);
      out.push_back(e);
      continue;
    }
    double phi_sum = 0.0;
    std::size_t phi_count = 0;
    for (std::size_t v = 0; v < axis.values.size(); ++v) {
      std::vector<std::size_t> at = held;
      at[b.axis] = v;
      const std::size_t point = point_at(r.spec, at);
      const SeedStatistics w = point_statistics(r.rows, point, engine, *rate);
      const SeedStatistics f = point_statistics(r.rows, point, engine, *phi);
      if (f.count > 0) {
        phi_sum += f.mean * static_cast<double>(f.count);
        phi_count += f.count;
      }
      if (w.count == 0) continue;
      e.orifice.push_back(b.orifice_scale * axis.values[v]);
      e.rate.push_back(w.mean);
      e.rate_error.push_back(w.standard_error.value_or(0.0));
    }
    if (phi_count == 0) {
      e.problem = fmt::format("no run gave '{}'", b.packing_fraction);
      out.push_back(e);
      continue;
    }
    e.bulk_density = phi_sum / static_cast<double>(phi_count) * b.grain_density;
    e.fit = fit_beverloo(e.orifice, e.rate, e.bulk_density, b.gravity, b.grain_diameter);
    if (!e.fit) e.problem = "the flow rates do not rise with the orifice (or fewer than two orifices gave one)";
    out.push_back(e);
  }
  return out;
}

namespace {

/// Beverloo's law fitted per engine: a table of C and k and the flow rate against D with the fits.
std::string beverloo_section(const SweepResults& r, const std::filesystem::path& dir) {
  const std::vector<EngineBeverloo> fits = beverloo_fits(r);
  if (fits.empty()) return "";
  const BeverlooSpec& b = *r.spec.beverloo;
  std::string md = fmt::format(
      "## Beverloo's law\n\nW = C ρ_b √g (D − k d)^5/2 fitted by least squares to the mean flow rate "
      "(`{}`) against the orifice diameter D = {} × `{}`, as the straight line W^2/5 = (C ρ_b √g)^2/5 (D − k d); "
      "d = {:.4g} m, g = {:.4g} m/s², ρ_b = the mean `{}` of the settled bed × {:.4g} kg/m³.\n\n",
      b.flow_rate, b.orifice_scale, r.spec.axes.at(b.axis).key, b.grain_diameter, b.gravity, b.packing_fraction,
      b.grain_density);
  reports::MarkdownTable t({"engine", "ρ_b (kg/m³)", "C", "k", "orifices", "largest misfit", "note"});
  reports::Plot plot;
  plot.title = "Mass flow rate against the orifice diameter, with Beverloo's law fitted";
  plot.xlabel = "orifice diameter D (m)";
  plot.ylabel = "mass flow rate W (kg/s)";
  for (const EngineBeverloo& e : fits) {
    if (!e.fit) {
      t.add_row({e.engine, e.bulk_density > 0.0 ? fmt::format("{:.1f}", e.bulk_density) : "—", "—", "—",
                 fmt::format("{}", e.orifice.size()), "—", e.problem});
      continue;
    }
    t.add_row({e.engine, fmt::format("{:.1f}", e.bulk_density), fmt::format("{:.3f}", e.fit->c),
               fmt::format("{:.2f}", e.fit->k), fmt::format("{}", e.fit->points),
               fmt::format("{:.1f} %", 100.0 * e.fit->largest_misfit), ""});
    reports::Series measured;
    measured.title = e.engine + " (mean ± s.e.)";
    measured.style = "points";
    measured.x = e.orifice;
    measured.y = e.rate;
    measured.y_error = e.rate_error;
    plot.series.push_back(std::move(measured));
    reports::Series law;
    law.title = fmt::format("{}: C = {:.3f}, k = {:.2f}", e.engine, e.fit->c, e.fit->k);
    const double lo = *std::min_element(e.orifice.begin(), e.orifice.end());
    const double hi = *std::max_element(e.orifice.begin(), e.orifice.end());
    for (int i = 0; i <= 40; ++i) {
      const double d = lo + (hi - lo) * (1.1 * i / 40.0 - 0.05);
      law.x.push_back(d);
      law.y.push_back(beverloo_rate(e.fit->c, e.fit->k, e.bulk_density, b.gravity, d, b.grain_diameter));
    }
    plot.series.push_back(std::move(law));
  }
  md += t.render() + "\n";
  md += figure(plot, dir, "beverloo");
  return md;
}

/// Per point and metric, each engine against the first: |Δ mean| / combined standard error.
std::string cross_code_table(const SweepResults& r) {
  std::string md = fmt::format(
      "## Engines compared\n\nEach cell is the difference of the ensemble means of an engine and `{}` in units of "
      "their combined standard error, √(se₁² + se₂²); above 2 the ensembles differ by more than their "
      "spread explains (marked **bold**).\n\n",
      r.engines.front());
  std::vector<std::string> header{"point"};
  for (const auto& a : r.spec.axes) header.push_back(a.label);
  header.emplace_back("engine");
  for (const auto& m : r.metrics) header.push_back(m);
  reports::MarkdownTable t(header);
  for (std::size_t e = 1; e < r.engines.size(); ++e) {
    for (const auto& p : r.points) {
      std::vector<std::string> line{fmt::format("{}", p.index)};
      for (const double v : p.values) line.push_back(fmt::format("{:.4g}", v));
      line.push_back(r.engines[e]);
      for (std::size_t m = 0; m < r.metrics.size(); ++m) {
        const SeedStatistics a = point_statistics(r.rows, p.index, r.engines.front(), m);
        const SeedStatistics b = point_statistics(r.rows, p.index, r.engines[e], m);
        if (a.count == 0 || b.count == 0) {
          line.emplace_back("—");
        } else if (const auto z = separation(a, b)) {
          line.push_back(*z > 2.0 ? fmt::format("**{:.2f}**", *z) : fmt::format("{:.2f}", *z));
        } else {
          line.push_back(a.mean == b.mean ? "0 (no spread)" : fmt::format("Δ {:.3g} (no spread)", b.mean - a.mean));
        }
      }
      t.add_row(line);
    }
  }
  return md + t.render() + "\n";
}

}  // namespace

std::size_t point_at(const SweepSpec& spec, const std::vector<std::size_t>& value_indices) {
  std::size_t index = 0;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) index = index * spec.axes[a].values.size() + value_indices.at(a);
  return index;
}

std::vector<CurveFamily> curve_families(const SweepSpec& spec) {
  std::vector<CurveFamily> out;
  const std::size_t n = spec.axes.size();
  for (std::size_t a = 0; a < n; ++a) {
    if (spec.axes[a].values.size() < 2) continue;
    CurveFamily f;
    f.x_axis = a;
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t b = (a + k) % n;
      if (spec.axes[b].values.size() >= 2) {
        f.family = b;
        break;
      }
    }
    for (const auto& axis : spec.axes) f.held.push_back(axis.values.size() / 2);
    out.push_back(f);
  }
  return out;
}

void write_sweep_report(const SweepResults& r, const std::filesystem::path& dir) {
  std::string md = fmt::format("# Sweep `{}`\n\n", r.spec.name);
  if (!r.spec.description.empty()) md += reports::inert_text(r.spec.description) + "\n\n";
  md += fmt::format(
      "Case `{}`; {} points × {} seeds × {} engine(s) = {} rows in {:.1f} s{}. Reproduce with:\n\n```sh\n{}\n```\n\n",
      r.spec.case_file.string(), r.points.size(), r.spec.seeds.size(), r.engines.size(), r.rows.size(), r.seconds,
      r.ranks > 1 ? fmt::format(" on {} MPI ranks", r.ranks) : std::string(), r.command);
  if (!r.spec.fixed.empty()) {
    std::string held;
    for (const FixedSetting& f : r.spec.fixed) {
      const std::string value = std::visit(
          [](const auto& v) -> std::string {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::string>) {
              return fmt::format("\"{}\"", v);
            } else if constexpr (std::is_same_v<T, bool>) {
              return v ? "true" : "false";
            } else {
              return fmt::format("{}", v);  // the shortest text that reads back as v
            }
          },
          f.value);
      held += fmt::format("{}`{} = {}`", held.empty() ? "" : ", ", reports::inert_text(f.key), reports::inert_text(value));
    }
    md += "Held in every run (the sweep's `set`): " + held + ".\n\n";
  }
  md += "Each cell is the mean over the seeds ± its standard error (sample s.d./√n) and the number of "
        "seeds that gave a value. A many-body run is chaotic: one seed is one sample of the ensemble.\n\n";
  std::size_t failed = 0;
  for (const auto& row : r.rows) failed += row.status == "ok" ? 0 : 1;
  if (failed > 0) md += fmt::format("**{} row(s) did not run `ok`**; `sweep.csv` gives each reason.\n\n", failed);
  for (const auto& engine : r.engines) {
    md += fmt::format("## {}\n\n", engine);
    std::vector<std::string> header{"point"};
    for (const auto& a : r.spec.axes) header.push_back(a.label);
    for (const auto& m : r.metrics) header.push_back(m);
    reports::MarkdownTable t(header);
    for (const auto& p : r.points) {
      std::vector<std::string> line{fmt::format("{}", p.index)};
      for (const double v : p.values) line.push_back(fmt::format("{:.4g}", v));
      for (std::size_t m = 0; m < r.metrics.size(); ++m) line.push_back(cell(point_statistics(r.rows, p.index, engine, m)));
      t.add_row(line);
    }
    md += t.render() + "\n";
  }
  if (r.engines.size() > 1) md += cross_code_table(r);
  md += beverloo_section(r, dir);

  std::string figures;
  for (const CurveFamily& f : curve_families(r.spec)) {
    for (const std::size_t m : plotted_metrics(r.metrics)) figures += family_figure(r, f, m, dir);
  }
  const auto damage = metric_index(r.metrics, "kappa_damage");
  const auto work = metric_index(r.metrics, "cohesive_work");
  if (damage && work) figures += damage_work_figure(r, *damage, *work, dir);
  figures += bed_figures(r, dir);
  if (!figures.empty()) {
    md += "## Figures\n\nMeans over the seeds with ± one standard error. Against one parameter, a curve per value "
          "of the next parameter; any other parameter is held at its middle value.\n\n" +
          figures;
  }
  support::write_file(dir / "report.md", md);
}

}  // namespace sweeps
