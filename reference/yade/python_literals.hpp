// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace reference::yade {

/// A Python float literal that parses back to exactly `value` (shortest round-trip digits;
/// "float('nan')", "float('inf')" for non-finite values). Pure.
std::string py_float(double value);

/// "Vector3(x, y, z)" with exact float literals. Pure.
std::string py_vector3(const std::array<double, 3>& v);

/// A single-quoted Python string literal of `text` (backslash, quote and control characters
/// escaped). Pure.
std::string py_string(std::string_view text);

}  // namespace reference::yade
