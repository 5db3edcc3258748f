// SPDX-License-Identifier: MIT
// Sub-model translation to `pair_style granular` coefficients, and its registry wording.
#include <string>

#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/contact/registry.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"

namespace lammps_pair_coeff_test {

using reference::lammps::map_pair_law;
using reference::lammps::pair_coeff_arguments;

dem::PairLaw law(const std::string& damping, double restitution = 0.5, bool clamp = false) {
  dem::ModelChoice choice;
  choice.damping = damping;
  choice.clamp_tensile = clamp;
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.restitution = restitution;
  return dem::make_pair_law(choice, p);
}

TEST(LammpsPairCoeff, LinearSpringWithoutDampingIsHookeWithZeroEta) {
  const auto c = map_pair_law(law("none"), 4.2e-3);
  EXPECT_EQ(pair_coeff_arguments(c),
            "hooke 100000 0 tangential linear_nohistory 0 0 damping velocity");
}

TEST(LammpsPairCoeff, RestitutionDampingIsEtaOfEquation311ForTheGivenReducedMass) {
  const double m = 4.1887902047863905e-3;
  const auto c = map_pair_law(law("restitution", 0.5), m);
  EXPECT_EQ(c.damping_coefficient, dem::laws::restitution_damping_coefficient(0.5, m, 1e5));
  EXPECT_NEAR(c.damping_coefficient, 8.81918355790422, 1e-12);  // η of the LAMMPS runs
  EXPECT_EQ(c.damping_style, "velocity");
  EXPECT_NE(c.damping_note.find("m* = 0.0041887902047863905 kg"), std::string::npos);
}

TEST(LammpsPairCoeff, BothTypesFixedGetNoDamping) {
  const auto c = map_pair_law(law("restitution", 0.5), std::nullopt);
  EXPECT_EQ(c.damping_coefficient, 0.0);
}

TEST(LammpsPairCoeff, ClampTensileAddsLimitDamping) {
  const auto c = map_pair_law(law("restitution", 0.5, true), 1.0);
  EXPECT_NE(pair_coeff_arguments(c).find(" limit_damping "), std::string::npos);
}

TEST(LammpsPairCoeff, MindlinFormPicksTheSlipOrTheForceHistory) {
  // 'total' loads the whole slip at today's k_t (`mindlin`); 'incremental' adds each step's
  // −k_t(a) v_t Δt to a stored force (`mindlin/force`). Both pass k_t = 8 G* explicitly.
  dem::ModelChoice choice;
  choice.normal = "hertz";
  choice.damping = "tsuji";
  choice.tangential = "mindlin_8g";
  dem::PairProperties p;
  p.effective_modulus = 3.0e10;
  p.effective_shear_modulus = 7.0e9;
  p.restitution = 0.8;
  p.friction = 0.4;
  p.tangential_damping_ratio = 0.0;
  const auto args = [&](dem::MindlinForm form) {
    choice.mindlin_form = form;
    return pair_coeff_arguments(map_pair_law(dem::make_pair_law(choice, p), 1e-6));
  };
  EXPECT_NE(args(dem::MindlinForm::total).find(" tangential mindlin 56000000000 0 0.40000000000000002"),
            std::string::npos)
      << args(dem::MindlinForm::total);
  EXPECT_NE(args(dem::MindlinForm::incremental).find(" tangential mindlin/force 56000000000 0 0.40000000000000002"),
            std::string::npos)
      << args(dem::MindlinForm::incremental);
}

TEST(LammpsPairCoeff, EveryCurrentSubModelIsMapped) {
  EXPECT_TRUE(reference::lammps::unmapped_sub_models(law("none")).empty());
  EXPECT_TRUE(reference::lammps::unmapped_sub_models(law("restitution")).empty());
}

TEST(LammpsPairCoeff, RegistryRowsNameTheKeywordsTheDriverWrites) {
  // The registry is the one place that says how a sub-model maps; keep it true to the writer.
  const auto lammps_text = [](dem::Slot slot, const char* keyword) {
    const dem::SubModelInfo* row = dem::find_sub_model(slot, keyword);
    return row == nullptr ? std::string() : std::string(row->lammps);
  };
  EXPECT_NE(lammps_text(dem::Slot::normal, "linear").find("hooke"), std::string::npos);
  EXPECT_NE(lammps_text(dem::Slot::damping, "none").find("damping velocity"), std::string::npos);
  EXPECT_NE(lammps_text(dem::Slot::damping, "restitution").find("damping velocity"),
            std::string::npos);
  EXPECT_NE(lammps_text(dem::Slot::tangential, "none").find("linear_nohistory 0 0"),
            std::string::npos);
}

}  // namespace
