// SPDX-License-Identifier: MIT
// Reference binaries chosen with --lammps/--yade/--liggghts (or DEMWB_LAMMPS/…) that fail, hang or
// write damaged output: every fault is an `error` (absent: `missing`) that fails the run, and a
// hung binary is reported within --timeout + 10 s.
#include <signal.h>

#include <chrono>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reference/yade/yade_installation.hpp"
#include "fake_engines.hpp"
#include "tests/app/demwb_process.hpp"

namespace fake_binaries_test {

using namespace demwb_hardening;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
using Json = nlohmann::json;

/// Every pid listed in `file` (one per line) has ended.
void expect_all_ended(const fs::path& file) {
  std::ifstream in(file);
  std::string pid;
  int seen = 0;
  while (in >> pid) {
    ++seen;
    EXPECT_TRUE(process_ended(pid)) << "process " << pid << " of a fake binary is still running";
  }
  EXPECT_GT(seen, 0) << "the fake binary never started (" << file << ")";
}

/// What one run of single_collision on `engine` reported.
struct Reported {
  int exit_code;
  std::string status;
  std::string reason;
  double seconds;
  std::string output;
};

/// Runs single_collision on `engine` alone with `extra` options (no cache), timing it. Alone: the
/// case's matched line, which would add the other code, the core in both codes' numerics and their
/// time-step checks, is dropped (a real run of the other code has no place in a hung run's time bound).
Reported run_single(const std::string& engine, std::vector<std::string> extra, const std::string& name,
                    const std::map<std::string, std::string>& env = {}) {
  const fs::path out = scratch(name);
  std::vector<std::string> args{"run", demwb_e2e::canonical_unmatched("single_collision"), "--engine", engine,
                                "--no-cache", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto start = std::chrono::steady_clock::now();
  const auto r = demwb(args, env, 120);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Reported rep{r.exit_code, "", "", seconds, r.out + r.err};
  std::error_code ec;
  if (fs::exists(out / "results.json", ec)) {
    const Json j = Json::parse(support::read_file(out / "results.json"));
    rep.status = j["engines"][engine]["status"];
    rep.reason = j["engines"][engine].value("reason", "");
  }
  return rep;
}

bool have_lammps() { return support::find_program("lmp").has_value(); }

/// Runs single_collision on `engine` with a fake made by `make_fake(fault, label)` for each fault
/// that returns (fails, garbage, NaN, truncated) and checks each is an error saying what went
/// wrong; `failure_says` is the fake's own failure message.
void expect_every_fault_an_error(const std::string& engine, const std::function<fs::path(Fault, const std::string&)>& make_fake,
                                 const std::string& failure_says) {
  const std::vector<std::pair<Fault, std::string>> faults = {
      {Fault::exit_1, failure_says},
      {Fault::garbage, "trace."},  // the trace file's name and line: it does not parse
      {Fault::nan, "non-finite"},
      {Fault::truncated, "values"},  // "13 values for 17 columns" / "expected 15 values, found 11"
  };
  for (const auto& [fault, says] : faults) {
    const auto label = engine + "-" + std::to_string(static_cast<int>(fault));
    const fs::path fake = make_fake(fault, label);
    const Reported r = run_single(engine, {"--" + engine, fake.string()}, "fake-run-" + label);
    EXPECT_EQ(r.exit_code, 1) << label << r.output;
    EXPECT_EQ(r.status, "error") << label << ": " << r.reason;
    EXPECT_NE(r.reason.find(says), std::string::npos) << label << ": " << r.reason;
  }
}

TEST(FakeLammps, EveryFaultIsAnErrorThatFailsTheRun) {
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path lmp = *support::find_program("lmp");
  expect_every_fault_an_error(
      "lammps",
      [&](Fault fault, const std::string& label) {
        return fake_lammps(scratch("fake-" + label), fault, lmp, scratch("fake-pid-" + label));
      },
      "deliberate failure of a fake lmp");
}

TEST(FakeLammps, AnAbsentBinaryIsMissingAndFailsTheRun) {
  // No baselines to fall back on (an empty directory): the absent code is `missing`.
  const std::string none = scratch("no-baselines").string();
  fs::create_directories(none);
  const Reported flag = run_single("lammps", {"--lammps", "/nonexistent/lmp", "--baselines", none}, "absent-lmp");
  EXPECT_EQ(flag.exit_code, 1) << flag.output;
  EXPECT_EQ(flag.status, "missing");
  EXPECT_NE(flag.reason.find("/nonexistent/lmp"), std::string::npos) << flag.reason;
  const Reported env =
      run_single("lammps", {"--baselines", none}, "absent-lmp-env", {{"DEMWB_LAMMPS", "/nonexistent/lmp-from-env"}});
  EXPECT_EQ(env.status, "missing");
  EXPECT_NE(env.reason.find("lmp-from-env"), std::string::npos) << env.reason;
}

TEST(FakeLammps, AHungRunIsReportedWithinTheTimeoutAndKilled) {
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path pids = scratch("hang-lmp-pid");
  const fs::path fake = fake_lammps(scratch("hang-lmp"), Fault::hang, *support::find_program("lmp"), pids);
  const Reported r = run_single("lammps", {"--lammps", fake.string(), "--timeout", "3"}, "hang-lmp-run");
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("timed out"), std::string::npos) << r.reason;
  EXPECT_LT(r.seconds, 3 + 10);
  expect_all_ended(pids);
}

TEST(FakeLammps, ABinaryThatHangsOnTheVersionProbeIsReportedWithinTheTimeout) {
  const fs::path pids = scratch("hang-probe-pid");
  const fs::path fake = fake_lammps(scratch("hang-probe"), Fault::hang_probe, "/bin/false", pids);
  const Reported r = run_single("lammps", {"--lammps", fake.string(), "--timeout", "4"}, "hang-probe-run");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("did not finish an empty run within 4 s"), std::string::npos) << r.reason;
  EXPECT_LT(r.seconds, 4 + 10);
  expect_all_ended(pids);
}

bool have_liggghts() { return support::find_program("liggghts").has_value(); }

TEST(FakeLiggghts, EveryFaultIsAnErrorThatFailsTheRun) {
  if (!have_liggghts()) GTEST_SKIP() << "liggghts is not installed (scripts/setup.sh installs it)";
  const fs::path real = *support::find_program("liggghts");
  const std::vector<std::pair<Fault, std::string>> faults = {
      {Fault::exit_1, "deliberate failure of a fake liggghts"},
      {Fault::garbage, "thermo"},  // the log holds no thermo table any more
      {Fault::nan, "non-finite"},
      {Fault::truncated, "thermo"},  // the table is gone or short
  };
  for (const auto& [fault, says] : faults) {
    const auto label = "liggghts-" + std::to_string(static_cast<int>(fault));
    const fs::path fake = fake_liggghts(scratch("fake-" + label), fault, real, scratch("fake-pid-" + label));
    const Reported r = run_single("liggghts", {"--liggghts", fake.string()}, "fake-run-" + label);
    EXPECT_EQ(r.exit_code, 1) << label << r.output;
    EXPECT_EQ(r.status, "error") << label << ": " << r.reason;
    EXPECT_NE(r.reason.find(says), std::string::npos) << label << ": " << r.reason;
  }
}

TEST(FakeLiggghts, ACrashBySignalIsAnErrorNamingTheSignal) {
  if (!have_liggghts()) GTEST_SKIP() << "liggghts is not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratch("crash-liggghts");
  fs::create_directories(dir);
  const fs::path fake = dir / "liggghts";
  write_script(fake, fmt::format("for a in \"$@\"; do [ \"$a\" = /dev/null ] && exec {} \"$@\"; done\nkill -SEGV $$\n",
                                 support::find_program("liggghts")->string()));
  const Reported r = run_single("liggghts", {"--liggghts", fake.string()}, "crash-liggghts-run");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("signal 11"), std::string::npos) << r.reason;
}

TEST(FakeLiggghts, AnErrorOnTheScreenAloneIsFoundWithAnyExitStatus) {
  // LIGGGHTS' Error::one writes to the screen only (and aborts unflushed, which stdbuf undoes).
  for (const int status : {1, 0}) {
    const fs::path dir = scratch("screen-error-" + std::to_string(status));
    fs::create_directories(dir);
    const fs::path fake = dir / "liggghts";
    write_script(fake, fmt::format("for a in \"$@\"; do [ \"$a\" = /dev/null ] && exec {} \"$@\"; done\n"
                                   "echo 'ERROR on proc 0: Invalid atom vector in variable formula (variable.cpp:1)'\n"
                                   "exit {}\n",
                                   have_liggghts() ? support::find_program("liggghts")->string() : "/bin/false", status));
    const Reported r = run_single("liggghts", {"--liggghts", fake.string()}, "screen-error-run-" + std::to_string(status));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_EQ(r.status, "error");
    EXPECT_NE(r.reason.find("Invalid atom vector in variable formula"), std::string::npos) << r.reason;
  }
}

TEST(FakeLiggghts, AnAbsentBinaryIsMissingAndFailsTheRun) {
  const std::string none = scratch("no-liggghts-baselines").string();
  fs::create_directories(none);
  const Reported flag =
      run_single("liggghts", {"--liggghts", "/nonexistent/liggghts", "--baselines", none}, "absent-liggghts");
  EXPECT_EQ(flag.exit_code, 1) << flag.output;
  EXPECT_EQ(flag.status, "missing");
  EXPECT_NE(flag.reason.find("/nonexistent/liggghts"), std::string::npos) << flag.reason;
  const Reported env = run_single("liggghts", {"--baselines", none}, "absent-liggghts-env",
                                  {{"DEMWB_LIGGGHTS", "/nonexistent/liggghts-from-env"}});
  EXPECT_EQ(env.status, "missing");
  EXPECT_NE(env.reason.find("liggghts-from-env"), std::string::npos) << env.reason;
}

TEST(FakeLiggghts, AHungRunIsReportedWithinTheTimeoutAndKilled) {
  if (!have_liggghts()) GTEST_SKIP() << "liggghts is not installed (scripts/setup.sh installs it)";
  const fs::path pids = scratch("hang-liggghts-pid");
  const fs::path fake = fake_liggghts(scratch("hang-liggghts"), Fault::hang, *support::find_program("liggghts"), pids);
  const Reported r = run_single("liggghts", {"--liggghts", fake.string(), "--timeout", "3"}, "hang-liggghts-run");
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("timed out"), std::string::npos) << r.reason;
  EXPECT_LT(r.seconds, 3 + 10);
  expect_all_ended(pids);
}

TEST(FakeLiggghts, ABinaryThatHangsOnTheVersionProbeIsReportedWithinTheTimeout) {
  const fs::path pids = scratch("hang-probe-liggghts-pid");
  const fs::path fake = fake_liggghts(scratch("hang-probe-liggghts"), Fault::hang_probe, "/bin/false", pids);
  const Reported r = run_single("liggghts", {"--liggghts", fake.string(), "--timeout", "4"}, "hang-probe-liggghts-run");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("did not finish an empty run within 4 s"), std::string::npos) << r.reason;
  EXPECT_LT(r.seconds, 4 + 10);
  expect_all_ended(pids);
}

/// The installed YADE's interpreter and modules, if any.
std::optional<reference::yade::YadeInstallation> installed_yade() {
  return reference::yade::find_yade_installation("yade").install;
}

TEST(FakeYade, EveryFaultIsAnErrorThatFailsTheRun) {
  const auto yade = installed_yade();
  if (!yade) GTEST_SKIP() << "YADE is not installed (scripts/setup.sh installs it)";
  expect_every_fault_an_error(
      "yade",
      [&](Fault fault, const std::string& label) {
        return fake_yade(scratch("fake-" + label), fault, yade->python, yade->module_dir, scratch("fake-pid-" + label));
      },
      "deliberate failure of a fake python");
}

TEST(FakeYade, AnAbsentOrForeignLauncherIsMissingAndFailsTheRun) {
  const std::string none = scratch("no-yade-baselines").string();
  fs::create_directories(none);
  const Reported absent = run_single("yade", {"--yade", "/nonexistent/yade", "--baselines", none}, "absent-yade");
  EXPECT_EQ(absent.exit_code, 1) << absent.output;
  EXPECT_EQ(absent.status, "missing");
  EXPECT_NE(absent.reason.find("/nonexistent/yade"), std::string::npos) << absent.reason;
  const Reported foreign = run_single("yade", {"--baselines", none}, "foreign-yade", {{"DEMWB_YADE", "/bin/sh"}});
  EXPECT_EQ(foreign.status, "missing");
  EXPECT_NE(foreign.reason.find("not a YADE launcher"), std::string::npos) << foreign.reason;
}

TEST(FakeYade, AHungRunIsReportedWithinTheTimeoutAndKilled) {
  const auto yade = installed_yade();
  if (!yade) GTEST_SKIP() << "YADE is not installed (scripts/setup.sh installs it)";
  const fs::path pids = scratch("hang-yade-pid");
  const fs::path fake = fake_yade(scratch("hang-yade"), Fault::hang, yade->python, yade->module_dir, pids);
  const Reported r = run_single("yade", {"--yade", fake.string(), "--timeout", "3"}, "hang-yade-run");
  EXPECT_EQ(r.status, "error");
  EXPECT_NE(r.reason.find("timed out"), std::string::npos) << r.reason;
  EXPECT_LT(r.seconds, 3 + 10);
  expect_all_ended(pids);
}

TEST(Engines, ShowsWhereEachBinaryWasFound) {
  const auto r = demwb({"engines", "--lammps", "/nonexistent/lmp", "--yade", "/bin/sh", "--liggghts", "/nonexistent/lig"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| liggghts | missing | — | '/nonexistent/lig' not found"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| lammps | missing | — | '/nonexistent/lmp' not found"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("/bin/sh is not a YADE launcher"), std::string::npos) << r.out;
  if (installed_yade()) {
    const auto found = demwb({"engines"});
    EXPECT_NE(found.out.find("| yade | installed |"), std::string::npos) << found.out;
    EXPECT_NE(found.out.find("modules "), std::string::npos) << found.out;
  }
}

/// Eight glass spheres dropped into a box for a few steps, on LAMMPS alone: a case a sweep can seed
/// (a population) and LAMMPS expresses.
std::string tiny_pour() {
  return R"(
[case]
name = "tiny_pour"
[model]
normal = "hertz"
damping = "tsuji"
clamp_tensile = true
tangential = "mindlin_8g"
mindlin_form = "incremental"
[materials.glass]
density = 2500.0
youngs_modulus = 6.0e10
poisson_ratio = 0.22
restitution = 0.8
friction = 0.4
tangential_damping_ratio = 0.0
[[populations]]
material = "glass"
seed = 1
arrangement = "simple_cubic"
count = 8
spacing = 4.4e-4
region = { shape = "box", min = [0.0, 0.0, 0.0], max = [2.0e-3, 2.0e-3, 2.0e-3] }
size = { distribution = "monodisperse", radius = 2.0e-4 }
[[walls]]
type = "box"
name = "box"
min = [0.0, 0.0, 0.0]
max = [2.0e-3, 2.0e-3, 2.0e-3]
material = "glass"
open_faces = ["z+"]
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-7
duration = 1.0e-5
[output]
snapshot_times = [1.0e-5]
[compare]
engines = ["lammps"]
reference = "lammps"
metrics = ["coordination_number"]
packing = { min = [0.0, 0.0, 0.0], max = [2.0e-3, 2.0e-3, 2.0e-3] }
)";
}

TEST(FakeLammps, ASweepFilesTimeoutKillsAHungRunUnderSweepAndRefresh) {
  // [sweep] timeout = 3 replaces the 600 s default: without it this test would wait ten minutes.
  // `demwb refresh --sweep` forwards only a --timeout the user gave, so the file's applies there too.
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratch("sweep-timeout-files");
  support::write_file(dir / "tiny.toml", tiny_pour());
  support::write_file(dir / "sweeps" / "hung.toml", R"([sweep]
name = "hung"
case = "../tiny.toml"
seeds = [1]
timeout = 3
[[parameters]]
key = "materials.glass.friction"
values = [0.4]
)");
  const fs::path pids = scratch("sweep-timeout-pid");
  const fs::path fake = fake_lammps(scratch("sweep-timeout-lmp"), Fault::hang, *support::find_program("lmp"), pids);
  const fs::path baselines = scratch("sweep-timeout-baselines");
  fs::create_directories(baselines);
  for (const bool refresh : {false, true}) {
    SCOPED_TRACE(refresh ? "refresh --sweep" : "sweep");
    const fs::path out = scratch(refresh ? "sweep-timeout-refresh" : "sweep-timeout-sweep");
    std::vector<std::string> args =
        refresh ? std::vector<std::string>{"refresh", "--sweep", (dir / "sweeps" / "hung.toml").string(), "-o",
                                           out.string(), "--baselines", baselines.string()}
                : std::vector<std::string>{"sweep", (dir / "sweeps" / "hung.toml").string(), "-o", out.string()};
    for (const char* a : {"--no-cache", "--lammps"}) args.emplace_back(a);
    args.push_back(fake.string());
    const auto start = std::chrono::steady_clock::now();
    const auto r = demwb(args, {}, 120);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, refresh ? 2 : 1) << r.out << r.err;  // refresh: an error, nothing stored
    EXPECT_LT(seconds, 3 + 10 + 20) << "the sweep's timeout was not applied";
    const std::string csv = support::read_file((refresh ? out / "hung" : out) / "sweep.csv");
    EXPECT_NE(csv.find("LAMMPS timed out after"), std::string::npos) << csv;
    expect_all_ended(pids);
  }
  EXPECT_FALSE(fs::exists(baselines / "sweeps" / "hung")) << "a failed sweep stored its results";
}

}  // namespace
