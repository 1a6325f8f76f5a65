// The window of a build without GLUT: says so.

#include <iostream>

#include "app/commands.h"
#include "cli/exit_codes.h"

namespace fosssim {

int run_window(const Scene&, const Options&) {
  std::cerr << "FOSSSim: error: this build has no interactive window (it was built without GLUT, "
               "or with FOSSSIM_WITH_WINDOW=OFF); run headless with -d 0, and see docs/viewing.md "
               "for pictures "
               "and movies without a display\n";
  return kExitBadInput;
}

}  // namespace fosssim
