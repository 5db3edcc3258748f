// SPDX-License-Identifier: MIT
#pragma once
// Randomised cross-code scenes for the matched engines (docs/engines.md, "Matched numerics on
// random scenes"): a seed gives one small case file — 2 to 6 spheres of mixed radii and one or
// two materials, random positions, velocities and spins, gravity on or off, 0 to 2 plane walls,
// for YADE and LIGGGHTS sometimes a mesh of one or two tilted triangles under the spheres (an
// STL written beside the case), and a contact model drawn from every sub-model of every slot —
// that runs on a reference code and on the core with that code's numerics. The matched row (trace deviation, at 1e-8) says
// whether the two agree; the code's mapping says n/a, with its reason, where it cannot express
// the scene.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace studies {

/// One generated scene: its case-file text and what was drawn, for the summary.
struct FuzzScene {
  std::string name;     ///< fuzz_<code>_<seed>
  std::string toml;     ///< the case file
  std::string model;    ///< normal/damping/tangential/cohesion/rolling keywords, '/'-joined
  int spheres = 0;
  int walls = 0;    ///< plane walls
  int facets = 0;   ///< facets of the mesh wall, 0 without one (YADE and LIGGGHTS scenes)
  bool gravity = false;
  /// Files the case names, to be written beside it: (file name, text) — the mesh's STL.
  std::vector<std::pair<std::string, std::string>> files;
  int draws = 1;  ///< drafts drawn before this one was kept (random_matched_scene with a filter)
};

/// The scene of `seed` for reference code `code` ("lammps", "yade" or "liggghts"); the same seed always
/// gives the same text. Throws std::invalid_argument for another code.
[[nodiscard]] FuzzScene random_matched_scene(std::string_view code, std::uint64_t seed);

/// Whether the code's mapping expresses a drafted scene (the driver's supports()).
using ExpressibleFilter = std::function<bool(const FuzzScene&)>;

/// The scene of `seed`, drawn so that most scenes (kExpressibleShare) are ones the code
/// expresses: such a seed redraws its draft (the k-th draft from the seed mixed with k) until
/// `expressible` accepts it, at most kMaxDrafts times; the other seeds keep their first draft,
/// so the mappings' n/a answers are still exercised. Deterministic for a seed and filter.
[[nodiscard]] FuzzScene random_matched_scene(std::string_view code, std::uint64_t seed,
                                             const ExpressibleFilter& expressible);

/// A scene's start velocities: each component uniform in ±kFuzzSpeed [m/s], and the compared
/// pair approaching along its line of centres at kFuzzApproach each [m/s].
inline constexpr double kFuzzSpeed = 0.2;
inline constexpr double kFuzzApproach = 0.3;
/// How long a scene runs [s].
inline constexpr double kFuzzDuration = 2.0e-3;
/// The fastest start, √3·kFuzzSpeed + kFuzzApproach = 0.646 m/s rounded up [m/s].
inline constexpr double kFuzzFastestStart = 0.65;
static_assert(kFuzzFastestStart >= 1.7320508075688772 * kFuzzSpeed + kFuzzApproach);

/// How far a YADE scene's spheres start from its mesh's shared edge beyond their radius [m]:
/// twice the fastest start over the run, so that none reaches it.
inline constexpr double kYadeMeshEdgeClearance = 2.0 * kFuzzFastestStart * kFuzzDuration;

/// Share of seeds whose scene must be expressible by the code.
inline constexpr double kExpressibleShare = 0.8;
/// Most drafts one seed draws.
inline constexpr int kMaxDrafts = 200;

}  // namespace studies
