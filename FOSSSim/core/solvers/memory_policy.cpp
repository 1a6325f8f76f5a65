#include "core/solvers/memory_policy.h"

#include <cstdlib>  // defines __GLIBC__ on glibc systems

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fosssim {

void return_large_blocks_to_system() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLargeBlockBytes));
  // Fixing the mapping threshold also stops glibc's dynamic trim threshold, which would
  // otherwise be twice it; left at its 128 KiB default, every free of a few hundred KB at the
  // top of the heap (MUMPS's solve workspace, allocated and freed at every solve) gave the
  // memory back to the system and the next solve took it again: brk calls, TLB flushes and
  // page faults were a fifth of a small 3D step (the CSC417 bunny). Twice the mapping
  // threshold is glibc's own rule: at most 2 MiB of free heap stays resident.
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThresholdBytes));
#endif
}

}  // namespace fosssim
