#include "app/solver_threads.h"

#include "core/solvers/solver_library_threads.h"

namespace fosssim {

bool set_solver_threads(int count) {
  set_solver_library_threads(count);
  return true;
}

}  // namespace fosssim
