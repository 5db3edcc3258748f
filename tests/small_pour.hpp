// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace test_support {

/// The head of a small pour's case file: 48 glass spheres of radius 1 mm on a simple cubic grid
/// (pitch 2.2 mm, 3 × 3 a layer, seed 7, jitter 0.02 m/s) in a box 6.6 mm wide and 4 cm tall,
/// linear springs (k = 2000 N/m) with restitution damping (ε = 0.5). The box leaves the faces
/// `open_faces` (a TOML array) open; the caller adds fields, integration, stages and the rest.
inline std::string small_pour_head(const std::string& name, const std::string& open_faces = R"(["z+"])") {
  return R"([case]
name = ")" + name + R"("
[model]
normal = "linear"
damping = "restitution"
[materials.glass]
density = 2500.0
normal_stiffness = 2000.0
restitution = 0.5
[[populations]]
material = "glass"
seed = 7
arrangement = "simple_cubic"
count = 48
spacing = 2.2e-3
velocity_jitter = 0.02
region = { shape = "box", min = [0.0, 0.0, 0.0], max = [6.6e-3, 6.6e-3, 0.04] }
size = { distribution = "monodisperse", radius = 1.0e-3 }
[[walls]]
type = "box"
name = "box"
min = [0.0, 0.0, 0.0]
max = [6.6e-3, 6.6e-3, 0.04]
material = "glass"
open_faces = )" + open_faces + "\n";
}

}  // namespace test_support
