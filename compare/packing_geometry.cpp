// SPDX-License-Identifier: MIT
#include "compare/packing_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "compare/metrics_breakup.hpp"
#include "dem/particles/particles.hpp"

namespace comparison {
namespace {

/// ∫₀ˣ √(ρ² − t²) dt = ½(x√(ρ² − x²) + ρ² asin(x/ρ)), x clamped to [−ρ, ρ].
double half_chord_integral(double rho, double x) noexcept {
  x = std::clamp(x, -rho, rho);
  const double s = std::sqrt(std::max(0.0, rho * rho - x * x));
  return 0.5 * (x * s + rho * rho * std::asin(x / rho));
}

/// Area of the disk of radius ρ at the origin with x ≤ a and y ≤ b. Along x the disk's chord
/// is [−s, s], s = √(ρ² − x²); clipped at y = b it has length 2s where s ≤ b, b + s where
/// −s < b < s, and 0 where b ≤ −s. The pieces meet where s = |b|, at x = ±c, c = √(ρ² − b²).
double quadrant_area(double rho, double a, double b) noexcept {
  if (!(rho > 0.0) || b <= -rho || a <= -rho) return 0.0;
  a = std::min(a, rho);
  const auto integral = [rho](double lo, double hi) {
    return half_chord_integral(rho, hi) - half_chord_integral(rho, lo);
  };
  if (b >= rho) return 2.0 * integral(-rho, a);
  const double c = std::sqrt(rho * rho - b * b);
  double area = 0.0;
  if (b >= 0.0) area += 2.0 * integral(-rho, std::min(a, -c));  // |x| ≥ c on the left: whole chords
  if (const double hi = std::min(a, c); hi > -c) area += b * (hi + c) + integral(-c, hi);
  if (b >= 0.0 && a > c) area += 2.0 * integral(c, a);           // |x| ≥ c on the right
  return area;
}

}  // namespace

double Box::volume() const noexcept {
  double v = 1.0;
  for (std::size_t k = 0; k < 3; ++k) v *= std::max(0.0, hi[k] - lo[k]);
  return v;
}

bool Box::contains(const cases::Vector3& p) const noexcept {
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(p[k] >= lo[k] && p[k] <= hi[k])) return false;
  }
  return true;
}

double disk_rectangle_area(double rho, double x0, double x1, double y0, double y1) noexcept {
  if (!(rho > 0.0) || !(x1 > x0) || !(y1 > y0)) return 0.0;
  const double area = quadrant_area(rho, x1, y1) - quadrant_area(rho, x0, y1) - quadrant_area(rho, x1, y0) +
                      quadrant_area(rho, x0, y0);
  return std::clamp(area, 0.0, std::numbers::pi * rho * rho);
}

double sphere_box_volume(const cases::Vector3& c, double r, const Box& box) noexcept {
  if (!(r > 0.0)) return 0.0;
  cases::Vector3 d0{};
  cases::Vector3 d1{};
  bool inside = true;
  for (std::size_t k = 0; k < 3; ++k) {
    d0[k] = box.lo[k] - c[k];
    d1[k] = box.hi[k] - c[k];
    if (d0[k] >= r || d1[k] <= -r || !(d1[k] > d0[k])) return 0.0;  // apart, or an empty box
    inside = inside && d0[k] <= -r && d1[k] >= r;
  }
  const double whole = dem::sphere_volume(r);
  if (inside) return whole;
  // A box whose farthest corner lies in the sphere is all inside it.
  double far = 0.0;
  for (std::size_t k = 0; k < 3; ++k) far += std::max(d0[k] * d0[k], d1[k] * d1[k]);
  if (far <= r * r) return box.volume();
  // Slices normal to z at height z = r sin θ: radius ρ = r cos θ, thickness dz = r cos θ dθ.
  const double theta_lo = std::asin(std::max(d0[2], -r) / r);
  const double theta_hi = std::asin(std::min(d1[2], r) / r);
  // The slice's area changes form where its circle reaches a side line or a corner of the
  // x–y rectangle: split there so that every piece is smooth.
  std::vector<double> cuts{theta_lo, theta_hi};
  const auto cut_at = [&](double distance) {
    if (!(distance > 0.0 && distance < r)) return;
    const double phi = std::acos(distance / r);
    for (const double t : {-phi, phi}) {
      if (t > theta_lo && t < theta_hi) cuts.push_back(t);
    }
  };
  for (const double x : {d0[0], d1[0]}) {
    cut_at(std::abs(x));
    for (const double y : {d0[1], d1[1]}) cut_at(std::hypot(x, y));
  }
  for (const double y : {d0[1], d1[1]}) cut_at(std::abs(y));
  std::sort(cuts.begin(), cuts.end());
  const auto slice = [&](double theta) {
    const double rho = r * std::cos(theta);
    return disk_rectangle_area(rho, d0[0], d1[0], d0[1], d1[1]) * rho;
  };
  // Where a slice's circle reaches a side line, the clipped area grows like a power 3/2 of the
  // distance from the piece's end. The smoothstep map θ = θ₀ + w(3s² − 2s³) turns those powers
  // into odd powers of s (analytic), so Gauss–Legendre in s converges to round-off.
  double volume = 0.0;
  for (std::size_t k = 1; k < cuts.size(); ++k) {
    const double t0 = cuts[k - 1];
    const double w = cuts[k] - t0;
    if (!(w > 0.0)) continue;
    const auto mapped = [&](double s) { return slice(t0 + w * s * s * (3.0 - 2.0 * s)) * 6.0 * w * s * (1.0 - s); };
    volume += boost::math::quadrature::gauss<double, 30>::integrate(mapped, 0.0, 1.0);
  }
  return std::clamp(volume, 0.0, std::min(whole, box.volume()));
}

double packing_fraction(std::span<const cases::Vector3> centres, std::span<const double> radii, const Box& box) {
  if (centres.size() != radii.size()) {
    throw std::invalid_argument("packing_fraction: the centres and radii differ in number");
  }
  const double volume = box.volume();
  if (!(volume > 0.0)) throw std::invalid_argument("packing_fraction: the region is empty");
  double solid = 0.0;
  for (std::size_t i = 0; i < centres.size(); ++i) solid += sphere_box_volume(centres[i], radii[i], box);
  return solid / volume;
}

Box interior(const Box& box, double margin) {
  Box in = box;
  for (std::size_t k = 0; k < 3; ++k) {
    in.lo[k] += margin;
    in.hi[k] -= margin;
    if (!(in.hi[k] > in.lo[k])) {
      throw std::invalid_argument("the region is no wider than twice the interior margin: no interior is left");
    }
  }
  return in;
}

double obscured_fraction(std::span<const cases::Vector3> centres, std::span<const double> radii, const Box& box,
                         std::size_t ny, std::size_t nz) {
  if (centres.size() != radii.size()) {
    throw std::invalid_argument("obscured_fraction: the centres and radii differ in number");
  }
  if (ny == 0 || nz == 0) throw std::invalid_argument("obscured_fraction: the grid has no points");
  if (!(box.hi[1] > box.lo[1]) || !(box.hi[2] > box.lo[2])) {
    throw std::invalid_argument("obscured_fraction: the region's y–z face is empty");
  }
  std::vector<std::size_t> in_box;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (box.contains(centres[i])) in_box.push_back(i);
  }
  const double dy = (box.hi[1] - box.lo[1]) / static_cast<double>(ny);
  const double dz = (box.hi[2] - box.lo[2]) / static_cast<double>(nz);
  std::size_t obscured = 0;
  for (std::size_t a = 0; a < ny; ++a) {
    const double y = box.lo[1] + (static_cast<double>(a) + 0.5) * dy;
    for (std::size_t b = 0; b < nz; ++b) {
      const double z = box.lo[2] + (static_cast<double>(b) + 0.5) * dz;
      const bool covered = std::any_of(in_box.begin(), in_box.end(), [&](std::size_t i) {
        const double ey = centres[i][1] - y;
        const double ez = centres[i][2] - z;
        return radii[i] * radii[i] > ey * ey + ez * ez;  // eq G.1, squared
      });
      if (covered) ++obscured;
    }
  }
  return static_cast<double>(obscured) / static_cast<double>(ny * nz);
}

std::vector<std::uint32_t> contact_counts(std::span<const cases::Vector3> centres, std::span<const double> radii) {
  if (centres.size() != radii.size()) {
    throw std::invalid_argument("contact_counts: the centres and radii differ in number");
  }
  std::vector<breakup::SnapshotSphere> spheres;
  spheres.reserve(centres.size());
  for (std::size_t k = 0; k < centres.size(); ++k) {
    spheres.push_back({dem::Vec3(centres[k][0], centres[k][1], centres[k][2]), radii[k]});
  }
  std::vector<std::uint32_t> contacts(spheres.size(), 0);
  for (const auto& [i, j] : breakup::bonded_pairs(spheres, breakup::body_contact(spheres))) {
    ++contacts[i];
    ++contacts[j];
  }
  return contacts;
}

double coordination_number(std::span<const cases::Vector3> centres, std::span<const double> radii, const Box& box) {
  const std::vector<std::uint32_t> contacts = contact_counts(centres, radii);
  std::size_t inside = 0;
  std::size_t sum = 0;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    if (!box.contains(centres[k])) continue;
    ++inside;
    sum += contacts[k];
  }
  if (inside == 0) throw std::invalid_argument("no mobile sphere has its centre in the region");
  return static_cast<double>(sum) / static_cast<double>(inside);
}

double share_inside(std::span<const cases::Vector3> centres, const Box& box) noexcept {
  if (centres.empty()) return 0.0;
  const auto n = std::count_if(centres.begin(), centres.end(), [&](const cases::Vector3& c) { return box.contains(c); });
  return static_cast<double>(n) / static_cast<double>(centres.size());
}

}  // namespace comparison
