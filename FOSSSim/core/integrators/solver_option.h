#pragma once
// The option "solver" of the integrators that solve step systems with StepSolver.

#include <array>
#include <string_view>

#include "core/integrators/integrator_options.h"
#include "core/solvers/step_solver.h"

namespace fosssim {

inline constexpr std::array<std::string_view, 3> kSolverChoices = {"auto", "eigen", "cholmod"};

/// The declaration of the option, shared by every integrator that has it.
inline constexpr OptionSpec kSolverOption = OptionSpec::choice(
    "solver", kSolverChoices,
    "linear solves: the course's dense LU for 2D systems of at most 64 unknowns (bit for bit the "
    "course's steps), Eigen's LDLT/LU below 1000 unknowns, CHOLMOD with reused factors from "
    "there on (auto), or always one of the sparse ones (eigen, cholmod)");

/// The SolverChoice an integrator's options hold.
inline SolverChoice solver_choice(const OptionValues& options) {
  const std::string_view choice = options.choice("solver");
  return choice == "eigen"     ? SolverChoice::kEigen
         : choice == "cholmod" ? SolverChoice::kCholmod
                               : SolverChoice::kAuto;
}

}  // namespace fosssim
