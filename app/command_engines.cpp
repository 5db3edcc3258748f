// SPDX-License-Identifier: MIT
// `demwb engines`: which engines exist here and their versions.
#include <iostream>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/catalogue.hpp"
#include "reference/engine.hpp"
#include "reports/markdown.hpp"

namespace app {

int command_engines(const std::vector<std::string>& args, const Invocation&) {
  const boost::program_options::options_description opts("options");
  if (!parse_command(args, "usage: demwb engines", opts, {})) return kExitOk;
  reports::MarkdownTable t({"engine", "status", "version"});
  for (const auto name : cases::engine_catalogue()) {
    const auto engine = reference::make_engine(name);
    if (!engine) {
      t.add_row({std::string(name), "no driver in this build", "—"});
      continue;
    }
    const auto version = engine->version();
    t.add_row({std::string(name), version ? "installed" : "missing", version.value_or("—")});
  }
  std::cout << t.render();
  return kExitOk;
}

}  // namespace app
