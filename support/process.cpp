// SPDX-License-Identifier: MIT
#include "support/process.hpp"

#include "support/interrupts.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>
#include <thread>

namespace support {
namespace {

/// Opens `target` for a child's stdout/stderr and dup2s it onto `fd` (async-signal-safe: it runs
/// between fork and exec).
bool redirect(const char* target, int fd) {
  const int file = ::open(target, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (file < 0) return false;
  const bool ok = ::dup2(file, fd) >= 0;
  ::close(file);
  return ok;
}

/// True when an MPI launcher started this process (it is a rank of `mpirun demwb sweep`).
bool inside_mpi_job() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

/// True for the variables through which an MPI launcher tells a process it is one of its ranks.
/// A reference code started by a rank (LAMMPS is itself an MPI program) must not see them, or it
/// would try to join that job; it runs as a job of its own. The permission to run mpirun as root
/// is kept.
bool is_mpi_rank_variable(const std::string& name) {
  if (name.rfind("OMPI_ALLOW_RUN_AS_ROOT", 0) == 0) return false;
  for (const char* prefix : {"OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_"}) {
    if (name.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

}  // namespace

std::optional<std::filesystem::path> find_program(const std::string& program) {
  if (program.find('/') != std::string::npos) {
    if (::access(program.c_str(), X_OK) == 0) return std::filesystem::path(program);
    return std::nullopt;
  }
  const char* path_env = std::getenv("PATH");
  std::stringstream dirs(path_env != nullptr ? path_env : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

ProcessResult run_process(const ProcessSpec& spec) {
  ProcessResult result;
  if (spec.argv.empty()) {
    result.error = "empty command";
    return result;
  }
  const auto program = find_program(spec.argv.front());
  if (!program) {
    result.error = spec.argv.front() + ": not found in PATH";
    return result;
  }
  std::vector<std::string> env_strings;
  const bool scrub_mpi = inside_mpi_job();
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    if (spec.environment.count(name) == 0 && !(scrub_mpi && is_mpi_rank_variable(name))) env_strings.push_back(entry);
  }
  for (const auto& [k, v] : spec.environment) env_strings.push_back(k + "=" + v);
  std::vector<char*> argv;
  for (const auto& a : spec.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<char*> envp;
  for (auto& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string program_path = program->string();
  // Everything the child needs is made before fork: between fork and exec it may only call
  // async-signal-safe functions (another thread may hold the allocator's lock).
  const std::string stdout_target = spec.stdout_file.empty() ? "/dev/null" : spec.stdout_file.string();
  const std::string stderr_target = spec.stderr_file.empty() ? "/dev/null" : spec.stderr_file.string();
  const std::string work_dir = spec.working_directory.string();

  // The child reports an exec failure through a close-on-exec pipe.
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  // Forked and registered under the interrupt registry's lock, so that SIGINT/SIGTERM either
  // finds the child registered or arrives before it exists (support/interrupts.hpp).
  std::unique_lock registry_lock(child_registry_mutex());
  const pid_t pid = ::fork();
  if (pid > 0) {
    ::setpgid(pid, pid);  // also done by the child; whichever runs first makes the group
    register_child_group(pid);
  }
  registry_lock.unlock();
  if (pid < 0) {
    result.error = std::string("fork: ") + std::strerror(errno);
    ::close(report[0]);
    ::close(report[1]);
    return result;
  }
  if (pid == 0) {
    ::close(report[0]);
    ::setpgid(0, 0);
    // demwb blocks SIGINT/SIGTERM for its watcher thread; the child gets the default mask back.
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    int err = 0;
    // Output files first, so relative paths mean the caller's directory, not the child's.
    if (!redirect(stdout_target.c_str(), STDOUT_FILENO) || !redirect(stderr_target.c_str(), STDERR_FILENO)) {
      err = errno;
    } else if (!work_dir.empty() && ::chdir(work_dir.c_str()) != 0) {
      err = errno;
    } else {
      const int devnull = ::open("/dev/null", O_RDONLY);
      if (devnull >= 0) ::dup2(devnull, STDIN_FILENO);
      ::execve(program_path.c_str(), argv.data(), envp.data());
      err = errno;
    }
    const ssize_t written = ::write(report[1], &err, sizeof err);
    static_cast<void>(written);
    ::_exit(127);
  }
  ::close(report[1]);
  int child_errno = 0;
  const ssize_t got = ::read(report[0], &child_errno, sizeof child_errno);
  ::close(report[0]);
  if (got == static_cast<ssize_t>(sizeof child_errno)) {
    ::waitpid(pid, nullptr, 0);
    unregister_child_group(pid);
    result.error = program_path + ": cannot start (" + std::strerror(child_errno) + ")";
    return result;
  }
  result.started = true;

  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (spec.timeout_s > 0.0 && elapsed > spec.timeout_s) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      result.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  unregister_child_group(pid);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  return result;
}

std::string file_tail(const std::filesystem::path& path, std::size_t max_lines) {
  std::ifstream in(path);
  if (!in) return "";
  std::deque<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    lines.push_back(line);
    if (lines.size() > max_lines) lines.pop_front();
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

}  // namespace support
