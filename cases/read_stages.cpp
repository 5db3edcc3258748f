// SPDX-License-Identifier: MIT
// Section reader for [[stages]]: preparation stages the core runs before any engine (agglomerate
// formation, thesis §5.2.1; launch at a wall, §5.2.2; a pour settled and skimmed, §6.3).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "cases/excerpt.hpp"
#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/names.hpp"

namespace cases::loader {
namespace {

constexpr std::array<std::string_view, 3> kKinds{"formation", "launch", "settle"};
constexpr auto kRemoveBy = std::to_array<std::string_view>({"centre", "top"});
constexpr auto kFormationKeys = std::to_array<std::string_view>(
    {"kind", "name", "pull", "pull_time", "restitution", "friction", "walls", "gravity", "kinetic_energy",
     "max_duration"});
constexpr auto kSettleKeys = std::to_array<std::string_view>(
    {"kind", "name", "restitution", "kinetic_energy", "min_duration", "max_duration", "remove_above",
     "remove_by", "count_spin"});
constexpr auto kLaunchKeys =
    std::to_array<std::string_view>({"kind", "name", "wall", "speed", "angle", "direction", "height"});

void require_restitution_damping(const Value& value, const Scene& scene, std::string_view stage);

FormationStageSpec read_formation(const Table& t, const Scene& scene) {
  t.allow_only(kFormationKeys);
  FormationStageSpec f;
  f.pull = t.require("pull").number(positive_range());
  f.pull_time = t.require("pull_time").number(positive_range());
  const Value restitution = t.require("restitution");
  f.restitution = restitution.number(dem::ValueRange{0.0, 1.0, true, false});
  require_restitution_damping(restitution, scene, "formation");
  if (const auto v = t.find("friction")) f.friction = v->boolean();
  if (const auto v = t.find("walls")) f.walls = v->boolean();
  if (const auto v = t.find("gravity")) f.gravity = v->vector3();
  f.kinetic_energy = t.require("kinetic_energy").number(positive_range());
  f.max_duration = t.require("max_duration").number(positive_range());
  if (f.max_duration <= f.pull_time) {
    t.fail("max_duration", fmt::format("must exceed pull_time ({} s): the stage ends only after the pull has faded, "
                                       "got {} s",
                                       f.pull_time, f.max_duration));
  }
  return f;
}

/// Throws on `value` (a stage's restitution) when the model's damping reads no restitution: the
/// stage could not change the damping. `stage` names the stage kind in the message.
void require_restitution_damping(const Value& value, const Scene& scene, std::string_view stage) {
  if (used_properties(scene.model).contains("restitution")) return;
  value.fail(fmt::format("the model's damping ('{}') does not read a restitution, so the {} cannot raise the "
                         "damping; choose damping = \"restitution\" (or another law set by a restitution)",
                         scene.model.damping, stage));
}

SettleStageSpec read_settle(const Table& t, const Scene& scene) {
  t.allow_only(kSettleKeys);
  SettleStageSpec s;
  if (const auto v = t.find("restitution")) {
    s.restitution = v->number(dem::ValueRange{0.0, 1.0, true, false});
    require_restitution_damping(*v, scene, "settle stage");
  }
  s.kinetic_energy = t.require("kinetic_energy").number(positive_range());
  if (const auto v = t.find("min_duration")) {
    s.min_duration = v->number(dem::ValueRange{0.0, std::numeric_limits<double>::infinity(), false, true});
  }
  s.max_duration = t.require("max_duration").number(positive_range());
  if (s.max_duration <= s.min_duration) {
    t.fail("max_duration", fmt::format("must exceed min_duration ({} s), got {} s", s.min_duration, s.max_duration));
  }
  if (const auto v = t.find("remove_above")) s.remove_above = v->number();
  if (const auto v = t.find("remove_by")) {
    if (!s.remove_above) v->fail("needs remove_above: it says which part of a sphere must lie above that height");
    s.remove_by_top = v->keyword(kRemoveBy, "part of a sphere") == "top";
  }
  if (const auto v = t.find("count_spin")) s.count_spin = v->boolean();
  bool gravity = false;
  for (const double g : scene.gravity) gravity = gravity || g != 0.0;
  if (!gravity) t.fail("kind", "a settle stage needs gravity ([fields] gravity): without it nothing settles");
  return s;
}

LaunchStageSpec read_launch(const Table& t, const Scene& scene) {
  t.allow_only(kLaunchKeys);
  LaunchStageSpec l;
  const Value wall = t.require("wall");
  l.wall = wall_index(wall, scene);
  const Value speed = t.require("speed");
  l.speed = speed.number(positive_range());
  check_speed(speed, l.speed, "launch speed");
  l.angle = t.require("angle").number(dem::ValueRange{0.0, 90.0, true, false});
  l.direction = in_plane_direction(t.require("direction"), scene.walls[l.wall]);
  if (const auto v = t.find("height")) {
    l.height = v->number(dem::ValueRange{0.5, std::numeric_limits<double>::infinity(), true, true});
  }
  return l;
}

}  // namespace

void read_stages(const Table& root, Scene& scene) {
  const auto section = root.find("stages");
  if (!section) return;
  if (!section->node().is_array()) {
    section->fail("expected an array of tables ([[stages]]), got " + describe(section->node()));
  }
  std::size_t launches = 0;
  for (const Value& entry : section->elements()) {
    const Table t = entry.table();
    const std::string kind = t.require("kind").keyword(kKinds, "stage kind");
    StageSpec stage;
    stage.name = t.has("name") ? read_name(t.require("name")) : kind;
    if (kind == "formation") {
      if (launches > 0) t.fail("kind", "a formation stage must come before the launch stage");
      stage.action = read_formation(t, scene);
    } else if (kind == "settle") {
      if (launches > 0) t.fail("kind", "a settle stage must come before the launch stage");
      stage.action = read_settle(t, scene);
    } else {
      if (++launches > 1) t.fail("kind", "a case has at most one launch stage");
      stage.action = read_launch(t, scene);
    }
    scene.stages.push_back(stage);
  }
  if (scene.stages.empty()) section->fail("must list at least one stage, or be left out");
}

}  // namespace cases::loader
