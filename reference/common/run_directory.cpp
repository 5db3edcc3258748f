// SPDX-License-Identifier: MIT
#include "reference/common/run_directory.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace reference {

std::filesystem::path make_run_directory(const std::filesystem::path& parent, std::string_view prefix) {
  // Absolute, because the child process changes into it before opening its output files.
  const std::filesystem::path base =
      std::filesystem::absolute(parent.empty() ? std::filesystem::temp_directory_path() : parent);
  std::error_code ec;
  std::filesystem::create_directories(base, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create directory {}: {}", base.string(), ec.message()));
  std::string pattern = (base / fmt::format("{}-run-XXXXXX", prefix)).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot create a run directory in {}: {}", base.string(), std::strerror(errno)));
  }
  return pattern;
}

std::map<std::string, std::string> mpi_singleton_environment(const std::filesystem::path& dir) {
  return {{"OMP_NUM_THREADS", "1"},
          {"OMPI_MCA_orte_tmpdir_base", dir.string()},
          {"OMPI_MCA_ess_singleton_isolated", "1"}};
}

}  // namespace reference
