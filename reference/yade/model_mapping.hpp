// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference::yade {

/// The YADE 2023.02a contact-law family a scene is expressed with (laws and conversions:
/// docs/engines.md, section YADE).
enum class YadeLaw {
  frict,        ///< FrictMat + Ip2_…_FrictPhys(kn, ks, frictAngle) + Law2_ScGeom_FrictPhys_CundallStrack
  frict_visco,  ///< FrictViscoMat(betan) + Ip2_…_FrictViscoPhys(kn, kRatio, frictAngle) + Law2_…_CundallStrackVisco
  mindlin,      ///< FrictMat(young, poisson) + Ip2_FrictMat_FrictMat_MindlinPhys + Law2_ScGeom_MindlinPhys_Mindlin
};

/// One material pair's contact parameters, taken from the workbench's pair table and written
/// into the script explicitly (YADE's own mixing is never used where YADE offers a MatchMaker).
struct YadePairParameters {
  std::size_t material_a = 0;
  std::size_t material_b = 0;
  double normal_stiffness = 0.0;  ///< kn [N/m] (frict, frict_visco); 0 for Mindlin
  double damping_ratio = 0.0;     ///< betan: frict_visco η/(2√(m* kn)); Mindlin β_n; 0 without dashpot
  double shear_stiffness = 0.0;   ///< ks [N/m] (frict; frict_visco passes kRatio = ks/kn); 0 for Mindlin
  double friction_angle = 0.0;    ///< atan μ [rad] (frictAngle MatchMaker)
  double cohesive_stiffness = 0.0;  ///< k_c [N/m] of the per-step Python force (linear cohesion)
};

/// A YADE material written for one wall: its base scene material (density, label, pair values)
/// with its own young and poisson.
struct YadeWallMaterial {
  std::size_t base = 0;
  double young = 0.0;    ///< FrictMat.young [Pa]; negative for a rigid wall
  double poisson = 0.0;  ///< FrictMat.poisson
};

/// young and poisson of a wall's YADE material for which Ip2_FrictMat_FrictMat_MindlinPhys,
/// against a sphere of (young_s, poisson_s) at YADE's R = r/k (k = `radius_ratio`: 2 for a plane,
/// as Ig2_Wall_Sphere_ScGeom gives the wall the sphere's radius; 3/2 for a facet, to which
/// Ig2_Facet_Sphere_ScGeom gives twice it), yields k_no = 4/3 E* √r and k_so = 8 G* √r, the
/// sphere–plane contact with R* = r: YADE's E* and G* must be √k times the case's. With
/// c = (1 − ν²)/E and d = (2 − ν)/G per material (YADE's mixing is 1/E* = c_s + c_w,
/// 1/G* = d_s + d_w), the wall needs c′ = 1/(√k E*) − c_s and d′ = 1/(√k G*) − d_s, solved by
/// ν′ = (ρ − 4)/(ρ − 2), ρ = d′/c′, and E′ = (1 − ν′²)/c′. E′ < 0 when the wall is stiffer than
/// that (a rigid plane: E′ = −(2 + √2) E_s, ν′ = ν_s); YADE takes it as given. Empty
/// `shear_modulus`: no tangential law, ν′ = ν_s. Returns nothing when no finite solution exists.
[[nodiscard]] std::optional<YadeWallMaterial> compensated_wall_material(
    double young_s, double poisson_s, double effective_modulus, std::optional<double> effective_shear_modulus,
    double radius_ratio = 2.0);

/// How the scene's contact model and walls are expressed in YADE 2023.02a.
struct YadeModelMapping {
  YadeLaw law = YadeLaw::frict;
  bool viscous = false;                        ///< law == frict_visco
  std::vector<double> material_damping_ratio;  ///< FrictViscoMat.betan per scene material
  std::vector<double> material_young;          ///< FrictMat.young per material (Mindlin; else 1)
  std::vector<double> material_poisson;        ///< FrictMat.poisson per material (Mindlin; else 0.25)
  double surface_energy = 0.0;                 ///< Mindlin DMT gamma (one value for every pair); 0: none
  bool python_cohesion = false;                ///< linear cohesion as a per-step Python force
  double aabb_enlarge = 1.0;                   ///< largest r̂/r: the collider's box enlargement for it
  std::vector<YadePairParameters> pairs;       ///< every material pair a ≤ b (and each wall material's copies)
  /// O.materials added after the scene's (ids scene.materials.size() + k), one per plane wall
  /// and one per mesh under Hertz–Mindlin: the wall's material with young and poisson chosen so
  /// that YADE's k_no and k_so at its R (r/2, or 2r/3 for a facet) equal the case's at R* = r
  /// (see compensated_wall_material).
  std::vector<YadeWallMaterial> wall_materials;
  std::vector<std::size_t> wall_material_ids;  ///< O.materials id per scene wall (the scene's material unless compensated)
  std::vector<std::string> reasons;            ///< why the model cannot be expressed (empty: it can)
  std::vector<std::string> warnings;           ///< where YADE's law differs from the workbench's
  std::map<std::string, std::string> conventions;  ///< "contact <slot>" → registry mapping text
};

/// Maps the scene's contact model (one small function per slot), its plane walls and its
/// meshes. Never throws: a model the core cannot build gives a reason.
YadeModelMapping map_contact_model(const PreparedScene& prepared);

/// Pair damping ratio YADE forms from two FrictViscoMat.betan values (Ip2_FrictViscoMat_…:
/// the mean when both are non-zero, else the non-zero one).
[[nodiscard]] double yade_mixed_damping_ratio(double betan_a, double betan_b) noexcept;

/// YADE Hertz–Mindlin's E* from two materials, E_a E_b / ((1 − ν_a²) E_b + (1 − ν_b²) E_a)
/// (eq 3.13 in YADE's operation order). Pure.
[[nodiscard]] double yade_effective_modulus(double young_a, double poisson_a, double young_b,
                                            double poisson_b) noexcept;

/// Axis (0, 1, 2) and sense (+1/−1) of utils.wall for a plane wall normal, or axis −1 when the
/// normal is not a coordinate axis (YADE's Wall is axis-aligned).
struct WallAxis {
  int axis = -1;
  int sense = 0;
};
[[nodiscard]] WallAxis wall_axis(const cases::Vector3& normal) noexcept;

}  // namespace reference::yade
