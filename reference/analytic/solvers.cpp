// SPDX-License-Identifier: MIT
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/solver.hpp"

namespace reference::analytic {

std::vector<std::unique_ptr<Solver>> all_solvers() {
  std::vector<std::unique_ptr<Solver>> solvers;
  solvers.push_back(std::make_unique<CollinearSolver>());
  return solvers;
}

}  // namespace reference::analytic
