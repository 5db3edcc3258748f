// SPDX-License-Identifier: MIT
#include "app/options.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/driver_revisions.hpp"
#include "cases/catalogue.hpp"
#include "cases/excerpt.hpp"
#include "cases/output_budget.hpp"

namespace app {

namespace po = boost::program_options;

namespace {

/// A positional name without its optional marker '?'.
std::string optional_name(const std::string& name) {
  return name.ends_with('?') ? name.substr(0, name.size() - 1) : name;
}

}  // namespace

std::optional<po::variables_map> parse_command(const std::vector<std::string>& args,
                                               const std::string& usage,
                                               const po::options_description& visible,
                                               const std::vector<std::string>& positional) {
  po::options_description all;
  all.add(visible);
  all.add_options()("help,h", "show this help");
  po::options_description hidden;
  po::positional_options_description pos;
  for (const auto& given : positional) {
    const std::string name = optional_name(given);
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
    if (name.ends_with('?')) continue;
    if (vm.count(name) == 0) throw po::error("missing argument " + name + "\n" + usage);
  }
  return vm;
}

void add_run_options(po::options_description& opts) {
  opts.add_options()("timeout", po::value<double>()->default_value(600.0),
                     "seconds before an external engine is killed")(
      "cache", po::value<std::string>(),
      "reference-result cache directory (default $DEMWB_CACHE_DIR, else $XDG_CACHE_HOME/demwb, else ~/.cache/demwb, else ./.demwb-cache)")(
      "no-cache", "run reference codes every time and store nothing")(
      "no-time-step-check",
      "do not rerun LAMMPS and YADE at halved time steps to estimate their own discretisation error "
      "(faster; native rows then carry no estimate and use the case's time step)")(
      "baselines", po::value<std::string>(),
      "committed baselines used when a reference code is not installed (default cases/baselines)")(
      "reproducible",
      "leave wall times out of results.json (they stay in report.md) so that two runs compare byte for byte")(
      "match", po::value<std::vector<std::string>>()->composing(),
      "also run the core with this reference code's numerics (lammps, yade, liggghts) and compare the two")(
      "no-match",
      "leave out the matched runs the case names in compare.matched (and their reference codes, unless "
      "asked for): only the engines of compare.engines or --engine run")(
      "threads", po::value<int>()->default_value(1),
      "OpenMP threads of the core (results are bit-identical for any count)")(
      "max-memory", po::value<std::string>(),
      "most memory one run's output may take, e.g. 512M or 8G (default half the physical memory); larger cases are refused at load time");
  add_program_options(opts);
}

cases::LoadOptions load_options(const po::variables_map& vm) {
  cases::LoadOptions options;
  if (vm.count("max-memory") == 0) {
    options.max_output_bytes = cases::physical_memory_bytes() / 2;
    return options;
  }
  const std::string text = vm["max-memory"].as<std::string>();
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  double scale = 1.0;
  const std::string suffix = text.substr(used);
  if (suffix == "K" || suffix == "k") scale = 1024.0;
  if (suffix == "M") scale = 1024.0 * 1024.0;
  if (suffix == "G") scale = 1024.0 * 1024.0 * 1024.0;
  if (suffix == "T") scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
  const bool known_suffix = suffix.empty() || scale > 1.0;
  if (used == 0 || !known_suffix || !(value * scale >= 1.0) || value * scale > 1.0e18) {
    throw std::invalid_argument("--max-memory '" + text.substr(0, 40) +
                                "': give a number of bytes, optionally with K, M, G or T (e.g. 512M)");
  }
  options.max_output_bytes = static_cast<std::uint64_t>(value * scale);
  return options;
}

double timeout_option(const po::variables_map& vm) {
  const double timeout = vm["timeout"].as<double>();
  if (!(timeout > 0.0) || timeout > 1e7) {
    throw std::invalid_argument("--timeout must be a number of seconds between 0 and 1e7");
  }
  return timeout;
}

std::vector<std::string> forwarded_run_options(const po::variables_map& vm) {
  std::vector<std::string> args{"--threads", std::to_string(vm["threads"].as<int>())};
  // Only a --timeout the user gave: a sweep file's own timeout applies when none was given.
  if (!vm["timeout"].defaulted()) {
    args.insert(args.end(), {"--timeout", fmt::format("{}", vm["timeout"].as<double>())});
  }
  if (vm.count("no-cache") != 0) args.emplace_back("--no-cache");
  if (vm.count("no-time-step-check") != 0) args.emplace_back("--no-time-step-check");
  for (const char* option : {"cache", "lammps", "yade", "liggghts"}) {
    if (vm.count(option) != 0) args.insert(args.end(), {std::string("--") + option, vm[option].as<std::string>()});
  }
  return args;
}

std::vector<std::string> sweep_arguments(const std::filesystem::path& sweep_file, const std::filesystem::path& out,
                                         unsigned jobs, const po::variables_map& vm) {
  std::vector<std::string> args{sweep_file.string(), "-o", out.string(), "-j", std::to_string(std::max(1U, jobs))};
  for (auto& a : forwarded_run_options(vm)) args.push_back(std::move(a));
  return args;
}

void add_tier_option(po::options_description& opts) {
  opts.add_options()("tier", po::value<std::string>()->default_value("fast"),
                     "fast: full-tier cases take their reference results from the committed baselines (CI); "
                     "full: every engine of every case runs");
}

cases::Tier tier_option(const po::variables_map& vm) {
  const std::string word = vm["tier"].as<std::string>();
  const auto tier = cases::parse_tier(word);
  if (!tier) throw std::invalid_argument("--tier must be 'fast' or 'full', not '" + cases::excerpt(word) + "'");
  return *tier;
}

void add_program_options(po::options_description& opts) {
  opts.add_options()("lammps", po::value<std::string>(),
                     "LAMMPS binary to drive (default $DEMWB_LAMMPS, else lmp in PATH)")(
      "yade", po::value<std::string>(), "YADE launcher script to drive (default $DEMWB_YADE, else yade in PATH)")(
      "liggghts", po::value<std::string>(),
      "LIGGGHTS binary to drive (default $DEMWB_LIGGGHTS, else liggghts in PATH)");
}

reference::ExternalPrograms external_programs(const po::variables_map& vm, double timeout_s) {
  reference::ExternalPrograms programs;
  const auto choose = [&](const char* option, const char* variable, std::string& program) {
    if (vm.count(option) != 0) {
      program = vm[option].as<std::string>();
      if (program.empty()) throw std::invalid_argument(std::string("--") + option + ": empty path");
    } else if (const char* v = std::getenv(variable); v != nullptr && *v != '\0') {
      program = v;
    }
  };
  choose("lammps", "DEMWB_LAMMPS", programs.lammps);
  choose("yade", "DEMWB_YADE", programs.yade);
  choose("liggghts", "DEMWB_LIGGGHTS", programs.liggghts);
  programs.probe_timeout_s = std::min(programs.probe_timeout_s, timeout_s);
  return programs;
}

cases::Scene with_matches(cases::Scene scene, const po::variables_map& vm) {
  if (vm.count("no-match") != 0) {
    if (vm.count("match") != 0) throw std::invalid_argument("--match and --no-match: give one of them, not both");
    scene.compare.matched.clear();
    return scene;
  }
  if (vm.count("match") == 0) return scene;
  for (const auto& code : split_names(vm["match"].as<std::vector<std::string>>())) {
    if (!cases::is_reference_code(code)) {
      throw std::invalid_argument("--match " + code + ": not a reference code (lammps, yade, liggghts)");
    }
    if (std::find(scene.compare.matched.begin(), scene.compare.matched.end(), code) == scene.compare.matched.end()) {
      scene.compare.matched.push_back(code);
    }
  }
  return scene;
}

void refuse_matches(const po::variables_map& vm, std::string_view command) {
  for (const char* option : {"match", "no-match"}) {
    if (vm.count(option) != 0) {
      throw std::invalid_argument(std::string("demwb ") + std::string(command) + ": --" + option +
                                  " does not apply (it runs the engines and matched runs its files name)");
    }
  }
}

RunContext run_context(const po::variables_map& vm, const std::filesystem::path& work_dir) {
  RunContext ctx;
  ctx.options.work_dir = work_dir;
  ctx.options.timeout_s = timeout_option(vm);
  ctx.programs = external_programs(vm, ctx.options.timeout_s);
  ctx.load = load_options(vm);
  ctx.options.threads = vm["threads"].as<int>();
  if (ctx.options.threads < 1 || ctx.options.threads > 1024) {
    throw std::invalid_argument("--threads must be between 1 and 1024");
  }
  if (vm.count("no-cache") == 0) {
    ctx.cache.emplace(vm.count("cache") != 0 ? std::filesystem::path(vm["cache"].as<std::string>())
                                             : store::ResultCache::default_dir());
  }
  ctx.prepare.threads = ctx.options.threads;
  ctx.prepare.core_revision = kCoreRevision;
  if (ctx.cache) ctx.prepare.cache_dir = ctx.cache->dir() / "stages";
  ctx.wall_times = vm.count("reproducible") == 0;
  ctx.refine_time_step = vm.count("no-time-step-check") == 0;
  ctx.baselines = vm.count("baselines") != 0
                      ? std::optional<std::filesystem::path>(vm["baselines"].as<std::string>())
                      : default_baselines();
  return ctx;
}

}  // namespace app
