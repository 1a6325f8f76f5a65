// solve_contact_lcp_dantzig of the WebAssembly build (FOSSSIM_WEB), which has no build of ODE's
// LCP solver: the problem is answered by solve_contact_qp, the exact active-set method the native
// build already uses on degenerate problems. On the non-degenerate problems this function is
// called for, the LCP has one solution, so both methods give it to round-off (not to the last
// bit: the browser's rigid contact scenes are checked for size, not bytes; docs/web.md).
#include "core/rigid/contact_lcp.h"
#include "core/solvers/solver_failure.h"

namespace fosssim {

ContactSolveResult solve_contact_lcp_dantzig(const ContactProblem& problem) {
  ContactSolveResult out;
  const int n = static_cast<int>(problem.b.size());
  try {
    out.lambda = solve_contact_qp(problem, contact_qp_iteration_limit(n));
  } catch (const SolverFailure& failure) {
    out.lambda = Vector::Zero(n);
    out.problem = failure.what();
    return out;
  }
  out.valid = check_contact_solution(problem, out.lambda, &out.problem);
  return out;
}

}  // namespace fosssim
