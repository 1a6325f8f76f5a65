// solve_contact_lcp_dantzig through ODE's Dantzig solver as Debian packages it with DART
// (libdart-external-odelcpsolver-dev). The native build's; the WebAssembly build, which has no
// build of that library, compiles contact_lcp_dantzig_web.cpp instead (docs/web.md).
#include <dart/external/odelcpsolver/error.h>
#include <dart/external/odelcpsolver/lcp.h>

#include <cstdarg>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "core/rigid/contact_lcp.h"

namespace fosssim {

namespace ode = dart::external::ode;

namespace {

/// Set by the library's message handler while this thread solves.
thread_local bool library_reported_error = false;
thread_local std::string library_message;

void catch_library_message(int /*errnum*/, const char* message, va_list arguments) {
  char text[256];
  std::vsnprintf(text, sizeof text, message, arguments);
  library_reported_error = true;
  library_message = text;
}

/// The library prints its messages (and aborts on its debug messages) unless told otherwise.
void install_library_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    ode::dSetMessageHandler(&catch_library_message);
    ode::dSetDebugHandler(&catch_library_message);
    ode::dSetErrorHandler(&catch_library_message);
  });
}

int padded(int n) { return n > 1 ? (((n - 1) | 3) + 1) : n; }  // ODE's dPAD

}  // namespace

ContactSolveResult solve_contact_lcp_dantzig(const ContactProblem& problem) {
  install_library_handlers();
  const int n = static_cast<int>(problem.b.size());
  ContactSolveResult out;
  out.lambda = Vector::Zero(n);
  if (n == 0) {
    out.valid = true;
    return out;
  }
  const int skip = padded(n);
  // A row by row, rows padded to a multiple of 4 (A is symmetric: rows are columns).
  std::vector<double> a(static_cast<std::size_t>(n) * skip, 0.0), rhs(n), x(n, 0.0), w(n, 0.0),
      lo(n, 0.0), hi(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a[static_cast<std::size_t>(i) * skip + j] = problem.A(i, j);
    rhs[i] = -problem.b[i];  // the library solves A x = b + w
  }
  library_reported_error = false;
  const bool solved = ode::dSolveLCP(n, a.data(), x.data(), rhs.data(), w.data(), 0, lo.data(),
                                     hi.data(), nullptr, false);
  for (int i = 0; i < n; ++i) out.lambda[i] = x[i];
  if (library_reported_error) {
    out.problem = "the LCP solver reported \"" + library_message + "\"";
  } else if (!solved) {
    out.problem = "the LCP solver gave up";
  } else {
    out.valid = check_contact_solution(problem, out.lambda, &out.problem);
  }
  return out;
}

}  // namespace fosssim
