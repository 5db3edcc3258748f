// SPDX-License-Identifier: MIT
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/hertz_solver.hpp"
#include "reference/analytic/oblique_impact_solver.hpp"
#include "reference/analytic/sliding_solver.hpp"
#include "reference/analytic/jkr_solver.hpp"
#include "reference/analytic/linear_cohesion_solver.hpp"
#include "reference/analytic/solver.hpp"

namespace reference::analytic {

std::vector<std::unique_ptr<Solver>> all_solvers() {
  std::vector<std::unique_ptr<Solver>> solvers;
  solvers.push_back(std::make_unique<CollinearSolver>());
  solvers.push_back(std::make_unique<HertzSolver>());
  solvers.push_back(std::make_unique<ObliqueImpactSolver>());
  solvers.push_back(std::make_unique<SlidingSolver>());
  solvers.push_back(std::make_unique<JkrPulloffSolver>());
  solvers.push_back(std::make_unique<LinearCohesionSolver>());
  return solvers;
}

}  // namespace reference::analytic
