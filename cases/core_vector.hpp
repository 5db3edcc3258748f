// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "dem/core/vector.hpp"

namespace cases {

/// A case file's vector (x, y, z) as the core's vector type.
inline dem::Vec3 core_vec(const Vector3& v) noexcept { return {v[0], v[1], v[2]}; }
/// The core's vector as a case file's (x, y, z).
inline Vector3 case_vec(const dem::Vec3& v) noexcept { return {v[0], v[1], v[2]}; }

}  // namespace cases
