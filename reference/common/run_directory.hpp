// SPDX-License-Identifier: MIT
#pragma once
// Where and how an external code runs: its private directory and the environment of an Open MPI
// program started as a singleton (LAMMPS and LIGGGHTS as Debian builds them).

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

namespace reference {

/// A new, empty directory "<parent>/<prefix>-run-XXXXXX", as an absolute path (parent created if
/// needed; the system temporary directory when `parent` is empty). Throws std::runtime_error
/// when it cannot.
std::filesystem::path make_run_directory(const std::filesystem::path& parent, std::string_view prefix);

/// The environment of one run in `dir`: one OpenMP thread, and Open MPI's session directory inside
/// `dir`. Started as a singleton, an Open MPI program creates /tmp/ompi.<host>.<uid>; two runs
/// starting at the same instant race on that mkdir and one exits with status 1 ("File exists").
/// And no `orted`: a singleton forks that support daemon in MPI_Init only to be able to spawn
/// processes later, which LAMMPS and LIGGGHTS never do; it cost about 0.2 s of every run
/// (`ess_singleton_isolated`, Open MPI 4.1).
std::map<std::string, std::string> mpi_singleton_environment(const std::filesystem::path& dir);

}  // namespace reference
