#include "pictures/cairo_library.h"

#include <dlfcn.h>

#include <string>

#include "core/error.h"

namespace fosssim {

namespace {

/// The library Debian's libcairo2 installs, by its soname (the one cairo.h was built against).
constexpr const char* kCairoSoname = "libcairo.so.2";

CairoLibrary load_cairo() {
  // Never closed: pictures may be drawn until the process ends.
  void* handle = ::dlopen(kCairoSoname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = ::dlerror();
    throw Error(ErrorKind::kUnavailable,
                std::string("pictures need Cairo, which cannot be loaded: ") +
                    (reason != nullptr ? reason : kCairoSoname) +
                    " (install the libcairo2 package)");
  }
  CairoLibrary library;
#define FOSSSIM_CAIRO_LOAD(name)                                                          \
  library.name = reinterpret_cast<decltype(library.name)>(::dlsym(handle, "cairo_" #name)); \
  if (library.name == nullptr) {                                                          \
    throw Error(ErrorKind::kUnavailable, std::string(kCairoSoname) +                      \
                                             " has no function cairo_" #name              \
                                             " (a Cairo older than the one FOSSSim was "  \
                                             "built with?)");                             \
  }
  FOSSSIM_CAIRO_FUNCTIONS(FOSSSIM_CAIRO_LOAD)
#undef FOSSSIM_CAIRO_LOAD
  return library;
}

}  // namespace

const CairoLibrary& cairo() {
  static const CairoLibrary library = load_cairo();  // a failed load is tried again next time
  return library;
}

}  // namespace fosssim
