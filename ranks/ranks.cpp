// SPDX-License-Identifier: MIT
#include "ranks/ranks.hpp"

#include <cstdlib>
#include <exception>
#include <stdexcept>

#if DEMWB_HAVE_MPI
#include <mpi.h>
#endif

namespace ranks {
namespace {

/// The number of ranks the launcher announced, or 0 when none did.
int announced_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* v = std::getenv(name); v != nullptr) return std::atoi(v);
  }
  return 0;
}

}  // namespace

bool launched_by_mpi() {
  return announced_size() > 0 || std::getenv("PMIX_RANK") != nullptr || std::getenv("PMI_RANK") != nullptr;
}

#if DEMWB_HAVE_MPI

Ranks::Ranks() {
  if (!launched_by_mpi()) return;
  // Only the main thread calls MPI; worker threads run the cases.
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  joined_ = true;
}

Ranks::~Ranks() {
  if (!joined_) return;
  // A rank leaving with an exception would leave the others waiting in a collective for ever:
  // end the whole job instead.
  if (std::uncaught_exceptions() > 0 && size_ > 1) MPI_Abort(MPI_COMM_WORLD, 2);
  MPI_Finalize();
}

std::vector<std::string> Ranks::gather(const std::string& mine) const {
  if (!joined_) return {mine};
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(static_cast<std::size_t>(size_), 0);
  std::string all;
  if (rank_ == 0) {
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
      total += lengths[static_cast<std::size_t>(r)];
    }
    if (total > 2147483647LL) throw std::runtime_error("ranks: the gathered results exceed 2 GiB");
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank_ != 0) return {};
  std::vector<std::string> out;
  for (int r = 0; r < size_; ++r) {
    out.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                             static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
  }
  return out;
}

long long Ranks::broadcast(long long value) const {
  if (joined_) MPI_Bcast(&value, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  return value;
}

#else

Ranks::Ranks() {
  if (announced_size() > 1) {
    throw std::runtime_error(
        "demwb was built without MPI, so it cannot share work between the ranks mpirun started; install "
        "libopenmpi-dev and rebuild (scripts/build.sh), or run without mpirun");
  }
}

Ranks::~Ranks() = default;

std::vector<std::string> Ranks::gather(const std::string& mine) const { return {mine}; }

long long Ranks::broadcast(long long value) const { return value; }

#endif

}  // namespace ranks
