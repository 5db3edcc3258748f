// SPDX-License-Identifier: MIT
#include "cases/case_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "cases/case_loader.hpp"

namespace cases {
namespace {

/// Closes a file descriptor when it goes out of scope.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) noexcept : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  /// The descriptor (negative when opening failed).
  [[nodiscard]] int get() const noexcept { return fd_; }

 private:
  int fd_;
};

/// What a file of mode `mode` is, for the message that refuses it.
std::string_view kind_of(mode_t mode) noexcept {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// "N bytes, more than the limit of M bytes (X MiB) for a case file".
std::string too_large(std::uint64_t size, bool at_least, std::uint64_t max_bytes) {
  return fmt::format("the file is {}{} bytes, more than the limit of {} bytes ({:.3g} MiB) for a case file",
                     at_least ? "at least " : "", size, max_bytes,
                     static_cast<double>(max_bytes) / (1024.0 * 1024.0));
}

}  // namespace

std::string read_case_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
  const std::string name = path.string();
  const auto fail = [&name](const std::string& problem) { throw CaseError(name, "(file)", problem); };
  // O_NONBLOCK: opening a FIFO without a writer must not wait; it is refused below anyway.
  const FileDescriptor fd(::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) fail(fmt::format("cannot open for reading ({})", std::strerror(errno)));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) fail(fmt::format("cannot inspect the file ({})", std::strerror(errno)));
  if (!S_ISREG(info.st_mode)) {
    fail(fmt::format("is {}; a case file must be a regular file (nothing was read)", kind_of(info.st_mode)));
  }
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > max_bytes) fail(too_large(size, false, max_bytes));
  // Read at most max_bytes + 1 bytes whatever the size said: a file that grows is still bounded.
  const std::uint64_t limit = max_bytes < UINT64_MAX ? max_bytes + 1 : max_bytes;
  std::string text(static_cast<std::size_t>(std::min(size + 1, limit)), '\0');
  std::size_t filled = 0;
  for (;;) {
    if (filled == text.size()) {
      if (text.size() >= limit) break;
      text.resize(static_cast<std::size_t>(std::min<std::uint64_t>(limit, 2 * text.size())));
    }
    const ssize_t got = ::read(fd.get(), text.data() + filled, text.size() - filled);
    if (got < 0) {
      if (errno == EINTR) continue;
      fail(fmt::format("read failed ({})", std::strerror(errno)));
    }
    if (got == 0) break;
    filled += static_cast<std::size_t>(got);
  }
  if (filled > max_bytes) fail(too_large(filled, true, max_bytes));
  text.resize(filled);
  return text;
}

}  // namespace cases
