// SPDX-License-Identifier: MIT
#include "reports/snapshot_view.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

#include <fmt/format.h>

#include "reports/gnuplot.hpp"
#include "support/text_file.hpp"

namespace reports {
namespace {

/// |v| of snapshot entry i (0 when the snapshot holds no velocities).
double speed_of(const cases::Snapshot& snap, std::size_t i) {
  if (i >= snap.velocity.size()) return 0.0;
  const cases::Vector3& v = snap.velocity[i];
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

ProjectionWindow packing_window(const cases::Scene& scene, const std::vector<cases::Snapshot>& snapshots) {
  ProjectionWindow w;
  if (!scene.compare.packing) return w;
  const cases::PackingSpec& p = *scene.compare.packing;
  const double wide = p.max[1] - p.min[1];
  const double tall = p.max[2] - p.min[2];
  w.y_min = p.min[1] - 0.1 * wide;
  w.y_max = p.max[1] + 0.1 * wide;
  w.z_min = p.min[2] - 0.1 * tall;
  w.z_max = p.max[2] + tall;
  for (const cases::Snapshot& s : snapshots) {
    for (std::size_t i = 0; i < std::min(s.position.size(), scene.particles.size()); ++i) {
      if (scene.particles[i].fixed) continue;
      const double v = speed_of(s, i);
      if (std::isfinite(v)) w.speed_max = std::max(w.speed_max, v);
    }
  }
  if (!(w.speed_max > 0.0)) w.speed_max = 1.0;
  return w;
}

std::vector<std::size_t> fluidisation_frames(std::span<const double> orf, std::size_t frames) {
  if (orf.size() < 3 || frames < 3) return frame_indices(orf.size(), frames);
  const double start = orf.front();
  const double end = *std::min_element(orf.begin(), orf.end());
  std::size_t first = orf.size();
  std::size_t last = orf.size() - 1;
  for (std::size_t k = 1; k < orf.size(); ++k) {
    if (first == orf.size() && orf[k] < start - 0.02 * (start - end) - 1e-12) first = k - 1;
    if (orf[k] <= end + 0.02 * (start - end)) {
      last = k;
      break;
    }
  }
  if (first == orf.size() || !(start - end > 0.05)) return frame_indices(orf.size(), frames);
  std::vector<std::size_t> out{0};
  for (const std::size_t k : frame_indices(last - first + 1, frames - 1)) {
    if (first + k != out.back()) out.push_back(first + k);
  }
  return out;
}

std::vector<std::size_t> frame_indices(std::size_t count, std::size_t frames) {
  std::vector<std::size_t> out;
  if (count == 0 || frames == 0) return out;
  if (frames == 1 || count == 1) return {count - 1};
  const std::size_t n = std::min(count, frames);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (k * (count - 1) + (n - 1) / 2) / (n - 1);  // rounded k·(count − 1)/(n − 1)
    if (out.empty() || out.back() != i) out.push_back(i);
  }
  return out;
}

std::optional<std::string> render_projection(const cases::Scene& scene, const cases::Snapshot& snap,
                                             const ProjectionWindow& window, const std::string& title,
                                             const std::filesystem::path& png) {
  const std::filesystem::path data = std::filesystem::path(png).replace_extension(".dat");
  const std::filesystem::path script = std::filesystem::path(png).replace_extension(".gp");
  const std::size_t n = std::min(snap.position.size(), scene.particles.size());
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Painter's order: the viewer looks along +x, so the largest x is drawn first.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return snap.position[a][0] > snap.position[b][0]; });
  std::string mobile;
  std::string fixed;
  for (const std::size_t i : order) {
    const cases::Vector3& x = snap.position[i];
    if (!std::isfinite(x[1]) || !std::isfinite(x[2])) continue;
    const double r = scene.particles[i].radius;
    if (x[1] + r < window.y_min || x[1] - r > window.y_max || x[2] + r < window.z_min || x[2] - r > window.z_max) continue;
    if (scene.particles[i].fixed) {
      fixed += fmt::format("{:.9g} {:.9g} {:.9g}\n", x[1], x[2], r);
    } else {
      mobile += fmt::format("{:.9g} {:.9g} {:.9g} {:.9g}\n", x[1], x[2], r, speed_of(snap, i));
    }
  }
  support::write_file(data, "# mobile: y z r speed\n" + (mobile.empty() ? std::string("nan nan nan nan\n") : mobile) +
                                "\n\n# fixed: y z r\n" + (fixed.empty() ? std::string("nan nan nan\n") : fixed));
  // Sized to the window's aspect (the discs stay round), within sensible bounds.
  const double aspect = (window.z_max - window.z_min) / (window.y_max - window.y_min);
  const int height = static_cast<int>(std::clamp(140.0 + 620.0 * aspect, 280.0, 900.0));
  std::string gp;
  gp += fmt::format("set terminal png size 760,{} enhanced font 'DejaVu Sans,10'\n", height);
  gp += "set output " + gnuplot_quoted(png.filename().string()) + "\n";
  gp += "set title " + gnuplot_quoted(title) + " noenhanced\n";
  gp += "set xlabel 'y (m)'\nset ylabel 'z (m)'\nset size ratio -1\n";
  gp += fmt::format("set xrange [{:.9g}:{:.9g}]\nset yrange [{:.9g}:{:.9g}]\n", window.y_min, window.y_max,
                    window.z_min, window.z_max);
  gp += fmt::format("set cbrange [0:{:.9g}]\nset cblabel 'speed (m/s)'\nset palette rgb 33,13,10\n", window.speed_max);
  gp += "set format x '%.1e'\nset format y '%.1e'\nset xtics rotate by 30 right\n";
  if (scene.compare.packing) {
    const cases::PackingSpec& p = *scene.compare.packing;
    gp += fmt::format("set object 1 rect from {:.9g},{:.9g} to {:.9g},{:.9g} fs empty border lc rgb 'black' lw 1\n",
                      p.min[1], p.min[2], p.max[1], p.max[2]);
  }
  const std::string file = gnuplot_quoted(data.filename().string());
  gp += "plot " + file + " index 1 using 1:2:3 with circles fs solid 1.0 border lc rgb '#404040' lc rgb '#a0a0a0' notitle, \\\n";
  gp += "     " + file + " index 0 using 1:2:3:4 with circles lc palette fs solid 1.0 border lc rgb '#404040' notitle\n";
  support::write_file(script, gp);
  return run_gnuplot(script, png);
}

}  // namespace reports
