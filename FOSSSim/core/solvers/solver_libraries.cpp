#include "core/solvers/solver_libraries.h"

#include <dlfcn.h>
#include <sched.h>

#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"

// The sonames, from the libraries CMake found (cmake/FOSSSimDependencies.cmake).
#ifndef FOSSSIM_CHOLMOD_SONAME
#error "FOSSSIM_CHOLMOD_SONAME is set by the build"
#endif

namespace fosssim {

namespace {

/// OpenBLAS's and libgomp's thread setters, found in whichever library brought them.
using SetThreads = void (*)(int);

std::mutex load_mutex;
int threads_wanted = 0;  // 0: never set
bool threads_applied_to_pool = false;
std::vector<void*> loaded_handles;  // the libraries loaded so far

/// Sets the thread count in the libraries `handle` brought (OpenBLAS, libgomp), if any.
void apply_threads(void* handle) {
  if (threads_wanted <= 0) return;
  if (auto set = reinterpret_cast<SetThreads>(::dlsym(handle, "openblas_set_num_threads"))) {
    set(threads_wanted);
  }
  if (auto set = reinterpret_cast<SetThreads>(::dlsym(handle, "omp_set_num_threads"))) {
    set(threads_wanted);
  }
}

/// dlopen with the calling thread narrowed to its first `threads_wanted` CPUs while the
/// libraries' constructors run, so that OpenBLAS's pool starts with at most that many threads.
void* open_narrowed(const char* soname) {
  cpu_set_t start_cpus;
  bool narrowed = false;
  if (threads_wanted > 0 && !threads_applied_to_pool &&
      ::sched_getaffinity(0, sizeof start_cpus, &start_cpus) == 0 &&
      CPU_COUNT(&start_cpus) > threads_wanted) {
    cpu_set_t fewer;
    CPU_ZERO(&fewer);
    int kept = 0;
    for (int cpu = 0; cpu < CPU_SETSIZE && kept < threads_wanted; ++cpu) {
      if (CPU_ISSET(cpu, &start_cpus)) {
        CPU_SET(cpu, &fewer);
        ++kept;
      }
    }
    narrowed = ::sched_setaffinity(0, sizeof fewer, &fewer) == 0;
  }
  void* handle = ::dlopen(soname, RTLD_NOW | RTLD_LOCAL);
  if (narrowed) ::sched_setaffinity(0, sizeof start_cpus, &start_cpus);
  return handle;
}

void* open_library(const char* soname, const char* package) {
  std::lock_guard<std::mutex> lock(load_mutex);
  void* handle = open_narrowed(soname);  // never closed: solves may run until the process ends
  if (handle == nullptr) {
    const char* reason = ::dlerror();
    throw Error(ErrorKind::kUnavailable,
                std::string("the sparse solvers need ") + soname +
                    ", which cannot be loaded: " + (reason != nullptr ? reason : soname) +
                    " (install the " + package + " package)");
  }
  apply_threads(handle);
  loaded_handles.push_back(handle);
  threads_applied_to_pool = threads_applied_to_pool || threads_wanted > 0;
  return handle;
}

template <class Function>
void find(void* handle, const char* soname, const char* name, Function& function) {
  function = reinterpret_cast<Function>(::dlsym(handle, name));
  if (function == nullptr) {
    throw Error(ErrorKind::kUnavailable, std::string(soname) + " has no function " + name +
                                             " (a version older than the one FOSSSim was "
                                             "built with?)");
  }
}

#define FOSSSIM_SOLVER_FIND(name) find(handle, soname, #name, library.name);

CholmodLibrary load_cholmod() {
  const char* soname = FOSSSIM_CHOLMOD_SONAME;
  void* handle = open_library(soname, "libcholmod3");
  CholmodLibrary library;
  FOSSSIM_CHOLMOD_FUNCTIONS(FOSSSIM_SOLVER_FIND)
  return library;
}

UmfpackLibrary load_umfpack() {
  const char* soname = FOSSSIM_UMFPACK_SONAME;
  void* handle = open_library(soname, "libumfpack5");
  UmfpackLibrary library;
  FOSSSIM_UMFPACK_FUNCTIONS(FOSSSIM_SOLVER_FIND)
  return library;
}

MumpsLibrary load_mumps() {
  MumpsLibrary library;
  {
    const char* soname = FOSSSIM_DMUMPS_SONAME;
    void* handle = open_library(soname, "libmumps-seq-5.5");
    FOSSSIM_DMUMPS_FUNCTIONS(FOSSSIM_SOLVER_FIND)
  }
  {
    const char* soname = FOSSSIM_SMUMPS_SONAME;
    void* handle = open_library(soname, "libmumps-seq-5.5");
    FOSSSIM_SMUMPS_FUNCTIONS(FOSSSIM_SOLVER_FIND)
  }
  return library;
}

#undef FOSSSIM_SOLVER_FIND

}  // namespace

// A function-local static: a failed load (an exception) is tried again on the next call.
const CholmodLibrary& cholmod_library() {
  static const CholmodLibrary library = load_cholmod();
  return library;
}

const UmfpackLibrary& umfpack_library() {
  static const UmfpackLibrary library = load_umfpack();
  return library;
}

const MumpsLibrary& mumps_library() {
  static const MumpsLibrary library = load_mumps();
  return library;
}

void set_solver_library_threads(int count) {
  std::lock_guard<std::mutex> lock(load_mutex);
  threads_wanted = count;
  for (void* handle : loaded_handles) apply_threads(handle);  // loaded before: set at once
}

}  // namespace fosssim
