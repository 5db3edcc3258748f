// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <string>

#include "cases/scene.hpp"
#include "reference/liggghts/contact_mapping.hpp"
#include "reference/liggghts/deck_writer.hpp"
#include "reference/liggghts/trace_columns.hpp"

namespace reference::liggghts {

/// The conventions of a LIGGGHTS run, for reports (RunResult::conventions): integrator, time
/// step, model words and where each property table came from, how LIGGGHTS' formulas differ from
/// the case's where they do (Coulomb test, history projection, two-sided planes), where each
/// trace column comes from, precision and version.
std::map<std::string, std::string> run_conventions(const cases::Scene& scene, const ContactSettings& contacts,
                                                   const TracePlan& plan, const DeckSettings& settings,
                                                   const std::string& version);

}  // namespace reference::liggghts
