// SPDX-License-Identifier: MIT
// `demwb convert`: thesis appendix E, linear elastic–cohesive parameters ↔ JKR parameters.
#include <iostream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "dem/contact/laws/jkr.hpp"
#include "dem/conversion/appendix_e.hpp"
#include "reports/markdown.hpp"

namespace app {
namespace {

namespace po = boost::program_options;
namespace conv = dem::conversion;

constexpr const char* kUsage =
    "usage: demwb convert linear-to-jkr --stiffness K --cohesive-stiffness KC --max-overlap D\n"
    "                     --radius R --effect-radius RE [--poisson NU] [options]\n"
    "       demwb convert jkr-to-linear --youngs-modulus E --poisson NU --surface-energy G\n"
    "                     --max-overlap D --radius R --effect-radius RE [options]\n"
    "\n"
    "Thesis appendix E for two identical spheres: k_e = 16/15 E* sqrt(R* D) (eq E.4) and the\n"
    "cohesion matched by equal work of the force-separation curve from D to rupture (listing\n"
    "E.1; the JKR work in closed form). Units: N/m, m, Pa, J/m^2 (gamma per surface).\n";

/// One output line: name, value, unit, meaning.
struct Row {
  std::string key;
  double value;
  std::string unit;
  std::string meaning;
};

conv::Convention parse_convention(const std::string& word) {
  if (word == "workbench") return conv::Convention::workbench;
  if (word == "thesis") return conv::Convention::thesis;
  throw std::invalid_argument(
      fmt::format("--convention must be 'workbench' or 'thesis', got '{}'", word));
}

dem::JkrRupture parse_rupture(const std::string& word) {
  if (const auto r = dem::parse_jkr_rupture(word)) return *r;
  throw std::invalid_argument(
      fmt::format("--rupture must be 'displacement' or 'load', got '{}'", word));
}

/// Options both directions share.
void add_common(po::options_description& opts) {
  opts.add_options()
      ("max-overlap", po::value<double>()->required(), "deepest overlap of a typical collision D [m]")
      ("radius", po::value<double>()->required(), "body radius r of both spheres [m]")
      ("effect-radius", po::value<double>()->required(), "effect radius r^ >= r [m]")
      ("convention", po::value<std::string>()->default_value("workbench"),
       "workbench: R* = r/2, E* = E/(2(1-nu^2)) as the core uses them; thesis: r and E as listing E.1 used them")
      ("rupture", po::value<std::string>()->default_value("displacement"),
       "where the JKR curve ends: displacement (delta_c) or load (delta_f)")
      ("json", "print JSON instead of a table");
}

/// JKR figures of the converted (or given) parameters, for the table.
void add_jkr_figures(const dem::laws::JkrParameters& p, std::vector<Row>& rows) {
  rows.push_back({"pulloff_force", dem::laws::jkr_pulloff_force(p), "N", "3 pi gamma R (load control)"});
  rows.push_back({"rupture_overlap", dem::laws::jkr_rupture_overlap(p), "m", "delta_c (displacement control)"});
  rows.push_back({"pulloff_overlap", dem::laws::jkr_pulloff_overlap(p), "m", "delta_f (load control)"});
  rows.push_back({"zero_load_radius", dem::laws::jkr_zero_load_radius(p), "m", "a_0"});
}

void print(const std::string& direction, conv::Convention convention, const std::vector<Row>& rows,
           bool json) {
  if (json) {
    nlohmann::json j;
    j["conversion"] = direction;
    j["convention"] = convention == conv::Convention::thesis ? "thesis" : "workbench";
    for (const auto& r : rows) j["values"][r.key] = {{"value", r.value}, {"unit", r.unit}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  reports::MarkdownTable t({"quantity", "value", "unit", "meaning"});
  for (const auto& r : rows) t.add_row({r.key, fmt::format("{:.9g}", r.value), r.unit, r.meaning});
  std::cout << t.render();
}

int linear_to_jkr(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()
      ("stiffness", po::value<double>()->required(), "linear elastic stiffness k_e [N/m]")
      ("cohesive-stiffness", po::value<double>()->required(), "linear cohesive stiffness k_c [N/m]")
      ("poisson", po::value<double>(), "Poisson's ratio nu, to report Young's modulus E (workbench)");
  add_common(opts);
  const auto vm = parse_command(args, kUsage, opts, {});
  if (!vm) return kExitOk;
  const auto convention = parse_convention((*vm)["convention"].as<std::string>());
  const auto rupture = parse_rupture((*vm)["rupture"].as<std::string>());
  const conv::PairGeometry pair{(*vm)["radius"].as<double>(), (*vm)["effect-radius"].as<double>(),
                                (*vm)["max-overlap"].as<double>()};
  const conv::LinearModel linear{(*vm)["stiffness"].as<double>(),
                                 (*vm)["cohesive-stiffness"].as<double>()};
  const conv::JkrModel jkr = conv::linear_to_jkr(linear, pair, convention, rupture);
  const double radius = conv::formula_radius(pair, convention);
  std::vector<Row> rows;
  rows.push_back({"formula_radius", radius, "m", convention == conv::Convention::thesis ? "r (thesis)" : "R* = r/2"});
  rows.push_back({"modulus", jkr.modulus, "Pa",
                  convention == conv::Convention::thesis ? "E as used in eq E.4/E.6 (thesis)"
                                                         : "E* from eq E.4"});
  if (convention == conv::Convention::thesis) {
    rows.push_back({"youngs_modulus", jkr.modulus, "Pa", "E (the thesis uses it unreduced)"});
  } else if (vm->count("poisson") != 0) {
    const double nu = (*vm)["poisson"].as<double>();
    if (!(nu > -1.0 && nu < 0.5)) {
      throw std::invalid_argument(fmt::format("--poisson must be in (-1, 0.5), got {}", nu));
    }
    rows.push_back({"youngs_modulus", conv::youngs_modulus(jkr.modulus, nu, convention), "Pa",
                    "E = 2(1 - nu^2) E*"});
  }
  rows.push_back({"surface_energy", jkr.surface_energy, "J/m^2", "gamma per surface, equal work"});
  rows.push_back({"separation_work", conv::linear_separation_work(linear, pair), "J",
                  "1/2 k_e D^2 - 1/2 k_c (2(r^-r)+D)^2 = JKR work"});
  if (jkr.surface_energy > 0.0) add_jkr_figures({jkr.modulus, radius, jkr.surface_energy}, rows);
  print("linear-to-jkr", convention, rows, vm->count("json") != 0);
  return kExitOk;
}

int jkr_to_linear(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()
      ("youngs-modulus", po::value<double>()->required(), "Young's modulus E [Pa]")
      ("poisson", po::value<double>()->required(), "Poisson's ratio nu")
      ("surface-energy", po::value<double>()->required(), "surface energy gamma per surface [J/m^2]");
  add_common(opts);
  const auto vm = parse_command(args, kUsage, opts, {});
  if (!vm) return kExitOk;
  const auto convention = parse_convention((*vm)["convention"].as<std::string>());
  const auto rupture = parse_rupture((*vm)["rupture"].as<std::string>());
  const double e = (*vm)["youngs-modulus"].as<double>();
  const double nu = (*vm)["poisson"].as<double>();
  if (!(nu > -1.0 && nu < 0.5)) {
    throw std::invalid_argument(fmt::format("--poisson must be in (-1, 0.5), got {}", nu));
  }
  if (!(e > 0.0)) throw std::invalid_argument(fmt::format("--youngs-modulus must be > 0, got {}", e));
  const conv::PairGeometry pair{(*vm)["radius"].as<double>(), (*vm)["effect-radius"].as<double>(),
                                (*vm)["max-overlap"].as<double>()};
  const conv::JkrModel jkr{conv::formula_modulus(e, nu, convention),
                           (*vm)["surface-energy"].as<double>()};
  const conv::LinearModel linear = conv::jkr_to_linear(jkr, pair, convention, rupture);
  const double radius = conv::formula_radius(pair, convention);
  std::vector<Row> rows;
  rows.push_back({"formula_radius", radius, "m", convention == conv::Convention::thesis ? "r (thesis)" : "R* = r/2"});
  rows.push_back({"modulus", jkr.modulus, "Pa",
                  convention == conv::Convention::thesis ? "E as used in eq E.4/E.6 (thesis)"
                                                         : "E* = E/(2(1 - nu^2))"});
  rows.push_back({"normal_stiffness", linear.normal_stiffness, "N/m", "k_e, eq E.4"});
  rows.push_back({"cohesive_stiffness", linear.cohesive_stiffness, "N/m", "k_c, equal work"});
  rows.push_back({"separation_work", conv::linear_separation_work(linear, pair), "J",
                  "JKR work from D to rupture = linear work"});
  if (jkr.surface_energy > 0.0) add_jkr_figures({jkr.modulus, radius, jkr.surface_energy}, rows);
  print("jkr-to-linear", convention, rows, vm->count("json") != 0);
  return kExitOk;
}

}  // namespace

int command_convert(const std::vector<std::string>& args, const Invocation&) {
  if (args.empty()) {
    std::cerr << "demwb convert: missing the conversion (linear-to-jkr or jkr-to-linear)\n\n"
              << kUsage << "\n";
    return kExitUsage;
  }
  if (args[0] == "-h" || args[0] == "--help") {
    std::cout << kUsage << "\n\nrun 'demwb convert linear-to-jkr --help' for the options\n";
    return kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "linear-to-jkr") return linear_to_jkr(rest);
  if (args[0] == "jkr-to-linear") return jkr_to_linear(rest);
  throw std::invalid_argument(fmt::format(
      "unknown conversion '{}' (known: linear-to-jkr, jkr-to-linear)", args[0]));
}

}  // namespace app
