// SPDX-License-Identifier: MIT
// `demwb study integrators`: the integrator-accuracy study of thesis chapter 4.
#include <iostream>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "studies/integrator_study.hpp"

namespace app {

int command_study(const std::vector<std::string>& args, const Invocation& inv) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("output,o", po::value<std::string>(), "output directory (default out/study-<name>)");
  const auto vm = parse_command(args, "usage: demwb study integrators [-o DIR]", opts, {"study"});
  if (!vm) return kExitOk;
  const std::string name = (*vm)["study"].as<std::string>();
  if (name != "integrators") {
    throw std::invalid_argument(fmt::format("unknown study '{}' (known: integrators)", name));
  }
  const std::filesystem::path out = vm->count("output") != 0
                                        ? std::filesystem::path((*vm)["output"].as<std::string>())
                                        : std::filesystem::path("out/study-integrators");
  const studies::IntegratorStudy study = studies::run_integrator_study(studies::IntegratorStudyOptions{});
  studies::write_integrator_study(study, out, inv.argc, inv.argv);
  std::cout << studies::orders_table(study) << "\nwrote " << (out / "report.md").string() << " and "
            << (out / "orders.json").string() << "\n";
  return kExitOk;
}

}  // namespace app
