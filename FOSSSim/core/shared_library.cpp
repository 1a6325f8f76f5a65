#include "core/shared_library.h"

#include <dlfcn.h>

#include "core/error.h"

namespace fosssim {

SharedLibrary SharedLibrary::open(const std::vector<std::string>& files, std::string context,
                                  const std::string& package, Scope scope) {
  std::string reasons;
  for (const std::string& file : files) {
    const int flags = RTLD_NOW | (scope == Scope::kGlobal ? RTLD_GLOBAL : RTLD_LOCAL);
    if (void* handle = ::dlopen(file.c_str(), flags)) return {handle, file, std::move(context)};
    const char* reason = ::dlerror();
    reasons += (reasons.empty() ? "cannot load " : "; cannot load ") + file + ": " +
               (reason != nullptr ? reason : "no reason given");
  }
  throw Error(ErrorKind::kUnavailable,
              context + ": " + reasons + " (install the " + package + " package)");
}

void* SharedLibrary::find(const char* name) const { return ::dlsym(handle_, name); }

void* SharedLibrary::require(const char* name) const {
  void* address = find(name);
  if (address == nullptr) {
    throw Error(ErrorKind::kUnavailable, context_ + ": " + file_ + " lacks " + name +
                                             " (a version older than the one FOSSSim was "
                                             "built with?)");
  }
  return address;
}

}  // namespace fosssim
