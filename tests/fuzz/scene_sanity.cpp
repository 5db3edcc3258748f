// SPDX-License-Identifier: MIT
#include "scene_sanity.hpp"

#include <cmath>

#include <fmt/format.h>

#include "cases/excerpt.hpp"
#include "cases/limits.hpp"
#include "cases/names.hpp"
#include "cases/output_budget.hpp"
#include "dem/particles/particles.hpp"

namespace fuzz {
namespace {

/// Longest message a load error or warning may have: file name, key and problem, each bounded.
constexpr std::size_t kMaxMessage = 256 + cases::kMaxEchoedKey + cases::kMaxEchoedProblem + 64;

/// True when x is finite and inside the loader's window of derived quantities.
bool in_window(double x) noexcept { return x >= cases::kMinDerived && x <= cases::kMaxDerived; }

/// |v|.
double norm(const cases::Vector3& v) noexcept { return std::hypot(v[0], v[1], v[2]); }

/// True when every component is finite.
bool finite(const cases::Vector3& v) noexcept {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// A wall's name: a name, or a box's name and its face (".x-" … ".z+").
bool wall_name(const std::string& name) {
  const auto dot = name.rfind('.');
  const bool face = dot != std::string::npos && name.size() == dot + 3 &&
                    std::string_view("xyz").find(name[dot + 1]) != std::string_view::npos &&
                    (name[dot + 2] == '-' || name[dot + 2] == '+');
  return cases::is_name(face ? std::string_view(name).substr(0, dot) : std::string_view(name));
}

/// Problems of one message: a line break or other control character, or a length past the bound.
void check_line(const std::string& text, const std::string& what, std::vector<std::string>& out) {
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20U || u == 0x7FU) {
      out.push_back(fmt::format("{} holds control character {:#04x}: {}", what, u, cases::excerpt(text, 300)));
      break;
    }
  }
  if (text.size() > kMaxMessage) out.push_back(fmt::format("{} is {} bytes long", what, text.size()));
}

/// Problems of the particles.
void check_particles(const cases::Scene& s, std::vector<std::string>& out) {
  if (s.particles.empty()) out.emplace_back("no particles");
  if (s.particles.size() > cases::kMaxParticles) out.push_back(fmt::format("{} particles", s.particles.size()));
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const cases::ParticleSpec& p = s.particles[i];
    if (p.material >= s.materials.size()) {
      out.push_back(fmt::format("particle {} has material {}", i, p.material));
      continue;
    }
    const double m = dem::sphere_mass(s.materials[p.material].density, p.radius);
    const bool sized = p.radius > 0.0 && std::isfinite(p.radius);
    if (!sized || !in_window(m) || !in_window(dem::sphere_inertia(m, p.radius))) {
      out.push_back(fmt::format("particle {}: radius {}, mass {}", i, p.radius, m));
    }
    if (!(p.effect_radius >= p.radius) || !std::isfinite(p.effect_radius)) {
      out.push_back(fmt::format("particle {}: effect radius {}", i, p.effect_radius));
    }
    if (!finite(p.position) || !(norm(p.velocity) < cases::kSpeedOfLight) ||
        !(norm(p.angular_velocity) * p.radius < cases::kSpeedOfLight) || !std::isfinite(p.charge)) {
      out.push_back(fmt::format("particle {}: position, velocity, spin or charge out of range", i));
    }
    for (const cases::MotionSegmentSpec& seg : p.motion) {
      if (!(norm(seg.velocity) < cases::kSpeedOfLight) || !(seg.duration >= 0.0) || !std::isfinite(seg.duration)) {
        out.push_back(fmt::format("particle {}: motion segment out of range", i));
      }
    }
  }
}

/// Problems of the materials, walls and the time integration.
void check_setting(const cases::Scene& s, std::vector<std::string>& out) {
  if (!cases::is_identifier(s.name, false)) out.push_back("case name " + cases::excerpt(s.name));
  if (s.materials.empty() || s.materials.size() > cases::kMaxMaterials) {
    out.push_back(fmt::format("{} materials", s.materials.size()));
  }
  for (const auto& m : s.materials) {
    if (!(m.density > 0.0) || !(m.density <= cases::kMaxDensity)) out.push_back(fmt::format("density {}", m.density));
  }
  std::size_t facets = 0;
  for (const auto& w : s.walls) facets += w.mesh ? 1 : 0;
  if (s.walls.size() - facets > cases::kMaxWalls) out.push_back(fmt::format("{} walls", s.walls.size() - facets));
  if (facets > cases::kMaxMeshFacets) out.push_back(fmt::format("{} mesh facets", facets));
  for (const auto& w : s.walls) {
    if (w.material >= s.materials.size() || !finite(w.point) || std::fabs(norm(w.normal) - 1.0) > 1e-9 ||
        !(norm(w.velocity) < cases::kSpeedOfLight) || !wall_name(w.name)) {
      out.push_back("wall " + cases::excerpt(w.name) + " out of range");
    }
  }
  const cases::IntegrationSpec& in = s.integration;
  if (in.timestep && (!in_window(*in.timestep) || !(in.duration / *in.timestep <= cases::kMaxSteps))) {
    out.push_back(fmt::format("time step {} over {} s", *in.timestep, in.duration));
  }
  if (!std::isfinite(in.duration) || in.duration < 0.0 || (in.duration == 0.0 && !s.duration_from_launch)) {
    out.push_back(fmt::format("duration {}", in.duration));
  }
}

/// Problems of what is recorded and compared.
void check_output(const cases::Scene& s, std::vector<std::string>& out) {
  const std::size_t n = s.particles.size();
  const cases::OutputSpec& o = s.output;
  if (o.trace_every < 1) out.emplace_back("trace_every 0");
  for (const std::size_t i : o.trace_particles) {
    if (i >= n) out.push_back(fmt::format("traced particle {}", i));
  }
  for (const auto& [p, q] : o.trace_pairs) {
    if (p >= n || q >= n || p == q) out.push_back(fmt::format("traced pair {}-{}", p, q));
  }
  for (const auto& [p, w] : o.trace_walls) {
    if (p >= n || w >= s.walls.size()) out.push_back(fmt::format("traced wall contact {}-{}", p, w));
  }
  for (std::size_t k = 0; k < o.snapshot_times.size(); ++k) {
    if (!std::isfinite(o.snapshot_times[k]) || (k > 0 && !(o.snapshot_times[k] > o.snapshot_times[k - 1]))) {
      out.push_back(fmt::format("snapshot time {}", o.snapshot_times[k]));
    }
  }
  if (s.compare.engines.empty()) out.emplace_back("no engine");
  if (s.compare.subject && *s.compare.subject >= n) out.emplace_back("subject out of range");
  if (s.compare.pair && (s.compare.pair->first >= n || s.compare.pair->second >= n)) {
    out.emplace_back("pair out of range");
  }
  const cases::OutputEstimate e = cases::estimate_output(s);
  if (e.bytes > cases::physical_memory_bytes()) out.push_back(fmt::format("output estimate {} bytes", e.bytes));
  if (std::isfinite(e.timestep) && !s.duration_from_launch && static_cast<double>(e.steps) > cases::kMaxSteps + 1.0) {
    out.push_back(fmt::format("{} steps", e.steps));
  }
  for (const std::string& w : s.warnings) check_line(w, "a warning", out);
}

}  // namespace

std::vector<std::string> scene_problems(const cases::Scene& scene) {
  std::vector<std::string> out;
  check_particles(scene, out);
  check_setting(scene, out);
  check_output(scene, out);
  return out;
}

std::vector<std::string> error_problems(const cases::CaseError& error, const std::string& file) {
  std::vector<std::string> out;
  const std::string what = error.what();
  if (what.rfind(file + ":", 0) != 0) {
    out.push_back("the message does not start with the file: " + cases::excerpt(what, 300));
  }
  if (error.key().empty()) out.emplace_back("the error names no key");
  check_line(what, "the message", out);
  return out;
}

}  // namespace fuzz
