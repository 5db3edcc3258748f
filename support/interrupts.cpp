// SPDX-License-Identifier: MIT
#include "support/interrupts.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace support {
namespace {

/// Everything an interrupt must undo.
struct Registry {
  std::mutex children_mutex;
  std::vector<pid_t> children;  ///< process groups of running children
  std::mutex paths_mutex;
  std::vector<std::filesystem::path> paths;  ///< partial outputs, in registration order
};

Registry& registry() {
  static Registry r;
  return r;
}

/// The signals demwb turns into a clean stop.
sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

/// Waits for SIGINT/SIGTERM, then kills the registered children, removes the registered paths
/// (newest first) and exits. Runs in its own thread, so it may allocate and lock.
[[noreturn]] void watch(sigset_t set) {
  int sig = 0;
  while (sigwait(&set, &sig) != 0) {
  }
  Registry& r = registry();
  r.children_mutex.lock();  // held until _exit: no child is forked after this point
  for (const pid_t group : r.children) ::kill(-group, SIGKILL);
  const std::size_t killed = r.children.size();
  r.paths_mutex.lock();
  std::size_t removed = 0;
  for (auto it = r.paths.rbegin(); it != r.paths.rend(); ++it) {
    std::error_code ec;
    if (std::filesystem::remove_all(*it, ec) > 0) ++removed;
  }
  const std::string message = "demwb: interrupted by " + std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") +
                              ": killed " + std::to_string(killed) + " reference run(s), removed " +
                              std::to_string(removed) + " partial output(s)\n";
  const ssize_t written = ::write(STDERR_FILENO, message.data(), message.size());
  static_cast<void>(written);
  ::_exit(128 + sig);
}

}  // namespace

void install_interrupt_handling() {
  sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread(watch, set).detach();
}

std::mutex& child_registry_mutex() { return registry().children_mutex; }

void register_child_group(pid_t pgid) { registry().children.push_back(pgid); }

void unregister_child_group(pid_t pgid) {
  Registry& r = registry();
  const std::lock_guard lock(r.children_mutex);
  r.children.erase(std::remove(r.children.begin(), r.children.end(), pgid), r.children.end());
}

OwnedPathGuard::OwnedPathGuard(std::filesystem::path path) : path_(std::move(path)) {
  if (path_.empty()) return;
  Registry& r = registry();
  const std::lock_guard lock(r.paths_mutex);
  r.paths.push_back(path_);
}

OwnedPathGuard OwnedPathGuard::if_new(const std::filesystem::path& dir) {
  std::error_code ec;
  return OwnedPathGuard(std::filesystem::exists(dir, ec) || ec ? std::filesystem::path() : std::filesystem::absolute(dir));
}

OwnedPathGuard::~OwnedPathGuard() {
  if (path_.empty()) return;
  Registry& r = registry();
  const std::lock_guard lock(r.paths_mutex);
  const auto it = std::find(r.paths.rbegin(), r.paths.rend(), path_);
  if (it != r.paths.rend()) r.paths.erase(std::next(it).base());
}

}  // namespace support
