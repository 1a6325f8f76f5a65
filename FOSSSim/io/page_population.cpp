#include "io/page_population.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace fosssim {

void populate_pages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  // Below this, the call costs about what the few faults it saves do.
  constexpr std::size_t kMinBytes = std::size_t{256} << 10;
  if (data == nullptr || bytes < kMinBytes) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) / page * page;
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / page * page;
  if (end <= begin) return;
  // Writes nothing: the pages are faulted in as if written, their contents kept. An error
  // (an older kernel's EINVAL) leaves them to be faulted in one by one, as without the call.
  ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace fosssim
