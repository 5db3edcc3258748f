// SPDX-License-Identifier: MIT
#pragma once
// What an interrupted demwb undoes (docs/security.md, "Interrupts"): on SIGINT or SIGTERM it
// kills the process groups of the reference codes still running, removes the partial outputs it
// owns, and exits 130 (SIGINT) or 143 (SIGTERM).
//
// The registry is the one piece of process-wide state in the program: a signal concerns the whole
// process, so whatever must be undone has to be reachable from one place.
#include <sys/types.h>

#include <filesystem>
#include <mutex>

namespace support {

/// Blocks SIGINT and SIGTERM in the calling thread (and so in every thread it starts afterwards)
/// and starts a watcher thread that waits for them, undoes what is registered and exits with
/// 128 + the signal number. Call once, first thing in main(), before any other thread exists.
void install_interrupt_handling();

/// The lock under which a child is forked and registered: the watcher takes it too, so a child is
/// either registered before the watcher looks or forked after the process is gone.
std::mutex& child_registry_mutex();

/// Records the process group `pgid` of a running child (call with child_registry_mutex() held).
void register_child_group(pid_t pgid);

/// Forgets a child group once it has been waited for.
void unregister_child_group(pid_t pgid);

/// Registers a file or directory this process is writing and would leave half-made if
/// interrupted; it is removed on SIGINT/SIGTERM while the guard lives. Moving the guard is not
/// allowed; destroying it (the output is complete, or the path was removed) forgets the path.
class OwnedPathGuard {
 public:
  /// Registers `path` (an empty path registers nothing).
  explicit OwnedPathGuard(std::filesystem::path path);
  /// Registers the output directory `dir` only if it does not exist yet (a directory the user
  /// already had is never removed).
  static OwnedPathGuard if_new(const std::filesystem::path& dir);
  ~OwnedPathGuard();
  OwnedPathGuard(const OwnedPathGuard&) = delete;
  OwnedPathGuard& operator=(const OwnedPathGuard&) = delete;

 private:
  std::filesystem::path path_;
};

}  // namespace support
