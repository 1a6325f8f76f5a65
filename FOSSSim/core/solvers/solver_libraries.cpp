#include "core/solvers/solver_libraries.h"

#include <sched.h>

#include <mutex>
#include <string>
#include <vector>

#include "core/shared_library.h"

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
std::vector<SharedLibrary> loaded;  // the libraries loaded so far

/// Sets the thread count in the libraries `library` brought (OpenBLAS, libgomp), if any.
void apply_threads(const SharedLibrary& library) {
  if (threads_wanted <= 0) return;
  for (const char* setter : {"openblas_set_num_threads", "omp_set_num_threads"}) {
    if (void* set = library.find(setter)) reinterpret_cast<SetThreads>(set)(threads_wanted);
  }
}

/// While it lives, the calling thread narrowed to its first `threads_wanted` CPUs, when a count
/// is wanted and no library has started a pool yet: the libraries' constructors run in dlopen,
/// and OpenBLAS's starts a thread per CPU the loading thread may run on.
struct NarrowedCpus {
  NarrowedCpus() {
    if (threads_wanted <= 0 || threads_applied_to_pool ||
        ::sched_getaffinity(0, sizeof start, &start) != 0 || CPU_COUNT(&start) <= threads_wanted) {
      return;
    }
    cpu_set_t fewer;
    CPU_ZERO(&fewer);
    for (int cpu = 0; cpu < CPU_SETSIZE && CPU_COUNT(&fewer) < threads_wanted; ++cpu) {
      if (CPU_ISSET(cpu, &start)) CPU_SET(cpu, &fewer);
    }
    narrowed = ::sched_setaffinity(0, sizeof fewer, &fewer) == 0;
  }
  ~NarrowedCpus() {
    if (narrowed) ::sched_setaffinity(0, sizeof start, &start);
  }
  cpu_set_t start;
  bool narrowed = false;
};

SharedLibrary open_library(const char* soname, const char* name, const char* package) {
  std::lock_guard<std::mutex> lock(load_mutex);
  const SharedLibrary library = [&] {
    const NarrowedCpus narrowed;
    return SharedLibrary::open({soname}, std::string("the sparse solvers need ") + name, package);
  }();
  apply_threads(library);
  loaded.push_back(library);
  threads_applied_to_pool = threads_applied_to_pool || threads_wanted > 0;
  return library;
}

}  // namespace

CholmodLibrary::CholmodLibrary()
    : library(open_library(FOSSSIM_CHOLMOD_SONAME, "CHOLMOD", "libcholmod3")) {}
UmfpackLibrary::UmfpackLibrary()
    : library(open_library(FOSSSIM_UMFPACK_SONAME, "UMFPACK", "libumfpack5")) {}
MumpsLibrary::MumpsLibrary()
    : double_library(open_library(FOSSSIM_DMUMPS_SONAME, "MUMPS", "libmumps-seq-5.5")),
      single_library(open_library(FOSSSIM_SMUMPS_SONAME, "MUMPS", "libmumps-seq-5.5")) {}

// A function-local static: a failed load (an exception) is tried again on the next call.
const CholmodLibrary& cholmod_library() {
  static const CholmodLibrary library;
  return library;
}

const UmfpackLibrary& umfpack_library() {
  static const UmfpackLibrary library;
  return library;
}

const MumpsLibrary& mumps_library() {
  static const MumpsLibrary library;
  return library;
}

void set_solver_library_threads(int count) {
  std::lock_guard<std::mutex> lock(load_mutex);
  threads_wanted = count;
  for (const SharedLibrary& library : loaded) apply_threads(library);  // loaded before: at once
}

}  // namespace fosssim
