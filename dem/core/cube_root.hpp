// SPDX-License-Identifier: MIT
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace dem {

/// Cube root of x, within one unit in the last place (faithful), for the contact loop: the JKR
/// critical radius takes one per contact and step, where the C library's cbrt (a call into frexp
/// and scalbn) cost ~15 % of an agglomerate impact (docs/performance.md). Positive normal x take
/// the fast path: x = m·2^e with m in [1, 2) and e = 3q + r, so ∛x = 2^q · ∛(2^r) · ∛m; ∛m from a
/// degree-6 polynomial (interpolation at the Chebyshev nodes of [1, 2], relative error 2.5e-7),
/// then one Halley step z − z (z³ − u)/(2z³ + u) on u = m·2^r, which cubes that error to below
/// rounding, and the exact scaling by 2^q. Zero,
/// negative, subnormal, infinite and NaN arguments go to std::cbrt.
[[nodiscard]] inline double cube_root(double x) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased = static_cast<std::int64_t>(bits >> 52U);  // sign bit clear for x > 0
  if (!(x > 0.0) || biased == 0 || biased == 0x7FF) return std::cbrt(x);
  // e + 3·1023 ≥ 2 > 0, so integer division splits e = 3q + r with r in {0, 1, 2}.
  const std::int64_t shifted = biased - 1023 + 3 * 1023;
  const std::int64_t q = shifted / 3 - 1023;
  const auto r = static_cast<std::size_t>(shifted % 3);
  const double m = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFULL) | 0x3FF0000000000000ULL);
  const double w = m - 1.5;
  // ∛(1.5 + w), w in [−½, ½], in Estrin's scheme.
  const double w2 = w * w;
  const double p01 = 1.1447142425533319 + 0.2543834538641131 * w;
  const double p23 = -0.05653050145458336 + 0.020857149295409144 * w;
  const double p45 = -0.009260767947340777 + 0.005166699418207403 * w;
  const double p6 = -0.002703333870491041;
  const double cbrt_m = p01 + w2 * (p23 + w2 * (p45 + w2 * p6));
  constexpr double kTwoPowers[3] = {1.0, 2.0, 4.0};
  constexpr double kCubeRootOfTwoPowers[3] = {1.0, 1.2599210498948732, 1.5874010519681994};
  // Halley's step on the reduced argument u = m·2^r in [1, 8), where nothing can overflow or
  // lose precision; the power of two 2^q is exact.
  const double u = m * kTwoPowers[r];
  const double z = cbrt_m * kCubeRootOfTwoPowers[r];
  const double z3 = z * z * z;
  const double root_u = z - z * ((z3 - u) / (2.0 * z3 + u));
  return root_u * std::bit_cast<double>(static_cast<std::uint64_t>(q + 1023) << 52U);
}

}  // namespace dem
