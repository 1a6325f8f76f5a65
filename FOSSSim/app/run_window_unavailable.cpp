// The window of a build without GLUT: says so.

#include "app/commands.h"
#include "core/error.h"

namespace fosssim {

int run_window(const Scene&, const Options&) {
  throw Error(ErrorKind::kUnavailable,
              "this build has no interactive window (it was built without GLUT, or with "
              "FOSSSIM_WITH_WINDOW=OFF); run headless with -d 0, and see docs/viewing.md for "
              "pictures and movies without a display");
}

}  // namespace fosssim
