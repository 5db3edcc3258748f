// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace cases {

/// A seeded stream of random numbers that is the same on every platform: the 64-bit Mersenne
/// twister (whose output the C++ standard fixes) with uniform and normal variates computed here
/// rather than by the library's distributions (whose algorithms are unspecified).
class RandomStream {
 public:
  /// The stream of `seed`.
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
  /// Uniform on [0, 1), 53 random bits.
  double uniform() noexcept { return static_cast<double>(engine_() >> 11U) * 0x1.0p-53; }
  /// Uniform on [a, b).
  double uniform(double a, double b) noexcept { return a + (b - a) * uniform(); }
  /// Standard normal, by the Box–Muller transform (pairs; the second is kept for the next call).
  double normal() noexcept {
    if (spare_) {
      spare_ = false;
      return second_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: the logarithm stays finite
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    second_ = r * std::sin(2.0 * std::numbers::pi * u2);
    spare_ = true;
    return r * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 engine_;
  bool spare_ = false;
  double second_ = 0.0;
};

}  // namespace cases
