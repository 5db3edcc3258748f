// SPDX-License-Identifier: MIT
#include "app/options.hpp"

#include <iostream>

namespace app {

namespace po = boost::program_options;

std::optional<po::variables_map> parse_command(const std::vector<std::string>& args,
                                               const std::string& usage,
                                               const po::options_description& visible,
                                               const std::vector<std::string>& positional) {
  po::options_description all;
  all.add(visible);
  all.add_options()("help,h", "show this help");
  po::options_description hidden;
  po::positional_options_description pos;
  for (const auto& name : positional) {
    hidden.add_options()(name.c_str(), po::value<std::string>());
    pos.add(name.c_str(), 1);
  }
  all.add(hidden);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(all).positional(pos).run(), vm);
  if (vm.count("help") != 0) {
    std::cout << usage << "\n" << visible << "  -h [ --help ]             show this help\n";
    return std::nullopt;
  }
  po::notify(vm);
  for (const auto& name : positional) {
    if (vm.count(name) == 0) throw po::error("missing argument " + name + "\n" + usage);
  }
  return vm;
}

}  // namespace app
