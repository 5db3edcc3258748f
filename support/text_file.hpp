// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace support {

/// Whole content of a file as bytes; throws std::runtime_error naming the path on failure.
std::string read_file(const std::filesystem::path& path);

/// Whole content of a file, or "" when it cannot be read (a log a crashed program never wrote).
std::string read_file_or_empty(const std::filesystem::path& path);

/// Writes `content` to `path` (creating parent directories) atomically: a temporary file in the
/// same directory, renamed over `path` when complete. Throws naming the path on failure.
void write_file(const std::filesystem::path& path, std::string_view content);

}  // namespace support
