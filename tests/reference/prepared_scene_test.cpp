// SPDX-License-Identifier: MIT
// The neutral layer's PreparedScene: the pair table is built once and shared (with the core's
// simulation too), a model that lacks a parameter fails at every use as building the table
// would, and a run through a prepared scene equals a run of the bare scene bit for bit.
#include "reference/common/prepared_scene.hpp"

#include <gtest/gtest.h>

#include <string>

#include "analytic_scenes.hpp"
#include "dem/core/model_error.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/registry.hpp"

namespace {

TEST(PreparedScene, TheCoreSetupSharesThePreparedTable) {
  const cases::Scene scene = demwb_test::single_collision();
  const reference::PreparedScene prepared(scene);
  EXPECT_EQ(&prepared.scene(), &scene);
  const reference::CoreSetup setup = reference::core_setup(prepared);
  ASSERT_NE(setup.simulation.pair_table, nullptr);
  EXPECT_EQ(setup.simulation.pair_table.get(), &prepared.pair_table());
  EXPECT_EQ(reference::core_setup(prepared, 2).simulation.pair_table.get(), &prepared.pair_table());
  const dem::Simulation sim(setup.simulation);
  EXPECT_EQ(&sim.pair_table(), &prepared.pair_table());
}

TEST(PreparedScene, AnIncompleteModelThrowsAtEveryUseWithTheTablesOwnMessage) {
  cases::Scene scene = demwb_test::single_collision();
  scene.materials[0].normal_stiffness.reset();  // the linear spring has nothing to work with
  std::string direct;
  try {
    const dem::PairTable table(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  } catch (const dem::ModelError& e) {
    direct = e.what();
  }
  ASSERT_FALSE(direct.empty()) << "the scene was meant to lack the spring's stiffness";
  const reference::PreparedScene prepared(scene);  // does not throw
  for (int k = 0; k < 2; ++k) {
    try {
      static_cast<void>(prepared.pair_table());
      ADD_FAILURE() << "pair_table() returned a table for an incomplete model";
    } catch (const dem::ModelError& e) {
      EXPECT_EQ(std::string(e.what()), direct);
    }
  }
  EXPECT_THROW(static_cast<void>(reference::core_setup(prepared)), dem::ModelError);
  // Every engine reports it as its own failure, not as a crash of the bookkeeping.
  const auto inhouse = reference::run_engine(*reference::make_engine("inhouse"), prepared, {});
  EXPECT_EQ(inhouse.status, cases::RunStatus::error);
  EXPECT_EQ(inhouse.reason, direct);
}

TEST(PreparedScene, EveryBuiltInEngineGivesTheSameRunPreparedOnceOrPerCall) {
  const cases::Scene scene = demwb_test::single_collision();
  const reference::PreparedScene prepared(scene);
  for (const char* name : {"inhouse", "analytic", "inhouse@lammps", "inhouse@yade"}) {
    const auto engine = reference::make_engine(name);
    ASSERT_NE(engine, nullptr) << name;
    const auto once = reference::run_engine(*engine, prepared, {});
    const auto bare = reference::run_engine(*engine, scene, {});
    ASSERT_EQ(once.status, cases::RunStatus::ok) << name << ": " << once.reason;
    EXPECT_EQ(once.trace.columns(), bare.trace.columns()) << name;
    for (const auto& column : once.trace.columns()) {
      EXPECT_EQ(*once.trace.column(column), *bare.trace.column(column)) << name << " " << column;
    }
  }
}

}  // namespace
