// SPDX-License-Identifier: MIT
#include "reports/gnuplot.hpp"

#include <cmath>

#include <fmt/format.h>

#include "support/process.hpp"
#include "support/text_file.hpp"

namespace reports {

std::string gnuplot_quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

namespace {

bool plottable(double x, double y, const Plot& p) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  if (p.log_x && !(x > 0.0)) return false;
  if (p.log_y && !(y > 0.0)) return false;
  return true;
}

}  // namespace

std::optional<std::string> render_png(const Plot& plot, const std::filesystem::path& png) {
  const std::filesystem::path data = std::filesystem::path(png).replace_extension(".dat");
  const std::filesystem::path script = std::filesystem::path(png).replace_extension(".gp");
  std::string dat;
  std::vector<bool> has_points;
  for (const auto& s : plot.series) {
    dat += "# " + s.title + "\n";
    bool any = false;
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k) {
      if (!plottable(s.x[k], s.y[k], plot)) continue;
      if (s.y_error.empty()) {
        dat += fmt::format("{:.17g} {:.17g}\n", s.x[k], s.y[k]);
      } else {
        dat += fmt::format("{:.17g} {:.17g} {:.17g}\n", s.x[k], s.y[k], k < s.y_error.size() ? s.y_error[k] : 0.0);
      }
      any = true;
    }
    if (!any) dat += "nan nan\n";
    has_points.push_back(any);
    dat += "\n\n";
  }
  std::string gp;
  // gnuplot's libgd `png` terminal: indexed colour, about a fifth of the bytes pngcairo's
  // antialiased truecolour takes for the same figure, which keeps committed sweep baselines small.
  gp += "set terminal png size 900,600 enhanced font 'DejaVu Sans,11'\n";
  gp += "set output " + gnuplot_quoted(png.filename().string()) + "\n";
  gp += "set title " + gnuplot_quoted(plot.title) + " noenhanced\n";
  gp += "set xlabel " + gnuplot_quoted(plot.xlabel) + " noenhanced\n";
  gp += "set ylabel " + gnuplot_quoted(plot.ylabel) + " noenhanced\n";
  gp += "set grid\nset key outside right top noenhanced\n";
  if (plot.log_x) gp += "set logscale x\nset format x '10^{%T}'\n";
  if (plot.log_y) gp += "set logscale y\nset format y '10^{%T}'\n";
  for (const auto& c : plot.extra_commands) gp += c + "\n";
  std::string plots;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    if (!has_points[i]) continue;
    if (!plots.empty()) plots += ", \\\n     ";
    const bool bars = !plot.series[i].y_error.empty();
    plots += fmt::format("{} index {} using {} with {} lw 2 title {}", gnuplot_quoted(data.filename().string()), i,
                         bars ? "1:2:3" : "1:2", bars ? std::string(plot.series[i].style == "points" ? "yerrorbars" : "yerrorlines") : plot.series[i].style,
                         gnuplot_quoted(plot.series[i].title));
  }
  if (plots.empty()) return "no plottable points";
  gp += "plot " + plots + "\n";
  support::write_file(data, dat);
  support::write_file(script, gp);
  return run_gnuplot(script, png);
}

std::optional<std::string> run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& png) {
  if (!support::find_program("gnuplot")) return "gnuplot is not installed";
  support::ProcessSpec spec;
  spec.argv = {"gnuplot", script.filename().string()};
  spec.working_directory = png.parent_path().empty() ? "." : png.parent_path();
  spec.stderr_file = std::filesystem::path(png).replace_extension(".log");
  spec.timeout_s = 60.0;
  const auto result = support::run_process(spec);
  if (!result.started) return result.error;
  if (result.timed_out) return "gnuplot timed out";
  if (result.exit_code != 0) {
    return fmt::format("gnuplot failed (exit {}): {}", result.exit_code,
                       support::file_tail(spec.stderr_file, 5));
  }
  std::filesystem::remove(spec.stderr_file);
  return std::nullopt;
}

}  // namespace reports
