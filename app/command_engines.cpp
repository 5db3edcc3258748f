// SPDX-License-Identifier: MIT
// `demwb engines`: which engines exist here, where their programs were found, and their versions.
#include <iostream>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/catalogue.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"
#include "reports/markdown.hpp"

namespace app {

int command_engines(const std::vector<std::string>& args, const Invocation&) {
  boost::program_options::options_description opts("options");
  add_program_options(opts);
  opts.add_options()("timeout", boost::program_options::value<double>()->default_value(10.0),
                     "seconds a version probe may take");
  const auto vm = parse_command(args, "usage: demwb engines [--lammps PATH] [--yade PATH]", opts, {});
  if (!vm) return kExitOk;
  const reference::ExternalPrograms programs = external_programs(*vm, timeout_option(*vm));
  reports::MarkdownTable t({"engine", "status", "version", "where"});
  for (const auto name : cases::engine_catalogue()) {
    const auto engine = reference::make_engine(name, programs);
    if (!engine) {
      t.add_row({std::string(name), "no driver in this build", "—", "—"});
      continue;
    }
    const auto version = engine->version();
    t.add_row({std::string(name), version ? "installed" : "missing", version.value_or("—"), engine->location()});
  }
  std::cout << t.render();
  return kExitOk;
}

}  // namespace app
