// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace reports {

/// One curve of a plot.
struct Series {
  std::string title;
  std::vector<double> x;
  std::vector<double> y;
  std::string style = "lines";  ///< gnuplot style: "lines", "linespoints", "points"
  std::vector<double> y_error;  ///< optional: an error bar (± this) per point; drawn as yerrorlines
};

/// A 2-D plot rendered to PNG by gnuplot.
struct Plot {
  std::string title;
  std::string xlabel;
  std::string ylabel;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::vector<std::string> extra_commands;  ///< raw gnuplot lines (labels, arrows)
};

/// Renders `plot` to `png`, keeping the data (.dat) and script (.gp) beside it so the figure can
/// be remade. Returns empty on success, else why not (gnuplot missing, gnuplot failed). Points
/// that are not finite (or not positive on a log axis) are left out.
std::optional<std::string> render_png(const Plot& plot, const std::filesystem::path& png);

/// Runs gnuplot on `script` in `png`'s folder (60 s at most); returns empty once it has drawn
/// `png`, else why not (gnuplot missing, failed with its last lines of error, timed out).
std::optional<std::string> run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& png);

/// `s` as a gnuplot string literal (double quotes, with quotes and backslashes escaped).
std::string gnuplot_quoted(const std::string& s);

}  // namespace reports
