// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <cstdint>

namespace dem {

/// Wall-clock seconds a force field spent in each part of its work, for `demwb bench`.
struct LoopTiming {
  double neighbor_build = 0.0;  ///< neighbour and wall list builds [s]
  double pair_loop = 0.0;       ///< sphere–sphere contacts [s]
  double sphere_loop = 0.0;     ///< walls, fields and accelerations, per sphere [s]
  double other = 0.0;           ///< packing, displacement checks, observation [s]
};

/// Adds the seconds since construction to a LoopTiming member when it goes out of scope.
class ScopedSeconds {
 public:
  /// Times into `sink`.
  explicit ScopedSeconds(double& sink) noexcept : sink_(sink), start_(std::chrono::steady_clock::now()) {}
  ScopedSeconds(const ScopedSeconds&) = delete;
  ScopedSeconds& operator=(const ScopedSeconds&) = delete;
  ~ScopedSeconds() {
    sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  double& sink_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dem
