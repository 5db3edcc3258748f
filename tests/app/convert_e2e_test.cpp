// SPDX-License-Identifier: MIT
// End-to-end tests of `demwb convert` (thesis appendix E): real process, real output.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "support/text_file.hpp"

namespace convert_e2e_test {

using demwb_e2e::demwb;
namespace fs = std::filesystem;

/// The benchmark pair of thesis table 5.1: r = 5 mm, effect radius 7.5 mm, δ_max = r/20.
const std::vector<std::string> kPair{"--max-overlap", "2.5e-4", "--radius", "5e-3",
                                     "--effect-radius", "7.5e-3"};

/// A double printed with enough digits to round-trip.
std::string fmt_double(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::vector<std::string> with_pair(std::vector<std::string> args) {
  args.insert(args.end(), kPair.begin(), kPair.end());
  return args;
}

TEST(DemwbConvert, LinearToJkrReproducesTheThesisBenchmarkPairing) {
  const auto r = demwb(with_pair({"convert", "linear-to-jkr", "--stiffness", "1e5",
                                  "--cohesive-stiffness", "1e2", "--convention", "thesis", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["convention"], "thesis");
  EXPECT_NEAR(j["values"]["youngs_modulus"]["value"].get<double>(), 8.4e7, 2e-3 * 8.4e7);
  EXPECT_NEAR(j["values"]["surface_energy"]["value"].get<double>(), 121.5, 5e-3 * 121.5);
  EXPECT_EQ(j["values"]["surface_energy"]["unit"], "J/m^2");
}

TEST(DemwbConvert, RoundTripThroughBothCommandsReturnsTheLinearParameters) {
  const auto forward = demwb(with_pair({"convert", "linear-to-jkr", "--stiffness", "1e5",
                                        "--cohesive-stiffness", "1e2", "--poisson", "0.3", "--json"}));
  ASSERT_EQ(forward.exit_code, 0) << forward.err;
  const auto f = nlohmann::json::parse(forward.out);
  const double e = f["values"]["youngs_modulus"]["value"];
  const double gamma = f["values"]["surface_energy"]["value"];
  const auto back = demwb(with_pair({"convert", "jkr-to-linear", "--youngs-modulus",
                                     fmt_double(e), "--poisson", "0.3", "--surface-energy",
                                     fmt_double(gamma), "--json"}));
  ASSERT_EQ(back.exit_code, 0) << back.err;
  const auto b = nlohmann::json::parse(back.out);
  EXPECT_NEAR(b["values"]["normal_stiffness"]["value"].get<double>(), 1e5, 1e-8 * 1e5);
  EXPECT_NEAR(b["values"]["cohesive_stiffness"]["value"].get<double>(), 1e2, 1e-7 * 1e2);
}

TEST(DemwbConvert, PrintsATableByDefault) {
  const auto r = demwb(with_pair({"convert", "jkr-to-linear", "--youngs-modulus", "8.4e7",
                                  "--poisson", "0.3", "--surface-energy", "121.5"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| quantity | value | unit | meaning |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| cohesive_stiffness |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| pulloff_force |"), std::string::npos) << r.out;
}

TEST(DemwbConvert, HelpExitsZeroAndBadArgumentsExitTwoWithAMessage) {
  EXPECT_EQ(demwb({"convert", "--help"}).exit_code, 0);
  const auto help = demwb({"convert", "linear-to-jkr", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage: demwb convert"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--cohesive-stiffness"), std::string::npos) << help.out;

  EXPECT_EQ(demwb({"convert"}).exit_code, 2);
  const auto unknown = demwb({"convert", "hertz-to-jkr"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown conversion 'hertz-to-jkr'"), std::string::npos) << unknown.err;
  const auto missing = demwb(with_pair({"convert", "linear-to-jkr", "--stiffness", "1e5"}));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("cohesive-stiffness"), std::string::npos) << missing.err;
  const auto negative = demwb(with_pair({"convert", "linear-to-jkr", "--stiffness", "-1",
                                         "--cohesive-stiffness", "1e2"}));
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_NE(negative.err.find("k_e must be"), std::string::npos) << negative.err;
  const auto not_a_number = demwb(with_pair({"convert", "linear-to-jkr", "--stiffness", "stiff",
                                             "--cohesive-stiffness", "1e2"}));
  EXPECT_EQ(not_a_number.exit_code, 2);
  const auto poisson = demwb(with_pair({"convert", "jkr-to-linear", "--youngs-modulus", "8.4e7",
                                        "--poisson", "0.7", "--surface-energy", "121.5"}));
  EXPECT_EQ(poisson.exit_code, 2);
  EXPECT_NE(poisson.err.find("--poisson"), std::string::npos) << poisson.err;
}

}  // namespace
