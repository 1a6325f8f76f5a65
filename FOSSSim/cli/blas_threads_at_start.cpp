// The BLAS's thread pool, sized from --threads before any shared library starts
// (docs/solvers.md, "Threads and determinism").
//
// OpenBLAS (its pthreads build, Debian's) starts its pool in its library constructor, before
// main: as many threads as OPENBLAS_NUM_THREADS says, else as many as the CPUs the process may
// run on (sched_getaffinity), each but the caller a thread that waits spinning. libgomp sizes
// its default team the same way when it is loaded. So app/solver_threads.cpp's
// openblas_set_num_threads comes after the pool exists, and a run that never solves paid for
// threads it never used. This file is linked into every program that loads OpenBLAS
// (FOSSSim, FOSSSim-generate, fosssim-oracle, the benchmarks) as an object of its own:
//  - a function in the executable's .preinit_array, which glibc runs with argc/argv/envp before
//    any shared library's constructor, reads the command line's `--threads N` (or
//    `--threads=N`; the last one given; 1 when there is none) and, when N is below the number
//    of CPUs the process may use, narrows the process to its first N of them: OpenBLAS and
//    libgomp then start at most N threads, whatever OPENBLAS_NUM_THREADS and OMP_NUM_THREADS
//    say (--threads overrides them);
//  - a constructor of the executable, which runs after every shared library's, gives every
//    thread of the process its CPUs back; main then sets the exact count
//    (set_solver_threads).
// The environment is not the lever: at .preinit_array time libc has not set `environ` yet, and
// its own start-up later resets it to the process's initial block, so a setenv made there is
// lost. The environment stays as it was, for the processes a program starts (ffmpeg, the
// oracle's candidates). A value --threads refuses (not a number in 1..256) counts as 1 here;
// CLI11 then rejects the command line. Before main nothing here allocates, and it calls no
// libc function a sanitizer's runtime may intercept (strtol, strcmp, sched_getaffinity): the
// affinity is asked of the kernel directly.

#include <dirent.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>

namespace {

/// The largest count --threads accepts (app/options.cpp).
constexpr long kMaxBlasThreads = 256;

/// The CPUs the process was started with, while it runs narrowed (before main).
cpu_set_t start_cpus;
bool cpus_narrowed = false;

/// `text` as a count in 1..kMaxBlasThreads (decimal digits only, as CLI11 reads it), or 0.
long thread_count(const char* text) {
  if (text == nullptr || *text == '\0') return 0;
  long count = 0;
  for (; *text != '\0'; ++text) {
    if (*text < '0' || *text > '9') return 0;
    count = 10 * count + (*text - '0');
    if (count > kMaxBlasThreads) return 0;
  }
  return count >= 1 ? count : 0;
}

/// Whether `argument` starts with `prefix`; the rest of it, or null.
const char* after_prefix(const char* argument, const char* prefix) {
  for (; *prefix != '\0'; ++argument, ++prefix) {
    if (*argument != *prefix) return nullptr;
  }
  return argument;
}

/// The count of the last `--threads N` or `--threads=N` in argv; 1 when none is valid.
long threads_option(int argc, char** argv) {
  long count = 1;
  for (int i = 1; i < argc && argv[i] != nullptr; ++i) {
    const char* rest = after_prefix(argv[i], "--");
    if (rest != nullptr && *rest == '\0') break;  // "--": no options after it
    rest = after_prefix(argv[i], "--threads");
    if (rest == nullptr) continue;
    const char* value = nullptr;
    if (*rest == '=') {
      value = rest + 1;
    } else if (*rest == '\0' && i + 1 < argc) {
      value = argv[++i];
    } else {
      continue;  // --threadsX is another option
    }
    const long given = thread_count(value);
    count = given > 0 ? given : 1;
  }
  return count;
}

/// Runs before the shared libraries' constructors (.preinit_array).
void narrow_cpus_before_libraries(int argc, char** argv, char** /*envp*/) {
  const long threads = threads_option(argc, argv);
  CPU_ZERO(&start_cpus);
  // The system call returns the size of the mask it wrote (glibc's wrapper returns 0).
  if (::syscall(SYS_sched_getaffinity, 0, sizeof(start_cpus), &start_cpus) <= 0) return;
  if (CPU_COUNT(&start_cpus) <= threads) return;
  cpu_set_t first;
  CPU_ZERO(&first);
  long kept = 0;
  for (int cpu = 0; cpu < CPU_SETSIZE && kept < threads; ++cpu) {
    if (CPU_ISSET(cpu, &start_cpus)) {
      CPU_SET(cpu, &first);
      ++kept;
    }
  }
  cpus_narrowed = ::syscall(SYS_sched_setaffinity, 0, sizeof(first), &first) == 0;
}

/// Runs after them (the executable's constructors come last): every thread gets the CPUs back,
/// the pool's too when --threads N > 1 let OpenBLAS start some.
__attribute__((constructor)) void restore_cpus_after_libraries() {
  if (!cpus_narrowed) return;
  cpus_narrowed = false;
  ::sched_setaffinity(0, sizeof(start_cpus), &start_cpus);
  DIR* tasks = ::opendir("/proc/self/task");
  if (tasks == nullptr) return;
  while (const dirent* task = ::readdir(tasks)) {
    const long id = std::strtol(task->d_name, nullptr, 10);
    if (id > 0) ::sched_setaffinity(static_cast<pid_t>(id), sizeof(start_cpus), &start_cpus);
  }
  ::closedir(tasks);
}

}  // namespace

// glibc calls .preinit_array's functions as it calls init functions: (argc, argv, envp).
__attribute__((section(".preinit_array"), used)) void (*const fosssim_blas_threads_at_start)(
    int, char**, char**) = narrow_cpus_before_libraries;
