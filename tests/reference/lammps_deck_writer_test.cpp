// SPDX-License-Identifier: MIT
// The LAMMPS deck writer: explicit pair coefficients, exact η per type pair, frozen fixed
// spheres, full-precision trace columns (no LAMMPS needed).
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"
#include "lammps_scenes.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/simulation_box.hpp"

namespace lammps_deck_writer_test {

using demwb_lammps_unit::line_index;
using demwb_lammps_unit::lines_of;
using demwb_lammps_unit::mixed_scene;
using demwb_lammps_unit::words;
using reference::lammps::DeckSettings;
using reference::lammps::write_deck;

DeckSettings settings(std::uint64_t steps = 20) {
  DeckSettings s;
  s.timestep = 1e-5;
  s.steps = steps;
  return s;
}

TEST(LammpsAtomTypes, OneTypePerMaterialRadiusAndFixedClass) {
  const auto types = reference::lammps::classify_particles(mixed_scene());
  ASSERT_EQ(types.types.size(), 4u);
  EXPECT_EQ(types.type_of, (std::vector<std::size_t>{0, 0, 1, 2, 3}));
  EXPECT_FALSE(types.types[1].fixed);
  EXPECT_TRUE(types.types[3].fixed);
  EXPECT_DOUBLE_EQ(types.types[1].mass, dem::sphere_mass(7800.0, 0.02));
}

TEST(LammpsAtomTypes, ReducedMassIsTheMobileMassAgainstAFixedType) {
  const auto types = reference::lammps::classify_particles(mixed_scene());
  const double m1 = types.types[0].mass;
  const double m2 = types.types[1].mass;
  EXPECT_DOUBLE_EQ(*types.reduced_mass(0, 2), m1);
  EXPECT_DOUBLE_EQ(*types.reduced_mass(3, 1), m2);
  EXPECT_DOUBLE_EQ(*types.reduced_mass(0, 1), m1 * m2 / (m1 + m2));
  EXPECT_FALSE(types.reduced_mass(2, 3).has_value());
}

TEST(LammpsDeck, FewSpheresOfManySizesComeFromTheDataFileWithTheirOwnDiameters) {
  // 20 spheres of 20 radii: diameters per atom, so a data file even below kMaxInlineAtoms (a
  // `set type … diameter` would have given every sphere the type's radius 0).
  cases::Scene scene = mixed_scene();
  const cases::ParticleSpec first = scene.particles.front();
  scene.particles.clear();
  for (int k = 0; k < 20; ++k) {
    cases::ParticleSpec p = first;
    p.radius = 0.01 + 1e-4 * k;
    p.effect_radius = p.radius;
    p.position = {0.05 * k, 0.0, 0.0};
    scene.particles.push_back(p);
  }
  scene.output.trace_particles = {0};
  scene.output.trace_pairs.clear();
  scene.output.trace_walls.clear();
  scene.model.damping = "none";  // a dashpot per type pair needs one m* per type: n/a here
  ASSERT_TRUE(reference::lammps::classify_particles(scene).per_atom_diameter);
  ASSERT_TRUE(reference::lammps::atoms_in_data_file(scene));
  const std::string deck = write_deck(scene, settings());
  EXPECT_NE(deck.find("read_data"), std::string::npos);
  EXPECT_EQ(deck.find("diameter 0 "), std::string::npos);
  const std::string data = reference::lammps::write_atom_data(scene, settings());
  EXPECT_NE(data.find(fmt::format(" {:.17g} ", 2.0 * (0.01 + 1e-4 * 19))), std::string::npos);
}

TEST(LammpsDeck, WritesAnExplicitPairCoeffForEveryTypePairAndNeverAWildcard) {
  const std::string deck = write_deck(mixed_scene(), settings());
  std::set<std::pair<int, int>> seen;
  for (const auto& line : lines_of(deck, "pair_coeff")) {
    const auto w = words(line);
    ASSERT_GE(w.size(), 4u) << line;
    ASSERT_NE(w[1], "*") << line;
    const int i = std::stoi(w[1]);
    const int j = std::stoi(w[2]);
    EXPECT_LE(i, j);
    EXPECT_TRUE(seen.insert({i, j}).second) << "pair " << i << "-" << j << " written twice";
  }
  EXPECT_EQ(seen.size(), 10u);  // 4 types: 4·5/2 pairs
  EXPECT_EQ(lines_of(deck, "pair_style").size(), 1u);
  EXPECT_EQ(words(lines_of(deck, "pair_style").front()).at(1), "granular");
}

TEST(LammpsDeck, DampingCoefficientIsExactForEachTypePairsReducedMass) {
  const cases::Scene scene = mixed_scene();
  const std::string deck = write_deck(scene, settings());
  const auto types = reference::lammps::classify_particles(scene);
  const dem::PairTable table(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  for (const auto& line : lines_of(deck, "pair_coeff")) {
    const auto w = words(line);
    // pair_coeff i j hooke k η tangential linear_nohistory 0 0 damping velocity
    ASSERT_EQ(w.size(), 12u) << line;
    EXPECT_EQ(w[3], "hooke");
    EXPECT_EQ(w[6], "tangential");
    EXPECT_EQ(w[7], "linear_nohistory");
    EXPECT_EQ(w[10], "damping");
    EXPECT_EQ(w[11], "velocity");
    const std::size_t a = std::stoul(w[1]) - 1;
    const std::size_t b = std::stoul(w[2]) - 1;
    const dem::PairProperties& p =
        table.properties(types.types[a].material, types.types[b].material);
    EXPECT_EQ(std::stod(w[4]), *p.normal_stiffness) << line;
    const auto m = types.reduced_mass(a, b);
    const double eta = m ? dem::laws::restitution_damping_coefficient(*p.restitution, *m,
                                                                      *p.normal_stiffness)
                         : 0.0;
    EXPECT_EQ(std::stod(w[5]), eta) << line;  // %.17g reads back the same double
  }
}

TEST(LammpsDeck, MobileFixedEtaUsesTheMobileMassAsFixFreezeDoes) {
  const std::string deck = write_deck(mixed_scene(), settings());
  const double m1 = dem::sphere_mass(2500.0, 0.01);
  const double eta = dem::laws::restitution_damping_coefficient(0.5, m1, 1e5);
  const auto line = lines_of(deck, "pair_coeff").at(2);  // types 1-3: glass mobile – glass fixed
  ASSERT_EQ(words(line).at(2), "3");
  EXPECT_EQ(std::stod(words(line).at(5)), eta);
}

TEST(LammpsDeck, FreezesAllFixedSpheresWithOneFixFreezeAndIntegratesTheRest) {
  const std::string deck = write_deck(mixed_scene(), settings());
  std::size_t freezes = 0;
  for (const auto& line : lines_of(deck, "fix")) {
    if (words(line).at(3) == "freeze") {
      ++freezes;
      EXPECT_EQ(words(line).at(2), "tr_fixed");
    }
  }
  EXPECT_EQ(freezes, 1u);
  EXPECT_NE(line_index(deck, "group           tr_fixed type 3 4"), std::string::npos);
  EXPECT_NE(line_index(deck, "group           tr_mobile type 1 2"), std::string::npos);
  EXPECT_NE(line_index(deck, "tr_integrate tr_mobile nve/sphere"), std::string::npos);
}

TEST(LammpsDeck, StoresPairForcesBeforeGravityAndFreezeTouchThem) {
  const std::string deck = write_deck(mixed_scene(), settings());
  const std::size_t store = line_index(deck, "tr_pairforce all store/force");
  const std::size_t gravity = line_index(deck, "tr_gravity");
  const std::size_t freeze = line_index(deck, "tr_freeze");
  ASSERT_NE(store, std::string::npos);
  ASSERT_NE(gravity, std::string::npos);
  ASSERT_NE(freeze, std::string::npos);
  EXPECT_LT(store, gravity);
  EXPECT_LT(store, freeze);
  const auto g = words(deck.substr(deck.find("tr_gravity tr_mobile gravity")));
  EXPECT_EQ(std::stod(g.at(3)), 9.81);
  EXPECT_EQ(g.at(4), "vector");
  EXPECT_EQ(std::stod(g.at(7)), -9.81);
}

TEST(LammpsDeck, OmitsGravityAndFreezeWhenTheSceneHasNone) {
  cases::Scene scene = mixed_scene();
  scene.gravity = {0.0, 0.0, 0.0};
  scene.particles.resize(3);
  scene.output.trace_particles = {0};
  scene.output.trace_pairs = {{0, 1}};
  const std::string deck = write_deck(scene, settings());
  EXPECT_EQ(line_index(deck, "tr_gravity"), std::string::npos);
  EXPECT_EQ(line_index(deck, "tr_freeze"), std::string::npos);
  EXPECT_EQ(line_index(deck, "tr_fixed"), std::string::npos);
}

TEST(LammpsDeck, HoldsRotationWithFixNveWhenTheSceneDoesNotIntegrateIt) {
  cases::Scene scene = mixed_scene();
  scene.integration.rotation = false;
  const std::string deck = write_deck(scene, settings());
  EXPECT_NE(line_index(deck, "tr_integrate tr_mobile nve "), std::string::npos);
  EXPECT_EQ(line_index(deck, "nve/sphere"), std::string::npos);
}

TEST(LammpsDeck, SetsDiameterBeforeDensityForEveryType) {
  const cases::Scene scene = mixed_scene();
  const std::string deck = write_deck(scene, settings());
  for (int t = 1; t <= 4; ++t) {
    const std::string set_type = "set             type " + std::to_string(t);
    const std::size_t diameter = line_index(deck, set_type + " diameter");
    const std::size_t density = line_index(deck, set_type + " density");
    ASSERT_NE(diameter, std::string::npos) << "type " << t;
    ASSERT_NE(density, std::string::npos) << "type " << t;
    EXPECT_LT(diameter, density) << "type " << t;
  }
  EXPECT_NE(line_index(deck, "set             type 2 diameter 0.040000000000000001"),
            std::string::npos);
  EXPECT_NE(line_index(deck, "set             atom 3 vx 0 vy 0 vz -2 omega 0 3 0"),
            std::string::npos);
}

TEST(LammpsDeck, CreatesEveryParticleAsTheAtomWithIdIndexPlusOneInsideTheBox) {
  const cases::Scene scene = mixed_scene();
  const std::string deck = write_deck(scene, settings());
  const auto creates = lines_of(deck, "create_atoms");
  ASSERT_EQ(creates.size(), scene.particles.size());
  EXPECT_EQ(words(creates[2]).at(1), "2");  // steel r 0.02 → type 2
  EXPECT_EQ(words(creates[4]).at(1), "4");
  const auto box = reference::lammps::simulation_box(scene, 2e-4);
  for (const auto& p : scene.particles) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_LT(box.low[k], p.position[k] - p.radius);
      EXPECT_GT(box.high[k], p.position[k] + p.radius);
    }
  }
}

TEST(LammpsDeck, PrintsTheInhouseTraceColumnsAtFullPrecisionEveryTraceEverySteps) {
  const std::string deck = write_deck(mixed_scene(), settings());
  const auto prints = lines_of(deck, "fix");
  std::string print;
  for (const auto& l : prints) {
    if (l.find(" print ") != std::string::npos) print = l;
  }
  ASSERT_FALSE(print.empty());
  EXPECT_NE(print.find("tr_print all print 2 \""), std::string::npos);
  EXPECT_NE(print.find(" file trace.txt screen no title \"# step time p0.x p0.y p0.z p0.vx "
                       "p0.vy p0.vz p0.wx p0.wy p0.wz p0.fx p0.fy p0.fz p3.x"),
            std::string::npos);
  EXPECT_NE(print.find("p3.fz c0-3.overlap c0-3.fn c0-3.fn_exact\""), std::string::npos);
  EXPECT_NE(print.find("$(x[1]:%.17g)"), std::string::npos);
  EXPECT_NE(print.find("$(fx[1]:%.17g)"), std::string::npos);  // mobile: LAMMPS' total force
  EXPECT_NE(print.find("$(f_tr_pairforce[4][1]:%.17g)"), std::string::npos);  // fixed: contacts
  EXPECT_NE(print.find("$(c_tr_atom[1][2]:%.17g)"), std::string::npos);       // ωx
  // No v_name references: LAMMPS would pass them through "%.15g".
  EXPECT_EQ(print.find("v_"), std::string::npos);
  EXPECT_EQ(lines_of(deck, "variable").size(), 1u);  // only the snapshot schedule
}

TEST(LammpsDeck, DumpsSnapshotsAtTheInhouseSnapshotSteps) {
  const std::string deck = write_deck(mixed_scene(), settings());
  EXPECT_NE(line_index(deck, "tr_snapshot_step equal \"10*(step>=0)*(step<10)+21*(step>=10)\""),
            std::string::npos);
  EXPECT_NE(line_index(deck, "every v_tr_snapshot_step first yes"), std::string::npos);
  EXPECT_NE(line_index(deck, "format float %.17g"), std::string::npos);
}

TEST(LammpsDeck, PutsExtraCommandsJustBeforeTheRun) {
  DeckSettings s = settings(20);
  s.extra_commands = "print \"hello\"";
  const std::string deck = write_deck(mixed_scene(), s);
  const std::size_t extra = line_index(deck, "print \"hello\"");
  const std::size_t run = line_index(deck, "run             20");
  ASSERT_NE(extra, std::string::npos);
  EXPECT_EQ(run, extra + 1);
  EXPECT_EQ(deck.substr(deck.size() - 19), "run             20\n");
}

TEST(LammpsDeck, ClampTensileBecomesLimitDamping) {
  cases::Scene scene = mixed_scene();
  scene.model.clamp_tensile = true;
  for (const auto& line : lines_of(write_deck(scene, settings()), "pair_coeff")) {
    EXPECT_NE(line.find(" limit_damping "), std::string::npos) << line;
  }
}

TEST(LammpsDeck, IsAPureFunctionOfItsInputsAndPlainAscii) {
  const std::string a = write_deck(mixed_scene(), settings());
  EXPECT_EQ(a, write_deck(mixed_scene(), settings()));
  for (const char c : a) EXPECT_LT(static_cast<unsigned char>(c), 0x80);
}

}  // namespace

namespace lammps_deck_writer_test {

TEST(LammpsDeck, NamesInCommentsStayCommentsWhateverTheyHold) {
  // The loader refuses such names (cases/names.hpp); the deck writer keeps them inert anyway: a
  // newline would end the comment and run `shell`, `"""` would swallow the rest of the deck.
  cases::Scene scene = mixed_scene();
  cases::WallSpec floor;
  floor.name = "floor\nshell touch pwned\n#\"\"\" \r\x7f";
  floor.normal = {0.0, 0.0, 1.0};
  floor.point = {0.0, 0.0, -1.0};
  scene.walls.push_back(floor);
  const std::string deck = write_deck(scene, settings());
  EXPECT_EQ(deck.find("\"\"\""), std::string::npos);
  EXPECT_EQ(deck.find('\r'), std::string::npos);
  EXPECT_EQ(deck.find('\x7f'), std::string::npos);
  bool named = false;
  std::istringstream lines(deck);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_NE(line.rfind("shell", 0), 0u) << line;
    if (line.find("floor") != std::string::npos) {
      named = true;
      EXPECT_EQ(line.rfind('#', 0), 0u) << "the name appears outside a comment: " << line;
      EXPECT_NE(line.find("floor?shell touch pwned?#''' ??"), std::string::npos) << line;
    }
  }
  EXPECT_TRUE(named) << "the wall's comment line is expected to name it";
}

}  // namespace
