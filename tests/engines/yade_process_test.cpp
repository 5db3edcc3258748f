// SPDX-License-Identifier: MIT
// How the YADE driver runs YADE: no network listeners, private work directories, failures
// reported with the Python traceback.
#include <chrono>
#include <fstream>
#include <future>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "compare/case_outcome.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/yade/python_literals.hpp"
#include "reference/yade/yade_process.hpp"
#include "support/text_file.hpp"
#include "yade_test_support.hpp"

namespace yade_process_test {

using namespace demwb_yade_test;

/// A TCP socket in state LISTEN (0A) from /proc/net/tcp or tcp6.
struct Listener {
  unsigned port;
  unsigned long inode;
};

std::vector<Listener> listening_sockets() {
  std::vector<Listener> out;
  for (const char* file : {"/proc/net/tcp", "/proc/net/tcp6"}) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::istringstream f(line);
      std::string slot, local, remote, state, queues, timer, retransmit, uid, timeout;
      unsigned long inode = 0;
      f >> slot >> local >> remote >> state >> queues >> timer >> retransmit >> uid >> timeout >> inode;
      if (state != "0A") continue;
      const unsigned port = static_cast<unsigned>(std::stoul(local.substr(local.rfind(':') + 1), nullptr, 16));
      out.push_back({port, inode});
    }
  }
  return out;
}

/// Socket inodes among the open file descriptors of process `pid`.
std::set<unsigned long> socket_inodes(const std::string& pid) {
  std::set<unsigned long> out;
  std::error_code ec;
  for (const auto& fd : std::filesystem::directory_iterator("/proc/" + pid + "/fd", ec)) {
    const std::string target = std::filesystem::read_symlink(fd.path(), ec).string();
    if (target.starts_with("socket:[")) out.insert(std::stoul(target.substr(8)));
  }
  return out;
}

/// Listening sockets owned by `pid`, plus listeners on YADE's server ports (9000–9100 TCP
/// prompt, 21000–21100 XMLRPC) that are not in `before`.
std::vector<Listener> suspicious_listeners(const std::string& pid, const std::vector<Listener>& before) {
  const auto owned = socket_inodes(pid);
  std::vector<Listener> out;
  for (const auto& l : listening_sockets()) {
    const bool yade_port = (l.port >= 9000 && l.port <= 9100) || (l.port >= 21000 && l.port <= 21100);
    bool existed = false;
    for (const auto& b : before) existed = existed || (b.inode == l.inode);
    if (owned.count(l.inode) != 0 || (yade_port && !existed)) out.push_back(l);
  }
  return out;
}

/// Waits up to 30 s for `file` to exist and returns its content.
std::string wait_for(const std::filesystem::path& file) {
  for (int i = 0; i < 3000 && !std::filesystem::exists(file); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // let the writer finish
  return std::filesystem::exists(file) ? support::read_file(file) : "";
}

TEST(YadeProcess, ImportedYadeOpensNoListeningSocket) {
  DEMWB_REQUIRE_YADE();
  const auto dir = scratch("listen");
  const auto pid_file = dir / "pid";
  const auto opened_file = dir / "opened";
  // After `import yade` (done by the runner) the script reports its pid and idles; then, as a
  // check that the scanner sees listeners at all, it opens one itself.
  const std::string script =
      "import os, time, socket\n"
      "open(" + reference::yade::py_string((pid_file.string() + ".tmp")) + ", 'w').write(str(os.getpid()))\n"
      "os.rename(" + reference::yade::py_string(pid_file.string() + ".tmp") + ", " +
      reference::yade::py_string(pid_file.string()) + ")\n"
      "time.sleep(1.0)\n"
      "s = socket.socket(); s.bind(('127.0.0.1', 0)); s.listen(1)\n"
      "open(" + reference::yade::py_string(opened_file.string()) + ", 'w').write(str(s.getsockname()[1]))\n"
      "time.sleep(1.0)\n";
  const auto before = listening_sockets();
  auto run = std::async(std::launch::async, [&] {
    return reference::yade::run_yade_script(reference::yade::default_yade_installation(), script, dir, 60.0);
  });
  const std::string pid = wait_for(pid_file);
  ASSERT_FALSE(pid.empty()) << "the YADE script did not start";
  for (int i = 0; i < 10; ++i) {  // ~0.5 s of the 1 s idle time
    EXPECT_TRUE(suspicious_listeners(pid, before).empty()) << "listener while YADE runs";
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string port = wait_for(opened_file);
  ASSERT_FALSE(port.empty());
  const auto seen = suspicious_listeners(pid, before);  // the scanner does see a real listener
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].port, std::stoul(port));
  const auto outcome = run.get();
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure << "\n" << outcome.log_tail;
}

TEST(YadeProcess, ConcurrentRunsUseTheirOwnDirectories) {
  DEMWB_REQUIRE_YADE();
  const cases::Scene scene = canonical("single_collision.toml");
  const auto dir = scratch("concurrent");
  auto run = [&] { return reference::run_engine(reference::YadeEngine{}, scene, {dir, 120.0}); };
  auto a = std::async(std::launch::async, run);
  auto b = std::async(std::launch::async, run);
  const auto ra = a.get();
  const auto rb = b.get();
  ASSERT_EQ(ra.status, cases::RunStatus::ok) << ra.reason << "\n" << ra.log_tail;
  ASSERT_EQ(rb.status, cases::RunStatus::ok) << rb.reason << "\n" << rb.log_tail;
  EXPECT_NE(ra.scratch_dir, rb.scratch_dir);
  EXPECT_FALSE(ra.scratch_dir.empty());
  for (const auto& name : ra.trace.columns()) {
    EXPECT_EQ(*ra.trace.column(name), *rb.trace.column(name)) << name;
  }
}

TEST(YadeProcess, ExceptionInsideTheRunIsAnErrorWithTraceback) {
  DEMWB_REQUIRE_YADE();
  const std::string script =
      "def explode():\n"
      "    raise RuntimeError('deliberate failure at iteration %d' % O.iter)\n"
      "O.engines = [PyRunner(command='explode()', iterPeriod=5)]\n"
      "O.dt = 1e-3\n"
      "O.run(10, True)\n";
  const auto outcome = reference::yade::run_yade_script(reference::yade::default_yade_installation(),
                                                        script, scratch("raises"), 60.0);
  EXPECT_EQ(outcome.process.exit_code, 1);
  EXPECT_NE(outcome.failure.find("YADE script failed with exit code 1"), std::string::npos) << outcome.failure;
  EXPECT_NE(outcome.log_tail.find("Traceback"), std::string::npos) << outcome.log_tail;
  EXPECT_NE(outcome.log_tail.find("deliberate failure at iteration 5"), std::string::npos) << outcome.log_tail;
}

TEST(YadeProcess, BrokenYadeGivesErrorThatNeverPassesComparison) {
  // A stand-in `yade` package that raises on import, under the real interpreter.
  DEMWB_REQUIRE_YADE();
  const auto fake = scratch("fake-module");
  support::write_file(fake / "yade" / "config.py", "version='0.0-broken'\n");
  support::write_file(fake / "yade" / "__init__.py", "raise ImportError('broken yade build')\n");
  const reference::YadeEngine engine{{reference::yade::default_yade_installation().python, fake}};
  ASSERT_EQ(engine.version(), "YADE 0.0-broken");
  const cases::Scene scene = canonical("single_collision.toml");
  const auto yade = reference::run_engine(engine, scene, {scratch("broken-run"), 60.0});
  EXPECT_EQ(yade.status, cases::RunStatus::error);
  EXPECT_NE(yade.reason.find("ImportError: broken yade build"), std::string::npos) << yade.reason;
  EXPECT_NE(yade.log_tail.find("Traceback"), std::string::npos) << yade.log_tail;
  const auto analytic = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  const auto outcome = comparison::evaluate_runs(scene, {analytic, yade});
  ASSERT_FALSE(outcome.comparisons.empty());
  for (const auto& c : outcome.comparisons) {
    EXPECT_EQ(c.status, comparison::Status::error) << c.metric;
  }
  EXPECT_FALSE(comparison::is_green(comparison::worst_status(outcome)));
}

TEST(YadeProcess, TimeoutKillsTheRun) {
  DEMWB_REQUIRE_YADE();
  const auto outcome = reference::yade::run_yade_script(reference::yade::default_yade_installation(),
                                                        "import time\ntime.sleep(30)\n",
                                                        scratch("timeout"), 1.0);
  EXPECT_TRUE(outcome.process.timed_out);
  EXPECT_NE(outcome.failure.find("timed out"), std::string::npos) << outcome.failure;
}

}  // namespace
