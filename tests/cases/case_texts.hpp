// SPDX-License-Identifier: MIT
#pragma once
// Case texts and helpers the loader tests share.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"

namespace case_texts {

/// A case header named `name` with the linear spring and a "glass" material: the start of the
/// generated-population cases several tests build (append [[populations]] and the rest).
inline std::string linear_glass_header(const std::string& name) {
  return "[case]\nname = \"" + name + R"("
[model]
normal = "linear"
[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5
)";
}

/// linear_glass_header(name) with one glass population in a 0.1 m box (radius 4 mm) whose other
/// keys are `population` (seed, arrangement, count, …), run for 0.01 s at Δt = 1e-5 s; append
/// [compare] or [output] tables.
inline std::string glass_population_case(const std::string& name, const std::string& population) {
  return linear_glass_header(name) + "[[populations]]\nmaterial = \"glass\"\n" + population + R"(region = { shape = "box", min = [0.0, 0.0, 0.0], max = [0.1, 0.1, 0.1] }
size = { distribution = "monodisperse", radius = 0.004 }
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 0.01
)";
}

/// Two glass spheres, one moving at 1 m/s towards the other, fixed one; 100 steps of 1e-5 s.
inline constexpr std::string_view kPair = R"([case]
name = "pair"

[model]
normal = "linear"

[materials.glass]
density = 2500.0
normal_stiffness = 1.0e5

[[particles]]
radius = 0.01
material = "glass"
position = [0.0, 0.0, 0.0]
velocity = [1.0, 0.0, 0.0]

[[particles]]
radius = 0.01
material = "glass"
position = [0.05, 0.0, 0.0]
fixed = true

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 1.0e-3
)";

/// `text` with the first occurrence of `from` replaced by `to` (which must be there).
inline std::string replaced(std::string text, std::string_view from, std::string_view to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The CaseError loading `text` (named case.toml) throws; fails the test when nothing is thrown.
inline cases::CaseError error_of(std::string_view text) {
  try {
    static_cast<void>(cases::load_case_text(text, "case.toml"));
  } catch (const cases::CaseError& e) {
    return e;
  }
  ADD_FAILURE() << "no CaseError for:\n" << text.substr(0, 2000);
  return cases::CaseError("case.toml", "(none)", "no error");
}

}  // namespace case_texts
