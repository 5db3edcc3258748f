// SPDX-License-Identifier: MIT
#include "reference/registry.hpp"

#include <array>

#include "cases/catalogue.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/inhouse/matched_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/lammps/matched_scene.hpp"
#include "reference/liggghts/liggghts_engine.hpp"
#include "reference/liggghts/matched_scene.hpp"
#include "reference/yade/matched_scene.hpp"
#include "reference/yade/yade_engine.hpp"

namespace reference {
namespace {

// The core takes a multi-step scheme's exact start-up states from the closed forms.
std::unique_ptr<Engine> make_inhouse(const ExternalPrograms&) {
  return std::make_unique<InhouseEngine>(ExactStates(&exact_states));
}

std::unique_ptr<Engine> make_analytic(const ExternalPrograms&) { return std::make_unique<AnalyticEngine>(); }

std::unique_ptr<Engine> make_lammps(const ExternalPrograms& programs) {
  LammpsOptions options;
  options.program = programs.lammps;
  options.probe_timeout_s = programs.probe_timeout_s;
  return std::make_unique<LammpsEngine>(std::move(options));
}

std::unique_ptr<Engine> make_yade(const ExternalPrograms& programs) {
  return std::make_unique<YadeEngine>(YadeEngine::from_launcher(programs.yade));
}

std::unique_ptr<Engine> make_liggghts(const ExternalPrograms& programs) {
  LiggghtsOptions options;
  options.program = programs.liggghts;
  options.probe_timeout_s = programs.probe_timeout_s;
  return std::make_unique<LiggghtsEngine>(std::move(options));
}

constexpr std::array kEngines{
    EngineEntry{"inhouse", &make_inhouse},
    EngineEntry{"analytic", &make_analytic},
    EngineEntry{"lammps", &make_lammps, &lammps::conventions},
    EngineEntry{"yade", &make_yade, &yade::conventions},
    EngineEntry{"liggghts", &make_liggghts, &liggghts::conventions},
};

}  // namespace

std::span<const EngineEntry> engine_registry() noexcept { return kEngines; }

std::unique_ptr<Engine> make_engine(std::string_view name, const ExternalPrograms& programs) {
  for (const EngineEntry& e : kEngines) {
    if (e.name == name) return e.make(programs);
  }
  if (const CodeConventions* c = code_conventions(cases::matched_code(name))) {
    return std::make_unique<MatchedInhouseEngine>(*c);
  }
  return nullptr;
}

const CodeConventions* code_conventions(std::string_view code) noexcept {
  for (const EngineEntry& e : kEngines) {
    if (e.name == code && e.conventions != nullptr) return &e.conventions();
  }
  return nullptr;
}

}  // namespace reference
