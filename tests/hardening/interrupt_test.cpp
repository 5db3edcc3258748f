// SPDX-License-Identifier: MIT
// SIGINT/SIGTERM during a run: demwb kills its reference children, removes the partial outputs it
// created and exits 130/143, leaving no process behind. A watchdog kills demwb if it does not stop.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "fake_engines.hpp"
#include "tests/app/demwb_process.hpp"

namespace interrupt_test {

using namespace demwb_hardening;
using demwb_e2e::canonical;
using demwb_e2e::scratch;

/// Starts demwb with `args` without waiting (stdout and stderr to `log`).
pid_t start_demwb(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> argv{DEMWB_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> c;
  for (auto& a : argv) c.push_back(a.data());
  c.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execv(c[0], c.data());
    ::_exit(127);
  }
  return pid;
}

/// Waits up to `seconds` for `pred`.
template <class Pred>
bool wait_for(Pred pred, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return pred();
}

/// Pids listed in `file`.
std::vector<std::string> pids_in(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  std::string pid;
  while (in >> pid) out.push_back(pid);
  return out;
}

/// Interrupts a suite while fake lmp processes hang, and checks the clean stop.
void interrupt_suite(int signal_number, int expected_exit, const std::string& name) {
  const fs::path pids = scratch(name + "-pids");
  const fs::path fake = fake_lammps(scratch(name + "-fake"), Fault::hang, "/bin/false", pids);
  // The probe of this fake is the real banner-less /bin/false: the version is "unknown", the run
  // proceeds, and the run itself hangs.
  const fs::path out = scratch(name + "-out");
  const fs::path log = scratch(name + "-log");
  const pid_t demwb = start_demwb({"suite", "canonical", "-j", "2", "--no-cache", "--lammps", fake.string(), "-o",
                                   out.string()},
                                  log);
  ASSERT_GT(demwb, 0);
  const bool hung = wait_for([&] { return !pids_in(pids).empty(); }, 60);
  ASSERT_TRUE(hung) << "no fake lmp started within 60 s: " << support::read_file(log);
  ASSERT_TRUE(fs::exists(out)) << "the suite made no output directory yet";
  ::kill(demwb, signal_number);
  int status = 0;
  const bool stopped = wait_for([&] { return ::waitpid(demwb, &status, WNOHANG) == demwb; }, 10);
  if (!stopped) {  // the watchdog: never leave a hung demwb behind a failed test
    ::kill(demwb, SIGKILL);
    ::waitpid(demwb, &status, 0);
    FAIL() << "demwb did not stop within 10 s of the signal";
  }
  ASSERT_TRUE(WIFEXITED(status)) << "demwb died of a signal instead of exiting";
  EXPECT_EQ(WEXITSTATUS(status), expected_exit);
  for (const auto& pid : pids_in(pids)) {
    EXPECT_TRUE(wait_for([&] { return process_ended(pid); }, 2)) << "fake lmp " << pid << " survived demwb";
  }
  EXPECT_FALSE(fs::exists(out)) << "the partial output directory it created was left behind";
  const std::string said = support::read_file(log);
  EXPECT_NE(said.find("interrupted by"), std::string::npos) << said;
}

TEST(Interrupts, SigtermStopsTheReferenceRunsAndExits143) { interrupt_suite(SIGTERM, 143, "sigterm"); }

TEST(Interrupts, SigintStopsTheReferenceRunsAndExits130) { interrupt_suite(SIGINT, 130, "sigint"); }

TEST(Interrupts, AnOutputDirectoryTheUserAlreadyHadIsKept) {
  const fs::path pids = scratch("keep-pids");
  const fs::path fake = fake_lammps(scratch("keep-fake"), Fault::hang, "/bin/false", pids);
  const fs::path out = scratch("keep-out");
  fs::create_directories(out);
  support::write_file(out / "mine.txt", "the user's file\n");
  const pid_t demwb = start_demwb({"run", canonical("single_collision"), "--engine", "lammps", "--no-cache", "--lammps",
                                   fake.string(), "-o", out.string()},
                                  scratch("keep-log"));
  ASSERT_TRUE(wait_for([&] { return !pids_in(pids).empty(); }, 30));
  ::kill(demwb, SIGTERM);
  int status = 0;
  if (!wait_for([&] { return ::waitpid(demwb, &status, WNOHANG) == demwb; }, 10)) {
    ::kill(demwb, SIGKILL);
    ::waitpid(demwb, &status, 0);
    FAIL() << "demwb did not stop within 10 s of SIGTERM";
  }
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_TRUE(fs::exists(out / "mine.txt"));
  // The run's own scratch directory (the fake's deck) was removed.
  std::size_t runs = 0;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(out, ec)) {
    runs += e.path().filename().string().starts_with("lammps-run-") ? 1 : 0;
  }
  EXPECT_EQ(runs, 0U);
}

}  // namespace
