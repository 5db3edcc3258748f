// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace cases {

/// Largest case file the loader reads: 4 MiB [bytes]. The largest case in the repository is a
/// few kilobytes and a case of many particles generates them ([[populations]]), so anything
/// near this size is a mistake or an attack, not a scene.
inline constexpr std::uint64_t kMaxCaseFileBytes = 4U * 1024U * 1024U;

/// The bytes of the case file at `path`, read as untrusted input: it must be a regular file (a
/// directory, a device such as /dev/zero, a FIFO or a socket is refused without reading it, and
/// opening never blocks) of at most `max_bytes`, checked before reading, and the read itself
/// stops after max_bytes + 1 bytes, so a file that grows while it is read is refused too.
/// Throws CaseError with the key "(file)" naming the path.
[[nodiscard]] std::string read_case_file(const std::filesystem::path& path,
                                         std::uint64_t max_bytes = kMaxCaseFileBytes);

}  // namespace cases
