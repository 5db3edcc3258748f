// SPDX-License-Identifier: MIT
// The LIGGGHTS driver's pure parts (no LIGGGHTS needed): atom types with the walls' types after the
// particles', the contact model as property tables (values and every refusal), the deck with its
// primitive and mesh walls, the thermo table read back, the banner.
#include <cmath>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/particles/particles.hpp"
#include "reference/common/prepared_scene.hpp"
#include "reference/liggghts/atom_types.hpp"
#include "reference/liggghts/contact_mapping.hpp"
#include "reference/liggghts/deck_parts.hpp"
#include "reference/liggghts/deck_writer.hpp"
#include "reference/liggghts/liggghts_engine.hpp"
#include "reference/liggghts/liggghts_runner.hpp"
#include "reference/liggghts/primitive_walls.hpp"
#include "reference/liggghts/trace_columns.hpp"
#include "support/text_file.hpp"

namespace liggghts_driver_test {

using namespace reference::liggghts;

/// A two-sphere case with a floor: [model] lines, the two materials' extra keys, and whether
/// the second sphere is frozen.
std::string case_text(const std::string& model, const std::string& steel, const std::string& glass,
                      bool frozen = false, const std::string& wall = "material = \"glass\"") {
  return fmt::format(R"([case]
name = "two"
[model]
{0}
[materials.steel]
density = 7800.0
{1}
[materials.glass]
density = 2500.0
{2}
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, -0.01]
normal = [0.0, 0.0, 1.0]
{4}
[[particles]]
radius = 0.002
material = "steel"
position = [0.0, 0.0, 0.0]
velocity = [0.5, 0.0, -0.1]
[[particles]]
radius = 0.003
material = "glass"
position = [0.0051, 0.0, 0.0]
fixed = {3}
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-6
duration = 1.0e-4
[output]
trace_every = 10
trace_particles = [0, 1]
trace_pairs = [[0, 1]]
trace_walls = [[0, 0]]
)",
                     model, steel, glass, frozen ? "true" : "false", wall);
}

const std::string kHertzModel = "normal = \"hertz\"\ndamping = \"tsuji\"\ntangential = \"mindlin_8g\"";
const std::string kSteel = "youngs_modulus = 2.0e8\npoisson_ratio = 0.29\nrestitution = 0.8\nfriction = 0.3\n";
const std::string kGlass = "youngs_modulus = 6.0e7\npoisson_ratio = 0.23\nrestitution = 0.8\nfriction = 0.3\n";

cases::Scene scene_of(const std::string& text) { return cases::load_case_text(text, "two.toml"); }

ContactMapping mapping_of(const cases::Scene& scene) {
  const reference::PreparedScene prepared(scene);
  return map_contacts(scene, prepared.pair_table(), classify(scene));
}

/// The case's tangential_damping_ratio line for both materials.
std::string with_ratio(const std::string& material, double ratio) {
  return material + fmt::format("tangential_damping_ratio = {:.17g}\n", ratio);
}

TEST(LiggghtsAtomTypes, WallMaterialsFollowTheParticleClassesAndMassesMixAsPairGranDoes) {
  const cases::Scene scene = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0), true));
  const AtomTypes types = classify(scene);
  ASSERT_EQ(types.particles.size(), 2u);
  ASSERT_EQ(types.wall_materials.size(), 1u);
  EXPECT_EQ(types.count(), 3u);
  EXPECT_EQ(types.wall_type(0), 3u);
  EXPECT_EQ(types.material_of(3), types.particles[1].material);  // the floor is glass, like sphere 1
  const double m0 = dem::sphere_mass(7800.0, 0.002);
  EXPECT_EQ(*types.reduced_mass(1, 1), m0 * m0 / (m0 + m0));
  EXPECT_EQ(*types.reduced_mass(1, 2), m0);  // against the frozen sphere: the mobile mass
  EXPECT_EQ(*types.reduced_mass(3, 1), m0);  // against a wall: the sphere's mass
  EXPECT_FALSE(types.reduced_mass(2, 3).has_value());  // a frozen sphere and a wall never meet
}

TEST(LiggghtsMixing, EffectiveModuliAreTheCoresForEveryPairOfMaterials) {
  // LIGGGHTS mixes Y* and G* from per-type E and ν; the core's pair table must hold the same
  // numbers, or the driver could not write E and ν at all.
  for (const double nu_a : {0.0, 0.2, 0.35, 0.49}) {
    for (const double nu_b : {0.1, 0.3, 0.45}) {
      const cases::Scene scene = scene_of(case_text(
          kHertzModel, fmt::format("youngs_modulus = 3.0e8\npoisson_ratio = {}\nrestitution = 0.8\nfriction = 0.3\n"
                                   "tangential_damping_ratio = 0.0\n", nu_a),
          fmt::format("youngs_modulus = 7.0e7\npoisson_ratio = {}\nrestitution = 0.8\nfriction = 0.3\n"
                      "tangential_damping_ratio = 0.0\n", nu_b)));
      const reference::PreparedScene prepared(scene);
      const dem::PairProperties& pair = prepared.pair_table().properties(0, 1);
      EXPECT_NEAR(liggghts_effective_modulus(3.0e8, nu_a, 7.0e7, nu_b), *pair.effective_modulus,
                  1e-14 * *pair.effective_modulus);
      EXPECT_NEAR(liggghts_effective_shear_modulus(3.0e8, nu_a, 7.0e7, nu_b), *pair.effective_shear_modulus,
                  1e-14 * *pair.effective_shear_modulus);
    }
  }
}

TEST(LiggghtsContactMapping, HertzWritesEAndNuPerTypeAndTheRestitutionPerTypePair) {
  const cases::Scene scene = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)));
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.reasons.empty()) << m.reasons.front();
  const ContactSettings& s = *m.settings;
  EXPECT_EQ(s.normal, "hertz");
  EXPECT_EQ(s.tangential, "history");
  EXPECT_EQ(s.youngs_modulus, (std::vector<double>{2.0e8, 6.0e7, 6.0e7}));
  EXPECT_EQ(s.poisson_ratio, (std::vector<double>{0.29, 0.23, 0.23}));
  EXPECT_EQ(s.restitution[0 * 3 + 1], 0.8);
  EXPECT_EQ(s.restitution[1 * 3 + 0], 0.8);
  EXPECT_EQ(s.friction[0 * 3 + 2], 0.3);
  EXPECT_FALSE(s.hard_particles);
  // A zero tangential dashpot switches LIGGGHTS' off.
  EXPECT_NE(std::find(s.options.begin(), s.options.end(), "tangential_damping off"), s.options.end());
}

TEST(LiggghtsContactMapping, TheHertzTangentialDashpotMustBeLiggghtsOwnOrNone) {
  const cases::Scene plain = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)));
  const reference::PreparedScene prepared(plain);
  // LIGGGHTS: γ_t / γ_n = √(8 G* / (2 Y*)) = 2 √(G*/E*), one number per material pair.
  const dem::PairProperties& steel = prepared.pair_table().properties(0, 0);
  const double implied = 2.0 * std::sqrt(*steel.effective_shear_modulus / *steel.effective_modulus);
  // Steel alone (both spheres and the wall steel): its own ratio maps, the dashpot stays on.
  const std::string steel_only = case_text(kHertzModel, with_ratio(kSteel, implied), with_ratio(kGlass, 0.0), false,
                                           "material = \"steel\"");
  std::string two_steel = steel_only;
  two_steel.replace(two_steel.rfind("material = \"glass\""), 18, "material = \"steel\"");
  const ContactMapping own = mapping_of(scene_of(two_steel));
  ASSERT_TRUE(own.reasons.empty()) << own.reasons.front();
  EXPECT_EQ(std::find(own.settings->options.begin(), own.settings->options.end(), "tangential_damping off"),
            own.settings->options.end());
  // Any other ratio is refused, naming LIGGGHTS' value.
  std::string other = two_steel;
  other.replace(other.find(fmt::format("tangential_damping_ratio = {:.17g}", implied)),
                fmt::format("tangential_damping_ratio = {:.17g}", implied).size(), "tangential_damping_ratio = 0.5");
  const ContactMapping refused = mapping_of(scene_of(other));
  ASSERT_FALSE(refused.reasons.empty());
  EXPECT_NE(refused.reasons.front().find("2 √(G*/E*)"), std::string::npos) << refused.reasons.front();
  EXPECT_FALSE(refused.settings.has_value());
}

TEST(LiggghtsContactMapping, TheLinearSpringTakesTheCoresDashpotPerTypePair) {
  const std::string model = "normal = \"linear\"\ndamping = \"restitution\"\ntangential = \"spring_coulomb\"";
  const std::string keys = "normal_stiffness = 4.0e4\nrestitution = 0.6\ntangential_stiffness = 2.0e4\n"
                           "friction = 0.4\ntangential_damping_ratio = 0.25\n";
  const cases::Scene scene = scene_of(case_text(model, keys, keys, true));
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.reasons.empty()) << m.reasons.front();
  const ContactSettings& s = *m.settings;
  EXPECT_EQ(s.normal, "hooke/stiffness");
  EXPECT_NE(std::find(s.options.begin(), s.options.end(), "absolute_damping on"), s.options.end());
  const AtomTypes types = classify(scene);
  const double beta = dem::laws::restitution_damping_factor(0.6);
  for (const auto& [a, b] : {std::pair<std::size_t, std::size_t>{1, 1}, {1, 2}, {1, 3}}) {
    const std::size_t k = (a - 1) * 3 + (b - 1);
    EXPECT_EQ(s.kn[k], 4.0e4);
    EXPECT_EQ(s.kt[k], 2.0e4);
    EXPECT_EQ(s.gamman[k], beta * std::sqrt(*types.reduced_mass(a, b) * 4.0e4)) << a << "-" << b;
    EXPECT_EQ(s.gammat[k], 0.25 * s.gamman[k]);
  }
  EXPECT_EQ(s.gamman[1 * 3 + 2], 0.0);  // frozen sphere against the wall: they never meet
}

TEST(LiggghtsContactMapping, EveryInexpressibleChoiceIsRefusedWithItsReason) {
  const std::string keys0 = with_ratio(kSteel, 0.0);
  const std::string keys1 = with_ratio(kGlass, 0.0);
  const auto reasons = [&](const std::string& model, const std::string& a = "", const std::string& b = "") {
    return mapping_of(scene_of(case_text(model, keys0 + a, keys1 + b))).reasons;
  };
  const auto says = [](const std::vector<std::string>& r, const std::string& what) {
    for (const auto& x : r) {
      if (x.find(what) != std::string::npos) return true;
    }
    return false;
  };
  EXPECT_TRUE(says(reasons(kHertzModel + "\ncohesion = \"jkr\"", "surface_energy = 0.1\n", "surface_energy = 0.1\n"),
                   "cohesion = 'jkr'"));
  EXPECT_TRUE(says(reasons(kHertzModel + "\nmindlin_form = \"incremental\""), "mindlin_form"));
  EXPECT_TRUE(says(reasons(kHertzModel + "\npair_lever_arm = \"radius\""), "pair_lever_arm"));
  EXPECT_TRUE(says(reasons(kHertzModel + "\nwall_lever_arm = \"radius\""), "wall_lever_arm"));
  EXPECT_TRUE(says(reasons("normal = \"hertz\"\ndamping = \"restitution\""), "√(6/5)"));
  EXPECT_TRUE(says(reasons("normal = \"hertz\"\ntangential = \"spring_coulomb\"", "tangential_stiffness = 1e4\n",
                           "tangential_stiffness = 1e4\n"),
                   "not expressible"));
  EXPECT_TRUE(says(reasons("normal = \"linear\"\ndamping = \"tsuji\"", "normal_stiffness = 1e4\n",
                           "normal_stiffness = 1e4\n"),
                   "tsuji"));
  EXPECT_TRUE(says(reasons(kHertzModel + "\nrolling = \"spring_dashpot_slider\"",
                           "rolling_friction = 0.1\nrolling_stiffness = 10.0\nrolling_damping = 0.0\n",
                           "rolling_friction = 0.1\nrolling_stiffness = 10.0\nrolling_damping = 0.0\n"),
                   "epsd2"));
  // A [[pairs]] override of E* is not what LIGGGHTS mixes from E and ν.
  const std::string overridden = case_text(kHertzModel, keys0, keys1) +
                                 "[[pairs]]\nmaterials = [\"steel\", \"glass\"]\neffective_modulus = 1.0e7\n";
  EXPECT_TRUE(says(mapping_of(scene_of(overridden)).reasons, "E* = 1e+07 Pa"));
}

TEST(LiggghtsContactMapping, TheConstantRollingTorqueIsCdtWithItsCoefficientPerTypePair) {
  const cases::Scene scene = scene_of(case_text(kHertzModel + "\nrolling = \"constant_torque\"",
                                                with_ratio(kSteel, 0.0) + "rolling_friction = 0.05\n",
                                                with_ratio(kGlass, 0.0) + "rolling_friction = 0.02\n"));
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.reasons.empty()) << m.reasons.front();
  EXPECT_EQ(m.settings->rolling, "cdt");
  // Types: steel, glass, the floor (glass); μ_r mixed by the core's rule (min) per type pair.
  const std::vector<double>& mu = m.settings->rolling_friction;
  ASSERT_EQ(mu.size(), 9U);
  EXPECT_EQ(mu[0], 0.05);  // steel–steel
  EXPECT_EQ(mu[1], 0.02);  // steel–glass
  EXPECT_EQ(mu[3], 0.02);  // glass–steel
  EXPECT_EQ(mu[2], 0.02);  // steel–floor
  const AtomTypes types = classify(scene);
  const std::string deck = write_deck(scene, types, *m.settings, trace_plan(scene, types), DeckSettings{1e-6, 100});
  EXPECT_NE(deck.find("gran model hertz tangential history rolling_friction cdt tangential_damping off\n"),
            std::string::npos)
      << deck;
  EXPECT_NE(deck.find("wall/gran model hertz tangential history rolling_friction cdt primitive"), std::string::npos)
      << deck;
  EXPECT_NE(deck.find("property/global coefficientRollingFriction peratomtypepair 3 0.050000000000000003 0.02"),
            std::string::npos)
      << deck;
  // Without rolling resistance the deck names neither.
  const cases::Scene plain = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)));
  const ContactMapping p = mapping_of(plain);
  ASSERT_TRUE(p.reasons.empty());
  const AtomTypes plain_types = classify(plain);
  const std::string plain_deck =
      write_deck(plain, plain_types, *p.settings, trace_plan(plain, plain_types), DeckSettings{1e-6, 100});
  EXPECT_EQ(plain_deck.find("rolling"), std::string::npos);
}

TEST(LiggghtsContactMapping, HertzWithTheViscoelasticDashpotIsHertzStiffnessWithTheCoresPairValues) {
  const std::string model = "normal = \"hertz\"\ndamping = \"lammps_viscoelastic\"\ntangential = \"mindlin_8g\"";
  const std::string steel = with_ratio(kSteel, 0.4) + "viscoelastic_damping = 500.0\n";
  const std::string glass = with_ratio(kGlass, 0.0) + "viscoelastic_damping = 200.0\n";
  // A [[pairs]] override of E* maps too: the table is the core's pair values, not LIGGGHTS' mixing.
  const std::string text = case_text(model, steel, glass) +
                           "[[pairs]]\nmaterials = [\"steel\", \"glass\"]\neffective_modulus = 1.0e7\n";
  const cases::Scene scene = scene_of(text);
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.reasons.empty()) << m.reasons.front();
  EXPECT_EQ(m.settings->normal, "hertz/stiffness");
  const reference::PreparedScene prepared(scene);
  const dem::PairLaw& sg = prepared.pair_table().law(0, 1);
  const auto& hertz = std::get<dem::HertzNormal>(sg.normal);
  EXPECT_EQ(hertz.effective_modulus, 1.0e7);
  // Types: steel 1, glass 2, the floor (glass) 3; steel–glass is entry 1.
  EXPECT_DOUBLE_EQ(m.settings->kn[1], 13333333.333333334);  // 4/3 E* for the overridden E* = 1e7 Pa
  // 8 G*, G* from LIGGGHTS' own mixing of the two materials' E and ν (not the core's value)
  EXPECT_NEAR(m.settings->kt[1], 8.0 * liggghts_effective_shear_modulus(2.0e8, 0.29, 6.0e7, 0.23),
              1e-12 * m.settings->kt[1]);
  EXPECT_EQ(m.settings->gamman[1], std::get<dem::LammpsViscoelasticDamping>(sg.damping).rate_per_length);
  EXPECT_EQ(m.settings->gammat[0], 0.4 * 500.0);  // steel–steel: the ratio times η₀
  const AtomTypes types = classify(scene);
  const std::string deck = write_deck(scene, types, *m.settings, trace_plan(scene, types), DeckSettings{1e-6, 100});
  EXPECT_NE(deck.find("gran model hertz/stiffness tangential history"), std::string::npos) << deck;
  for (const char* property : {"property/global kn ", "property/global kt ", "property/global gamman ",
                               "property/global gammat "}) {
    EXPECT_NE(deck.find(property), std::string::npos) << property << "\n" << deck;
  }
  EXPECT_EQ(deck.find("youngsModulus"), std::string::npos);
  EXPECT_EQ(deck.find("absolute_damping"), std::string::npos);
  // On a linear spring the viscoelastic dashpot has no counterpart.
  const ContactMapping linear = mapping_of(scene_of(case_text(
      "normal = \"linear\"\ndamping = \"lammps_viscoelastic\"", "normal_stiffness = 1e4\nviscoelastic_damping = 5.0\n",
      "normal_stiffness = 1e4\nviscoelastic_damping = 5.0\n")));
  ASSERT_FALSE(linear.reasons.empty());
  EXPECT_NE(linear.reasons[0].find("lammps_viscoelastic"), std::string::npos) << linear.reasons[0];
}

TEST(LiggghtsContactMapping, ARigidWallIsATypeOfEnormousModulus) {
  const cases::Scene scene = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0), false,
                                                "material = \"glass\"\nrigid = true"));
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.reasons.empty()) << m.reasons.front();
  EXPECT_EQ(m.settings->youngs_modulus.back(), kRigidYoungsModulus);
  EXPECT_TRUE(m.settings->hard_particles);
  // LIGGGHTS' mix with it is the particle's E/(1 − ν²) to the last bits.
  const double mixed = liggghts_effective_modulus(2.0e8, 0.29, kRigidYoungsModulus, 0.23);
  EXPECT_NEAR(mixed, 2.0e8 / (1.0 - 0.29 * 0.29), 1e-15 * mixed);
}

TEST(LiggghtsDeck, WritesWhatThisLiggghtsAcceptsInFullPrecision) {
  const cases::Scene scene =
      scene_of(case_text(kHertzModel + "\nclamp_tensile = true", with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0), true));
  const AtomTypes types = classify(scene);
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.settings.has_value());
  const TracePlan plan = trace_plan(scene, types);
  DeckSettings settings;
  settings.timestep = 1e-6;
  settings.steps = 100;
  const std::string deck = write_deck(scene, types, *m.settings, plan, settings);
  // Values in full: the floor sits 17 significant digits deep, and the sphere's start velocity.
  EXPECT_NE(deck.find("zplane -0.01 "), std::string::npos);
  EXPECT_NE(deck.find("set             atom 1 vx 0.5 vy 0 vz -0.10000000000000001 "), std::string::npos) << deck;
  EXPECT_NE(deck.find("neigh_modify    exclude group tr_fixed tr_fixed"), std::string::npos);
  EXPECT_NE(deck.find("fix             tr_wall_0 tr_mobile wall/gran"), std::string::npos);
  for (const char* wanted :
       {"communicate     single vel yes", "newton          off", "create_box      3 tr_box",
        "pair_style      gran model hertz tangential history limitForce on tangential_damping off",
        "contact_distance_factor 1.1", "fix             tr_pair_force all store/force",
        "primitive type 3 zplane -0.01 store_force yes limitForce on tangential_damping off",
        "fix             tr_freeze tr_fixed freeze", "thermo_modify   format float %.17g norm no lost error",
        "thermo          10", "run             100"}) {
    EXPECT_NE(deck.find(wanted), std::string::npos) << wanted << "\n" << deck;
  }
  // Modern LAMMPS syntax this LIGGGHTS refuses, and v_ references (15 digits) inside formulas.
  EXPECT_EQ(deck.find("comm_modify"), std::string::npos);
  EXPECT_EQ(deck.find("pair_style      granular"), std::string::npos);
  for (const TraceColumn& c : plan.columns) EXPECT_EQ(c.formula.find("v_"), std::string::npos) << c.name;
  // The columns are the trace's, in its order, then whether the pair's fn is its own (a wall
  // makes three bodies).
  const cases::Trace layout = cases::trace_layout(scene);
  ASSERT_EQ(plan.columns.size(), layout.columns().size() + 1);
  for (std::size_t k = 0; k < layout.columns().size(); ++k) EXPECT_EQ(plan.columns[k].name, layout.columns()[k]);
  EXPECT_EQ(plan.columns.back().name, exact_column(0, 1));
  // The frozen sphere's force is its stored contact force (fix freeze zeroes fx).
  EXPECT_EQ(plan.columns[1 + 12 + 9].formula, "f_tr_pair_force[2][1]");
}

TEST(LiggghtsDeck, TheTimingDeckIsTheReferenceDeckWithoutItsOutputs) {
  // `demwb bench`: the same atoms, model, walls and integration, the skin it is given, and none
  // of the stored forces, trace columns or snapshots the reference run reads back.
  const cases::Scene scene =
      scene_of(case_text(kHertzModel + "\nclamp_tensile = true", with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0), true));
  const reference::PreparedScene prepared(scene);
  const TimingDeck t = timing_deck(prepared, 1e-6, 100, 3e-4);
  ASSERT_TRUE(t.reasons.empty()) << t.reasons.front();
  EXPECT_TRUE(t.data.empty());  // two spheres: atoms inline
  for (const char* wanted :
       {"pair_style      gran model hertz tangential history limitForce on tangential_damping off",
        "neighbor        0.00029999999999999997 bin", "contact_distance_factor 1.1",
        "primitive type 3 zplane -0.01 limitForce on tangential_damping off", "fix             tr_freeze tr_fixed freeze",
        "thermo_modify   lost error", "thermo          100", "run             100", "create_atoms    1 single 0 0 0"}) {
    EXPECT_NE(t.deck.find(wanted), std::string::npos) << wanted << "\n" << t.deck;
  }
  for (const char* absent : {"store/force", "store_force", "variable", "thermo_style", "dump"}) {
    EXPECT_EQ(t.deck.find(absent), std::string::npos) << absent << "\n" << t.deck;
  }
  // A scene LIGGGHTS cannot express: reasons and no deck.
  const cases::Scene jkr = scene_of(case_text("normal = \"hertz\"\ndamping = \"tsuji\"\ntangential = \"mindlin_8g\"\n"
                                              "cohesion = \"jkr\"",
                                              with_ratio(kSteel, 0.0) + "surface_energy = 0.1\n",
                                              with_ratio(kGlass, 0.0) + "surface_energy = 0.1\n"));
  const TimingDeck refused = timing_deck(reference::PreparedScene(jkr), 1e-6, 100, 3e-4);
  ASSERT_FALSE(refused.reasons.empty());
  EXPECT_TRUE(refused.deck.empty());
  EXPECT_NE(refused.reasons.front().find("cohesion"), std::string::npos) << refused.reasons.front();
}

TEST(LiggghtsDeck, ManySpheresOfManySizesComeFromADataFileWithDiametersPerAtom) {
  // 120 mobile spheres of 20 radii and one frozen: more than 100 atoms, more than 16 classes.
  std::string text = case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0), true);
  for (int k = 0; k < 120; ++k) {
    text += fmt::format("[[particles]]\nradius = {:.17g}\nmaterial = \"steel\"\nposition = [{:.17g}, 0.05, 0.0]\n"
                        "velocity = [0.0, 0.0, -0.1]\n",
                        0.001 + 1e-5 * (k % 20), 0.01 * k);
  }
  const cases::Scene scene = scene_of(text);
  const AtomTypes types = classify(scene);
  ASSERT_TRUE(types.per_atom_diameter);
  ASSERT_EQ(types.particles.size(), 2u);  // (steel, mobile), (glass, frozen)
  ASSERT_TRUE(atoms_in_data_file(scene, types));
  const ContactMapping m = mapping_of(scene);
  ASSERT_TRUE(m.settings.has_value()) << m.reasons.front();
  DeckSettings settings;
  settings.timestep = 1e-6;
  settings.steps = 10;
  const std::string deck = write_deck(scene, types, *m.settings, trace_plan(scene, types), settings);
  EXPECT_NE(deck.find("read_data       atoms.data"), std::string::npos);
  EXPECT_EQ(deck.find("create_atoms"), std::string::npos);
  const std::string data = write_atom_data(scene, types, settings);
  EXPECT_NE(data.find("122 atoms\n3 atom types\n"), std::string::npos);
  // Atom k + 1: its type, diameter, density and position exactly; the frozen sphere does not move.
  EXPECT_NE(data.find("\n3 1 0.002 7800 0 0.050000000000000003 0\n"), std::string::npos) << data.substr(0, 600);
  const double r119 = 0.001 + 1e-5 * 19;  // the last sphere, as the case gives it
  EXPECT_NE(data.find(fmt::format("\n122 1 {:.17g} 7800 {:.17g} 0.050000000000000003 0\n", 2.0 * r119, 0.01 * 119)),
            std::string::npos);
  EXPECT_NE(data.find("\n2 0 0 0 0 0 0\n"), std::string::npos);
  EXPECT_NE(data.find("\n3 0 0 -0.10000000000000001 0 0 0\n"), std::string::npos);
  // A dashpot in kg/s per type pair cannot be written when m* varies within a type.
  const std::string linear = "normal = \"linear\"\ndamping = \"restitution\"";
  std::string many_linear = text;
  many_linear.replace(many_linear.find(kHertzModel), kHertzModel.size(), linear);
  for (const char* key : {"steel", "glass"}) {
    many_linear.replace(many_linear.find(fmt::format("[materials.{}]\n", key)), std::string(key).size() + 13,
                        fmt::format("[materials.{}]\nnormal_stiffness = 1e4\n", key));
  }
  const ContactMapping refused = mapping_of(scene_of(many_linear));
  ASSERT_FALSE(refused.reasons.empty());
  EXPECT_NE(refused.reasons.front().find("one m* per type pair"), std::string::npos) << refused.reasons.front();
}

/// A log holding a thermo table of `plan`'s columns at steps 0, 10, …, `last`.
std::string thermo_log(std::size_t columns, std::uint64_t last, std::uint64_t every, const std::string& extra = "") {
  std::string log = "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled …)\nSetting up run\n    Step";
  for (std::size_t k = 0; k < columns; ++k) log += " " + column_variable(k);
  log += "\n";
  for (std::uint64_t s = 0; s <= last; s += every) {
    log += fmt::format("{:>8}", s);
    for (std::size_t k = 0; k < columns; ++k) log += fmt::format(" {:.17g}", 0.1 * static_cast<double>(s + k));
    log += "\n";
    if (s == 10) log += extra;
  }
  return log + "Loop time of 0.01 on 1 procs for 100 steps with 2 atoms\n";
}

TEST(LiggghtsThermo, ReadsTheTableAndRefusesAShortOrDamagedOne) {
  const cases::Scene scene = scene_of(case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)));
  const TracePlan plan = trace_plan(scene, classify(scene));
  const std::size_t n = plan.columns.size();
  const cases::Trace t =
      trace_from_thermo(scene, plan, thermo_log(n, 100, 10, "WARNING: a warning between rows\n"), "log", 100);
  ASSERT_EQ(t.rows(), 11u);
  EXPECT_EQ(t.columns().front(), "time");
  EXPECT_EQ(t.values(3)[2], 0.1 * (20 + 3));
  // LIGGGHTS prints the last step even off the output grid: that row is not the trace's.
  std::string off_grid = thermo_log(n, 100, 10);
  std::string closing = fmt::format("{:>8}", 105);
  for (std::size_t k = 0; k < n; ++k) closing += " 1";
  off_grid.insert(off_grid.find("Loop time"), closing + "\n");
  EXPECT_EQ(trace_from_thermo(scene, plan, off_grid, "log", 105).rows(), 11u);
  const auto error_of = [&](const std::string& log, std::uint64_t steps) {
    try {
      (void)trace_from_thermo(scene, plan, log, "log.liggghts", steps);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(thermo_log(n, 50, 10), 100).find("rows; expected 11"), std::string::npos);
  // The closing row twice, an on-grid row missing, or a closing row where none belongs: refused.
  std::string twice = off_grid;
  twice.insert(twice.find("Loop time"), closing + "\n");
  EXPECT_NE(error_of(twice, 105).find("expected no more rows"), std::string::npos) << error_of(twice, 105);
  std::string gap = thermo_log(n, 100, 10);
  const std::size_t row40 = gap.find("\n      40 ") + 1;
  gap.erase(row40, gap.find('\n', row40) + 1 - row40);
  EXPECT_NE(error_of(gap, 100).find("thermo row at step 50; expected step 40"), std::string::npos) << error_of(gap, 100);
  EXPECT_NE(error_of(off_grid, 100).find("expected no more rows"), std::string::npos);
  EXPECT_NE(error_of("no table here\n", 100).find("no thermo table"), std::string::npos);
  std::string damaged = thermo_log(n, 100, 10);
  const std::size_t row20 = damaged.find("\n      20 ") + 10;  // the row of step 20, its first value
  damaged.replace(row20, damaged.find(' ', row20) - row20, "2.0x");
  EXPECT_NE(error_of(damaged, 100).find("is not a number"), std::string::npos) << error_of(damaged, 100);
  std::string cut = thermo_log(n, 100, 10);
  const std::size_t row30 = cut.find("\n      30 ") + 1;
  cut.erase(cut.rfind(' ', cut.find('\n', row30)), cut.find('\n', row30) - cut.rfind(' ', cut.find('\n', row30)));
  EXPECT_NE(error_of(cut, 100).find("values; expected"), std::string::npos) << error_of(cut, 100);
}

TEST(LiggghtsWalls, AnAxisAlignedCylinderIsAPrimitiveWithItsCentreInLiggghtsOrder) {
  cases::WallSpec barrel;
  barrel.name = "barrel";
  barrel.shape = dem::WallShape::frustum;
  barrel.point = {0.001, 0.002, 0.003};
  barrel.size_u = barrel.size_v = 0.01;
  barrel.length = 0.04;
  // Axis z: centre (x, y); axis y: (z, x); axis x: (y, z) — primitive_wall_definitions.h Dim<dim>.
  barrel.normal = {0.0, 0.0, 1.0};
  EXPECT_EQ(primitive_arguments(barrel), "zcylinder 0.01 0.001 0.002");
  barrel.normal = {0.0, -1.0, 0.0};
  EXPECT_EQ(primitive_arguments(barrel), "ycylinder 0.01 0.0030000000000000001 0.001");
  const std::optional<WallCylinder> down = wall_cylinder(barrel);
  ASSERT_TRUE(down.has_value());
  EXPECT_DOUBLE_EQ(down->low, 0.002 - 0.04);  // the axis points from the base towards the other end
  EXPECT_DOUBLE_EQ(down->high, 0.002);
  barrel.normal = {1.0, 0.0, 0.0};
  EXPECT_EQ(primitive_arguments(barrel), "xcylinder 0.01 0.002 0.0030000000000000001");
  EXPECT_TRUE(unmapped_wall(barrel, 0).empty());
  barrel.normal = {0.6, 0.8, 0.0};
  EXPECT_TRUE(primitive_arguments(barrel).empty());
  EXPECT_NE(unmapped_wall(barrel, 0).at(0).find("tilted: a primitive cylinder"), std::string::npos);
  barrel.normal = {0.0, 0.0, 1.0};
  barrel.size_v = 0.005;  // a cone
  EXPECT_TRUE(primitive_arguments(barrel).empty());
  EXPECT_NE(unmapped_wall(barrel, 0).at(0).find("is a cone: only plane and cylinder walls"), std::string::npos);
}

TEST(LiggghtsWalls, ASphereStartingBeyondACylindersEndOnItsExtendedSurfaceIsNotApplicable) {
  // LIGGGHTS' primitive cylinder has no ends: a sphere below a barrel whose extended surface it
  // touches would be pushed there, the core's barrel ends at its base.
  const std::string barrel = R"([[walls]]
type = "cylinder"
name = "barrel"
base = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
radius = 0.00809
height = 0.02
material = "glass"
)";
  std::string text = case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)) + barrel;
  // Sphere 1 (r 3 mm, centre x = 5.1 mm) touches the barrel (R 8.09 mm) from inside, within its height.
  EXPECT_TRUE(cylinder_end_reasons(scene_of(text), 1).empty());
  const std::string at_zero = "position = [0.0051, 0.0, 0.0]";
  text.replace(text.find(at_zero), at_zero.size(), "position = [0.0051, 0.0, -0.001]");
  const std::vector<std::string> reasons = cylinder_end_reasons(scene_of(text), 1);
  ASSERT_EQ(reasons.size(), 1U);
  EXPECT_NE(reasons[0].find("particle 1 starts beyond an end of cylinder wall 1 ('barrel')"), std::string::npos)
      << reasons[0];
  // A traced contact with a cylinder has no overlap formula here.
  std::string traced = case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0)) + barrel;
  traced.replace(traced.find("trace_walls = [[0, 0]]"), 22, "trace_walls = [[0, 1]]");
  const reference::Support s = reference::LiggghtsEngine{}.supports(scene_of(traced));
  EXPECT_NE(s.explain().find("only a plane wall's overlap and force are traced"), std::string::npos) << s.explain();
}

TEST(LiggghtsWalls, MeshesAreWrittenAsStlFilesAndHeldByOneWallFix) {
  // Two meshes: one fix mesh/surface each, one fix wall/gran holding both (LIGGGHTS 3.8 refuses a
  // second wall/gran of type mesh), the files' corners in the scene's coordinates to 17 digits,
  // and a box that holds every corner.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-liggghts-driver-mesh";
  std::filesystem::create_directories(dir);
  support::write_file(dir / "tri.stl", "solid t\n facet normal 0 0 0\n  outer loop\n   vertex 0 0 0\n"
                                       "   vertex 10 0 0\n   vertex 0 10 0\n  endloop\n endfacet\nendsolid t\n");
  std::string text = case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0));
  text += "[[walls]]\ntype = \"mesh\"\nname = \"a\"\nfile = \"tri.stl\"\nscale = 1.0e-3\n"
          "translate = [0.0, 0.0, -0.005]\nmaterial = \"glass\"\n"
          "[[walls]]\ntype = \"mesh\"\nname = \"b\"\nfile = \"tri.stl\"\nscale = 1.0e-3\n"
          "translate = [0.0, 0.0, 0.03]\nmaterial = \"steel\"\n";
  support::write_file(dir / "meshes.toml", text);
  const cases::Scene scene = cases::load_case(dir / "meshes.toml");
  ASSERT_EQ(scene.meshes.size(), 2U);
  const reference::PreparedScene prepared(scene);
  const DeckParts parts = deck_parts(prepared);
  ASSERT_TRUE(parts.reasons.empty()) << parts.reasons.front();
  DeckSettings settings{1e-6, 100};
  const std::string deck = write_deck(scene, parts.types, *parts.contacts, trace_plan(scene, parts.types), settings);
  EXPECT_NE(deck.find("tr_mesh_0 all mesh/surface file mesh_0.stl type 3"), std::string::npos) << deck;
  EXPECT_NE(deck.find("tr_mesh_1 all mesh/surface file mesh_1.stl type 4"), std::string::npos) << deck;
  EXPECT_NE(deck.find("wall/gran model hertz tangential history mesh n_meshes 2 meshes tr_mesh_0 tr_mesh_1 "
                      "tangential_damping off"),
            std::string::npos)
      << deck;
  const std::string stl = write_mesh_stl(scene, 1);
  EXPECT_EQ(stl.rfind("solid mesh_1\n", 0), 0U);
  EXPECT_NE(stl.find("vertex 0.01 0 0.029999999999999999\n"), std::string::npos) << stl;
  EXPECT_EQ(mesh_file(1), "mesh_1.stl");
  // The box reaches the upper mesh at z = 30 mm (the spheres alone would stop far below it).
  const auto region = deck.find("region");
  ASSERT_NE(region, std::string::npos);
  const std::string box = deck.substr(region, deck.find('\n', region) - region);
  std::istringstream words(box);
  std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
  ASSERT_GE(w.size(), 9U) << box;
  EXPECT_GE(std::stod(w[8]), 0.03) << box;
  // A mesh behind a plane wall (40 mm below the floor) still lies inside the box: LIGGGHTS would drop
  // facets outside it and stop.
  std::string behind = text;
  behind.replace(behind.find("translate = [0.0, 0.0, -0.005]"), 30, "translate = [0.0, 0.0, -0.05]");
  support::write_file(dir / "behind.toml", behind);
  const cases::Scene low = cases::load_case(dir / "behind.toml");
  const reference::PreparedScene low_prepared(low);
  const DeckParts low_parts = deck_parts(low_prepared);
  ASSERT_TRUE(low_parts.reasons.empty()) << low_parts.reasons.front();
  const std::string low_deck =
      write_deck(low, low_parts.types, *low_parts.contacts, trace_plan(low, low_parts.types), settings);
  const auto low_region = low_deck.find("region");
  std::istringstream low_words(low_deck.substr(low_region, low_deck.find('\n', low_region) - low_region));
  std::vector<std::string> lw{std::istream_iterator<std::string>(low_words), {}};
  ASSERT_GE(lw.size(), 9U);
  EXPECT_LE(std::stod(lw[7]), -0.05) << low_deck.substr(low_region, 200);
  // A mesh of coordinates spanning less than 1e-4 m is refused, as LIGGGHTS would.
  std::string tiny = text;
  tiny.replace(tiny.find("scale = 1.0e-3\ntranslate = [0.0, 0.0, -0.005]"), 45,
               "scale = 1.0e-6\ntranslate = [0.05, 0.05, 0.05]");
  support::write_file(dir / "tiny.toml", tiny);
  const cases::Scene small = cases::load_case(dir / "tiny.toml");
  const reference::PreparedScene small_prepared(small);
  EXPECT_NE(reference::LiggghtsEngine{}.supports(small_prepared).explain().find("mesh 'a': its coordinates span"),
            std::string::npos)
      << reference::LiggghtsEngine{}.supports(small_prepared).explain();
  // A moving mesh is not mapped; nor does demwb bench write mesh files.
  std::string moving = text;
  moving.insert(moving.rfind("material = \"steel\""), "velocity = [0.0, 0.0, -0.1]\n");
  support::write_file(dir / "moving.toml", moving);
  const cases::Scene moved = cases::load_case(dir / "moving.toml");
  const reference::PreparedScene moved_prepared(moved);
  EXPECT_NE(reference::LiggghtsEngine{}.supports(moved_prepared).explain().find("mesh 'b' moves"), std::string::npos);
  EXPECT_NE(timing_deck(prepared, 1e-6, 10, 1e-4).reasons.at(0).find("does not write mesh files"), std::string::npos);
}

TEST(LiggghtsWalls, APlaneFacingDownMeasuresAndPushesAlongItsOwnNormal) {
  // A ceiling at z = 0.02 with normal −z: the distance is 0.02 − z, and the force along the wall's
  // normal is −F_z (positive when it pushes the sphere down, away from it).
  cases::WallSpec ceiling;
  ceiling.name = "ceiling";
  ceiling.point = {0.0, 0.0, 0.02};
  ceiling.normal = {0.0, 0.0, -1.0};
  const std::optional<WallPlane> plane = wall_plane(ceiling);
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(plane->axis, 2);
  EXPECT_EQ(plane->sign, -1.0);
  EXPECT_EQ(plane_arguments(*plane), "zplane 0.02");
  EXPECT_EQ(distance_formula(*plane, 3), "(0.02-z[3])");
  std::string text = case_text(kHertzModel, with_ratio(kSteel, 0.0), with_ratio(kGlass, 0.0));
  const std::string floor = "point = [0.0, 0.0, -0.01]\nnormal = [0.0, 0.0, 1.0]";
  text.replace(text.find(floor), floor.size(), "point = [0.0, 0.0, 0.01]\nnormal = [0.0, 0.0, -1.0]");
  const cases::Scene scene = scene_of(text);
  const TracePlan plan = trace_plan(scene, classify(scene));
  const auto fn = std::find_if(plan.columns.begin(), plan.columns.end(),
                               [](const TraceColumn& c) { return c.name == cases::wall_column(0, 0, "fn"); });
  ASSERT_NE(fn, plan.columns.end());
  EXPECT_EQ(fn->formula, "-f_force_tr_wall_0[1][3]");
  EXPECT_TRUE(unmapped_wall(ceiling, 0).empty());
  ceiling.normal = {0.0, 0.6, -0.8};
  EXPECT_FALSE(wall_plane(ceiling).has_value());
  EXPECT_FALSE(unmapped_wall(ceiling, 0).empty());
  ceiling.normal = {0.0, 0.0, -1.0};
  ceiling.removed_at = 0.0;  // stood through the preparation only: left out, not refused
  EXPECT_FALSE(reference::wall_in_run(ceiling));
  EXPECT_TRUE(unmapped_wall(ceiling, 0).empty());
  ceiling.removed_at = 1e-3;
  EXPECT_FALSE(unmapped_wall(ceiling, 0).empty());
}

TEST(LiggghtsBanner, ReadsTheVersion) {
  EXPECT_EQ(banner_version("LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled 2022-01-26-19:42:32 by buildd, git "
                           "commit unknown)\n"),
            "LIGGGHTS-PUBLIC 3.8.0");
  EXPECT_FALSE(banner_version("LAMMPS (29 Sep 2021 - Update 2)\n").has_value());
  EXPECT_FALSE(banner_version("").has_value());
}

}  // namespace liggghts_driver_test
