// SPDX-License-Identifier: MIT
// The engine registry: every engine a case file may name has exactly one row, each row makes an
// engine of its own name, and matched engines are made for the codes with matched numerics only.
#include "reference/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cases/catalogue.hpp"

namespace {

TEST(EngineRegistry, EveryCatalogueEngineHasOneRowAndEveryRowMakesItsEngine) {
  const auto rows = reference::engine_registry();
  for (const std::string_view name : cases::engine_catalogue()) {
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [&](const auto& e) { return e.name == name; }), 1) << name;
  }
  for (const reference::EngineEntry& e : rows) {
    EXPECT_NE(std::find(cases::engine_catalogue().begin(), cases::engine_catalogue().end(), e.name),
              cases::engine_catalogue().end())
        << e.name << " is not in the case files' engine catalogue";
    const auto engine = reference::make_engine(e.name);
    ASSERT_NE(engine, nullptr) << e.name;
    EXPECT_EQ(engine->name(), e.name);
  }
}

TEST(EngineRegistry, MatchedEnginesExistForTheirCodesAndUnknownNamesGiveNone) {
  for (const char* code : {"lammps", "yade"}) {
    const auto engine = reference::make_engine(std::string("inhouse@") + code);
    ASSERT_NE(engine, nullptr) << code;
    EXPECT_EQ(engine->name(), std::string("inhouse@") + code);
  }
  EXPECT_EQ(reference::make_engine("gromacs"), nullptr);
  EXPECT_EQ(reference::make_engine(""), nullptr);
  EXPECT_EQ(reference::make_engine("inhouse@gromacs"), nullptr);
}

TEST(EngineRegistry, OnlyReferenceCodesExportConventionsAndEachNamesItsOwnCode) {
  for (const char* code : {"lammps", "yade"}) {
    const reference::CodeConventions* c = reference::code_conventions(code);
    ASSERT_NE(c, nullptr) << code;
    EXPECT_EQ(c->code, code);
    EXPECT_NE(c->matched_scene, nullptr) << code;
  }
  EXPECT_EQ(reference::code_conventions("inhouse"), nullptr);
  EXPECT_EQ(reference::code_conventions("analytic"), nullptr);
  EXPECT_EQ(reference::code_conventions("gromacs"), nullptr);
}

}  // namespace
