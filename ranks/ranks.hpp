// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace ranks {

/// True when an MPI launcher (OpenMPI's mpirun, or a PMI/PMIx launcher) started this process.
bool launched_by_mpi();

/// The processes one command is spread over: this process alone, or — when mpirun started it —
/// every rank of the MPI job. Joining happens in the constructor and leaving in the destructor,
/// so exactly one Ranks may exist per process. Built without MPI, a process that mpirun started
/// with more than one rank is refused with an error rather than silently running N copies.
class Ranks {
 public:
  Ranks();
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  /// This process's rank, 0 … size() − 1.
  int rank() const { return rank_; }
  /// How many ranks there are (1 outside MPI).
  int size() const { return size_; }
  /// True when this process runs under MPI (even with one rank).
  bool distributed() const { return joined_; }

  /// Every rank's text, in rank order, at rank 0; the other ranks get an empty list.
  std::vector<std::string> gather(const std::string& mine) const;
  /// Rank 0's value, on every rank.
  long long broadcast(long long value) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool joined_ = false;
};

}  // namespace ranks
