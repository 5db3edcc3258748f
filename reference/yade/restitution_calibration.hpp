// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "reference/yade/model_mapping.hpp"

namespace reference::yade {

/// The two-body YADE run that calibrates FrictViscoMat.betan so that YADE's rebound has the
/// case's restitution ε (issue 4 §4; docs/engines.md): the compared contact of the case (its
/// particle, its partner sphere or wall, their radii, masses, velocities and Δt) alone, without
/// gravity, friction or rotation. YADE's dashpot sees α·u_n (model_mapping.cpp), so the textbook
/// betan = β(ε)/2 rebounds below ε; the calibration absorbs α and the leapfrog's O(Δt) error.
struct YadeCalibrationPlan {
  std::size_t material = 0;       ///< scene material whose betan is calibrated
  double target = 0.0;            ///< ε the case asks for
  double start = 0.0;             ///< β(ε)/2, the textbook value and first secant point
  std::size_t particle = 0;       ///< the case's compared particle (body id in the trial)
  std::optional<std::size_t> partner_particle;  ///< the sphere partner, or
  std::optional<std::size_t> partner_wall;      ///< the wall partner (scene wall index)
  std::size_t partner_wall_entry = 0;  ///< its place in the script's WALLS (walls gone before the run are left out)
  std::array<double, 3> normal{};  ///< contact normal (from partner to particle) at the start
  std::uint64_t max_steps = 0;     ///< steps of one trial at most (the case's)
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  ///< material pairs of the KN MatchMaker
  std::string description;         ///< for RunResult::calibrations[].parameter
};

/// The calibration a native run of `scene` needs, or empty: only for damping 'restitution' on
/// the FrictVisco law (YADE's own 'yade_frictvisco' is not calibrated), a compared contact of
/// one material, and a head-on start (the normal is fixed by the initial positions).
std::optional<YadeCalibrationPlan> plan_calibration(const cases::Scene& scene,
                                                    const YadeModelMapping& model,
                                                    std::uint64_t max_steps);

/// Name of the file the calibration writes: "betan,restitution" rows, one per trial, the last
/// one being the chosen betan.
inline constexpr std::string_view kCalibrationFile = "calibration.csv";

/// Python block (pure text) that runs the secant iterations in the script before the scene is
/// built and sets MATERIALS[material] to the chosen betan. Needs `_append_materials()`,
/// MATERIALS, PARTICLES, WALLS, KN and FRICTION_ANGLE from the script writer.
std::string write_calibration_block(const YadeCalibrationPlan& plan);

/// The calibration record parsed from kCalibrationFile. Throws YadeOutputError naming the
/// file and line when a row is not two numbers or there is none.
cases::Calibration parse_calibration_csv(std::string_view text, const YadeCalibrationPlan& plan);

}  // namespace reference::yade
