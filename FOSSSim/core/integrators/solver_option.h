#pragma once
// The option "solver" of the integrators that solve step systems with StepSolver.

#include <array>
#include <string_view>

#include "core/integrators/integrator_options.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

/// The choices, named after what they do; "cholmod" is the old name of "sparse-direct"
/// (which uses MUMPS, CHOLMOD or UMFPACK, docs/solvers.md), still accepted so that older scenes
/// and command lines keep working.
inline constexpr std::array<std::string_view, 5> kSolverChoices = {"auto", "eigen", "sparse-direct",
                                                                   "cholmod", "amg"};

/// The declaration of the option, shared by every integrator that has it.
inline constexpr OptionSpec kSolverOption = OptionSpec::choice(
    "solver", kSolverChoices,
    "linear solves: the course's dense LU for 2D systems of at most 64 unknowns (bit for bit the "
    "course's steps), Eigen's LDLT/LU below 1000 unknowns, the sparse direct libraries (MUMPS, "
    "CHOLMOD, UMFPACK) with reused factors from there on (auto); or always Eigen's sparse "
    "factorizations (eigen) or the sparse direct libraries (sparse-direct; cholmod is its old "
    "name), or a Krylov method preconditioned by algebraic multigrid (amg: hypre's BoomerAMG, "
    "with the sparse direct libraries as the fallback)");

/// The SolverChoice an integrator's options hold.
inline SolverChoice solver_choice(const OptionValues& options) {
  const std::string_view choice = options.choice("solver");
  if (choice == "eigen") return SolverChoice::kEigen;
  if (choice == "sparse-direct" || choice == "cholmod") return SolverChoice::kSparseDirect;
  if (choice == "amg") return SolverChoice::kAmg;
  return SolverChoice::kAuto;
}

}  // namespace fosssim
