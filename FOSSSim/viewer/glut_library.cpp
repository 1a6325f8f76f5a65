#include "viewer/glut_library.h"

#include <dlfcn.h>

#include <string>

#include "core/error.h"

namespace fosssim {

namespace {

/// freeglut's sonames: Debian 12's freeglut 3.4, then the older 3.x.
constexpr const char* kGlutSonames[] = {"libglut.so.3.12", "libglut.so.3"};

GlutLibrary load_glut() {
  void* handle = nullptr;
  std::string reasons;
  for (const char* soname : kGlutSonames) {
    handle = ::dlopen(soname, RTLD_NOW | RTLD_LOCAL);  // never closed: the window's library
    if (handle != nullptr) break;
    const char* reason = ::dlerror();
    reasons += std::string(reasons.empty() ? "" : "; ") + (reason != nullptr ? reason : soname);
  }
  if (handle == nullptr) {
    throw Error(ErrorKind::kUnavailable, "the window needs GLUT, which cannot be loaded: " +
                                             reasons + " (install the libglut3.12 package)");
  }
  // dlsym on GLUT's handle also searches the libraries it depends on: OpenGL and Xlib.
  GlutLibrary library;
#define FOSSSIM_GLUT_LOAD(name)                                                           \
  library.name = reinterpret_cast<decltype(library.name)>(::dlsym(handle, #name));        \
  if (library.name == nullptr) {                                                          \
    throw Error(ErrorKind::kUnavailable,                                                  \
                "GLUT, OpenGL or Xlib as loaded here has no function " #name);            \
  }
  FOSSSIM_GLUT_FUNCTIONS(FOSSSIM_GLUT_LOAD)
#undef FOSSSIM_GLUT_LOAD
  return library;
}

}  // namespace

const GlutLibrary& glut() {
  static const GlutLibrary library = load_glut();  // a failed load is tried again next time
  return library;
}

}  // namespace fosssim
