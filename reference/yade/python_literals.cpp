// SPDX-License-Identifier: MIT
#include "reference/yade/python_literals.hpp"

#include <cmath>

#include <fmt/format.h>

namespace reference::yade {

std::string py_float(double value) {
  if (std::isnan(value)) return "float('nan')";
  if (std::isinf(value)) return value > 0 ? "float('inf')" : "float('-inf')";
  std::string s = fmt::format("{}", value);  // shortest representation that round-trips
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string py_vector3(const std::array<double, 3>& v) {
  return fmt::format("Vector3({}, {}, {})", py_float(v[0]), py_float(v[1]), py_float(v[2]));
}

std::string py_string(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\' || c == '\'') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace reference::yade
