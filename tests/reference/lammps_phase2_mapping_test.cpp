// SPDX-License-Identifier: MIT
// Phase-2 LAMMPS mapping without the binary: Hertz-family E conversions (pair and wall), JKR,
// friction, Tsuji e_in inversion, wall planes, prescribed motion, and the decks of the
// canonical cases.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/pair_table.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"
#include "reference/lammps/prescribed_motion.hpp"
#include "reference/lammps/tsuji_input.hpp"
#include "reference/lammps/run_conventions.hpp"
#include "reference/lammps/tsuji_input.hpp"
#include "reference/lammps/wall_mapping.hpp"

namespace lammps_phase2_mapping_test {

using reference::lammps::map_pair_law;
using reference::lammps::pair_coeff_arguments;
using reference::lammps::PairContext;

constexpr double kModulus = 4.6153846153846154e7;  // E* of E = 8.4e7, ν = 0.3, both bodies

dem::PairLaw hertz_law(const std::string& damping = "none", const std::string& cohesion = "none",
                       const std::string& tangential = "none", double restitution = 0.5) {
  dem::ModelChoice choice;
  choice.normal = "hertz";
  choice.damping = damping;
  choice.cohesion = cohesion;
  choice.tangential = tangential;
  dem::PairProperties p;
  p.effective_modulus = kModulus;
  p.restitution = restitution;
  p.surface_energy = 121.5;
  p.tangential_stiffness = 1e6;
  p.friction = 0.2;
  p.tangential_damping_ratio = 0.0;
  p.normal_stiffness = 1e5;
  return dem::make_pair_law(choice, p);
}

PairContext context(bool wall = false) {
  PairContext c;
  c.reduced_mass = 2.0943951023931952e-3;
  c.poisson_ratio = 0.3;
  c.wall = wall;
  return c;
}

cases::Scene canonical(const std::string& name) {
  return cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases" / "canonical" /
                          (name + ".toml"));
}

TEST(LammpsHertzMapping, PairCoeffEIsTwoOneMinusNuSquaredTimesEStar) {
  const auto c = map_pair_law(hertz_law(), context());
  EXPECT_EQ(c.normal_style, "hertz/material");
  EXPECT_DOUBLE_EQ(c.normal_elastic.at(0), 2.0 * (1.0 - 0.09) * kModulus);
  EXPECT_EQ(c.normal_trailing, std::vector<double>{0.3});
  EXPECT_EQ(c.damping_style, "velocity");
  EXPECT_EQ(c.damping_coefficient, 0.0);
}

TEST(LammpsHertzMapping, WallEIsTwoOneMinusNuTimesEStarForThisBuildsMissingSquare) {
  const auto c = map_pair_law(hertz_law(), context(true));
  EXPECT_DOUBLE_EQ(c.normal_elastic.at(0), 2.0 * (1.0 - 0.3) * kModulus);
}

TEST(LammpsHertzMapping, JkrReplacesTheNormalKeywordAndNeedsAHistoryTangential) {
  const auto c = map_pair_law(hertz_law("none", "jkr"), context());
  EXPECT_EQ(pair_coeff_arguments(c).substr(0, 4), "jkr ");
  EXPECT_EQ(c.normal_trailing, (std::vector<double>{0.3, 121.5}));
  EXPECT_EQ(c.tangential, "linear_history 0 0 0");
}

TEST(LammpsHertzMapping, JkrWallIsNotMappedBecauseTheWallNeverReleases) {
  const auto reasons = reference::lammps::unmapped_sub_models(hertz_law("none", "jkr"), true);
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("never releases"), std::string::npos);
}

TEST(LammpsHertzMapping, LinearCohesionIsNotMappedWithTheReason) {
  dem::PairLaw law = hertz_law();
  law.cohesion = dem::LinearCohesion{100.0};
  const auto reasons = reference::lammps::unmapped_sub_models(law);
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_NE(reasons[0].find("no linear cohesion over an interaction radius"), std::string::npos);
}

TEST(LammpsHertzMapping, SpringCoulombIsLinearHistoryWithKfRatioAndMu) {
  const auto c = map_pair_law(hertz_law("none", "none", "spring_coulomb"), context());
  EXPECT_EQ(c.tangential, "linear_history 1000000 0 0.20000000000000001");
}

TEST(LammpsTsujiInput, InvertsLammpsPolynomialToTheLastBits) {
  for (const double factor : {0.05290, 0.34074, 0.4817693, 1.0}) {
    const auto e = reference::lammps::tsuji_input_for_factor(factor);
    ASSERT_TRUE(e.has_value()) << factor;
    EXPECT_NEAR(dem::laws::lammps_tsuji_factor(*e), factor, 1e-14) << factor;
  }
  EXPECT_FALSE(reference::lammps::tsuji_input_for_factor(-1e-3).has_value());
  EXPECT_FALSE(reference::lammps::tsuji_input_for_factor(100.0).has_value());
  EXPECT_FALSE(reference::lammps::tsuji_input_for_factor(NAN).has_value());
}

TEST(LammpsTsujiInput, ThePolynomialFallsOverTheWholeInputRangeSoTheInverseIsUnique) {
  const double zero = reference::lammps::tsuji_input_zero();
  EXPECT_GT(zero, 1.0);
  EXPECT_LT(zero, 1.001);
  EXPECT_NEAR(dem::laws::lammps_tsuji_factor(zero), 0.0, 1e-15);
  double previous = dem::laws::lammps_tsuji_factor(reference::lammps::kTsujiInputLowest);
  for (int i = 1; i <= 100000; ++i) {
    const double e = reference::lammps::kTsujiInputLowest + (zero - reference::lammps::kTsujiInputLowest) * i / 100000.0;
    const double now = dem::laws::lammps_tsuji_factor(e);
    ASSERT_LT(now, previous) << e;
    previous = now;
  }
}

TEST(LammpsTsujiInput, EveryRestitutionInZeroToOneMaps) {
  // The core's α(ε) runs from √5 (ε → 0) to 0 (ε = 1): below ε ≈ 0.12 it needs e_in < 0, above
  // ε ≈ 0.9996 e_in > 1, and ε = 1 is no dashpot (damping velocity 0).
  for (int k = 1; k <= 2000; ++k) {
    const double e = k / 2000.0;
    const double factor = dem::laws::tsuji_factor(e);
    if (e == 1.0) {
      EXPECT_EQ(factor, 0.0);
      continue;
    }
    const auto e_in = reference::lammps::tsuji_input_for_factor(factor);
    ASSERT_TRUE(e_in.has_value()) << e;
    EXPECT_NEAR(dem::laws::lammps_tsuji_factor(*e_in), factor, 1e-14 * std::max(1.0, factor)) << e;
  }
  for (const double e : {1e-6, 0.1, 0.9999, 0.99999999}) {
    EXPECT_TRUE(reference::lammps::tsuji_input_for_factor(dem::laws::tsuji_factor(e)).has_value()) << e;
  }
}

TEST(LammpsTsujiInput, TsujiAtRestitutionOneIsNoDashpotAndBeyondTheOldRangeStillTsuji) {
  const auto undamped = map_pair_law(hertz_law("tsuji", "none", "none", 1.0), context());
  EXPECT_EQ(undamped.damping_style, "velocity");
  EXPECT_EQ(undamped.damping_coefficient, 0.0);
  const auto nearly = map_pair_law(hertz_law("tsuji", "none", "none", 0.9999), context());
  EXPECT_EQ(nearly.damping_style, "tsuji");
  EXPECT_GT(nearly.damping_coefficient, 1.0);
  const auto strong = map_pair_law(hertz_law("tsuji", "none", "none", 0.1), context());
  EXPECT_EQ(strong.damping_style, "tsuji");
  EXPECT_LT(strong.damping_coefficient, 0.0);
}

TEST(LammpsTsujiInput, CoreTsujiForRestitutionHalfNeedsEInFromLammpsNotes) {
  // α = √5 β(0.5) → e_in = 0.3666513616 (LAMMPS 29 Sep 2021 then rebounds at 0.49996).
  const double beta = -std::log(0.5) / std::sqrt(std::log(0.5) * std::log(0.5) + M_PI * M_PI);
  const auto e = reference::lammps::tsuji_input_for_factor(std::sqrt(5.0) * beta);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(*e, 0.3666513616, 1e-9);
}

TEST(LammpsTsujiInput, HertzTsujiAndRestitutionDampingMapToDampingTsuji) {
  const auto tsuji = map_pair_law(hertz_law("tsuji"), context());
  EXPECT_EQ(tsuji.damping_style, "tsuji");
  EXPECT_NEAR(tsuji.damping_coefficient, 0.3666513616, 1e-9);
  const auto restitution = map_pair_law(hertz_law("restitution"), context());
  EXPECT_EQ(restitution.damping_style, "tsuji");
  const double beta2 = dem::laws::restitution_damping_factor(0.5);
  EXPECT_NEAR(dem::laws::lammps_tsuji_factor(restitution.damping_coefficient),
              std::sqrt(1.5) * beta2, 1e-14);
}

TEST(LammpsWallMapping, AxisAlignedPlanesBecomeLoOrHiPlanes) {
  cases::WallSpec floor;
  floor.normal = {0.0, 0.0, 1.0};
  floor.point = {0.0, 0.0, 0.25};
  const auto plane = reference::lammps::wall_plane(floor);
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(reference::lammps::wall_plane_arguments(*plane), "zplane 0.25 NULL");
  EXPECT_EQ(reference::lammps::wall_distance_formula(*plane, 3), "(z[3]-0.25)");
  cases::WallSpec side;
  side.normal = {-1.0, 0.0, 0.0};
  side.point = {0.5, 0.0, 0.0};
  EXPECT_EQ(reference::lammps::wall_plane_arguments(*reference::lammps::wall_plane(side)),
            "xplane NULL 0.5");
}

TEST(LammpsWallMapping, TiltedOrMovingWallsAreNotMappedWithReasons) {
  cases::WallSpec tilted;
  tilted.name = "ramp";
  tilted.normal = {0.0, std::sqrt(0.5), std::sqrt(0.5)};
  tilted.velocity = {0.0, 0.0, 1.0};
  const auto reasons = reference::lammps::unmapped_wall(tilted, 2);
  ASSERT_EQ(reasons.size(), 2u);
  EXPECT_NE(reasons[0].find("xplane/yplane/zplane"), std::string::npos);
  EXPECT_NE(reasons[1].find("moves"), std::string::npos);
}

TEST(LammpsWallMapping, AMeshIsOneReasonForAllItsFacets) {
  cases::WallSpec facet;
  facet.name = "hopper.7";
  facet.shape = dem::WallShape::triangle;
  facet.mesh = 0;
  EXPECT_TRUE(reference::lammps::unmapped_wall(facet, 9).empty());  // left to the mesh's reason
  const cases::MeshSpec mesh{"hopper", "cone.stl", "", 512};
  const std::string reason = reference::lammps::unmapped_mesh(mesh);
  EXPECT_NE(reason.find("'hopper' is a triangle mesh (512 facets from cone.stl)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("no mesh wall"), std::string::npos) << reason;
}

TEST(LammpsPrescribedMotion, PiecewiseDisplacementClampsEachStretch) {
  const std::vector<cases::MotionSegmentSpec> motion{{0.18, {-1e-3, 0.0, 0.0}},
                                                     {0.0, {1e-3, 0.0, 0.0}}};
  EXPECT_EQ(reference::lammps::motion_displacement_formula(motion, 0),
            "-0.001*((time-0)*(time>0)*(time<0.17999999999999999)+0.17999999999999999*"
            "(time>=0.17999999999999999))+0.001*(time-0.17999999999999999)*"
            "(time>0.17999999999999999)");
  EXPECT_EQ(reference::lammps::motion_displacement_formula(motion, 1), "0");
  EXPECT_EQ(reference::lammps::motion_velocity_formula(motion, 0),
            "-0.001*(time>=0)*(time<0.17999999999999999)+0.001*(time>=0.17999999999999999)");
}

TEST(LammpsCanonicalDecks, ObliqueWallImpactHasAWallGranFixWithTheCoresEta) {
  const cases::Scene scene = canonical("oblique_wall_impact");
  reference::lammps::DeckSettings s;
  s.timestep = 1e-6;
  s.steps = 1000;
  const std::string deck = reference::lammps::write_deck(scene, s);
  EXPECT_NE(deck.find("wall/gran granular hooke 100000 "), std::string::npos) << deck;
  EXPECT_NE(deck.find("tangential linear_history 1000000 0 0.20000000000000001 damping velocity "
                      "zplane 0 NULL"),
            std::string::npos)
      << deck;
  EXPECT_LT(deck.find("fix             tr_pairforce"), deck.find("wall/gran"));
  EXPECT_LT(deck.find("wall/gran"), deck.find("fix             tr_contactforce"));
  const auto na = reference::lammps::inexpressible_metrics(scene);
  EXPECT_TRUE(na.contains("spin_after"));
  EXPECT_TRUE(na.contains("tangential_restitution"));
}

TEST(LammpsCanonicalDecks, JkrPulloffDrivesTheSphereWithFixMoveAndMarksRuptureMetrics) {
  const cases::Scene scene = canonical("jkr_pulloff");
  reference::lammps::DeckSettings s;
  s.timestep = 1e-5;
  s.steps = 44000;
  const std::string deck = reference::lammps::write_deck(scene, s);
  EXPECT_NE(deck.find("pair_coeff      1 1 jkr "), std::string::npos) << deck;
  EXPECT_NE(deck.find("fix             tr_move_1 tr_driven_1 move variable v_tr_dx_1"),
            std::string::npos)
      << deck;
  const auto na = reference::lammps::inexpressible_metrics(scene);
  EXPECT_TRUE(na.contains("rupture_separation"));
  EXPECT_FALSE(na.contains("pulloff_force"));
}

TEST(LammpsCanonicalDecks, HertzCollisionWritesHertzMaterialWithConvertedE) {
  const cases::Scene scene = canonical("hertz_collision");
  reference::lammps::DeckSettings s;
  s.timestep = 6.9e-6;
  s.steps = 145;
  const std::string deck = reference::lammps::write_deck(scene, s);
  EXPECT_NE(deck.find("pair_coeff      1 1 hertz/material 84000000"), std::string::npos)
      << deck;
}

}  // namespace
