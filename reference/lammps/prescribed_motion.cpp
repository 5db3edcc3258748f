// SPDX-License-Identifier: MIT
#include "reference/lammps/prescribed_motion.hpp"

#include <fmt/format.h>

namespace reference::lammps {
namespace {

constexpr std::string_view kAxes[] = {"x", "y", "z"};

}  // namespace

std::string motion_displacement_formula(const std::vector<cases::MotionSegmentSpec>& motion,
                                        int axis) {
  std::string out;
  double begin = 0.0;
  for (std::size_t k = 0; k < motion.size(); ++k) {
    const double v = motion[k].velocity[axis];
    const bool last = k + 1 == motion.size();
    if (v != 0.0) {
      // LAMMPS' min()/max() are reductions over computes, so the clamp uses logical factors.
      const std::string elapsed = fmt::format("(time-{:.17g})", begin);
      const std::string clamped =
          last ? fmt::format("{}*(time>{:.17g})", elapsed, begin)
               : fmt::format("({0}*(time>{1:.17g})*(time<{2:.17g})+{3:.17g}*(time>={2:.17g}))",
                             elapsed, begin, begin + motion[k].duration, motion[k].duration);
      out += fmt::format("{}{:.17g}*{}", out.empty() ? "" : "+", v, clamped);
    }
    begin += motion[k].duration;
  }
  return out.empty() ? "0" : out;
}

std::string motion_velocity_formula(const std::vector<cases::MotionSegmentSpec>& motion,
                                    int axis) {
  std::string out;
  double begin = 0.0;
  for (std::size_t k = 0; k < motion.size(); ++k) {
    const double v = motion[k].velocity[axis];
    const bool last = k + 1 == motion.size();
    const double end = begin + motion[k].duration;
    if (v != 0.0) {
      out += fmt::format("{}{:.17g}*(time>={:.17g})", out.empty() ? "" : "+", v, begin);
      if (!last) out += fmt::format("*(time<{:.17g})", end);
    }
    begin = end;
  }
  return out.empty() ? "0" : out;
}

std::vector<std::string> motion_commands(const cases::Scene& scene) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const auto& motion = scene.particles[i].motion;
    if (motion.empty()) continue;
    out.push_back(fmt::format("group tr_driven_{} id {}", i, i + 1));
    std::string args;
    for (int a = 0; a < 3; ++a) {
      out.push_back(fmt::format("variable tr_d{}_{} equal \"{}\"", kAxes[a], i,
                                motion_displacement_formula(motion, a)));
      args += fmt::format(" v_tr_d{}_{}", kAxes[a], i);
    }
    for (int a = 0; a < 3; ++a) {
      out.push_back(fmt::format("variable tr_v{}_{} equal \"{}\"", kAxes[a], i,
                                motion_velocity_formula(motion, a)));
      args += fmt::format(" v_tr_v{}_{}", kAxes[a], i);
    }
    out.push_back(fmt::format("fix tr_move_{0} tr_driven_{0} move variable{1}", i, args));
  }
  return out;
}

}  // namespace reference::lammps
