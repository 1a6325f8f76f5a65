// Tests of return_large_blocks_to_system (core/solvers/memory_policy.h).
//
// Checked (glibc's malloc only: elsewhere, and under AddressSanitizer, the call does nothing):
// after the call, a large block freed does not raise the size from which blocks are mapped on their
// own. By default glibc raises that size to a freed mapped block's (up to 32 MiB), so a 16 MiB
// block allocated after a 24 MiB one was freed would come from the heap and stay resident after its
// own free. (Sizes far above any free chunk the test process's heap may hold, which malloc would
// use first.) And a half-megabyte block freed at the top of the heap stays there instead of
// being given back (the trim threshold, which fixing the mapping threshold leaves at 128 KiB).

#include "core/solvers/memory_policy.h"
#include "core/sanitizers.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fosssim::testing {
namespace {

/// AddressSanitizer replaces malloc: glibc's options and counts mean nothing under it.
constexpr bool kMallocIsGlibcs = !FOSSSIM_ADDRESS_SANITIZER;

#if defined(__GLIBC__)
void* volatile kept = nullptr;  // volatile: the allocations below may not be elided

/// Blocks currently mapped on their own.
std::size_t mapped_blocks() { return mallinfo2().hblks; }

/// The check, in a process of its own: earlier tests may have left large free chunks in
/// this one's heap, which malloc would reuse before mapping anything. Exits 0 when it holds.
[[noreturn]] void check_large_blocks_are_mapped() {
  return_large_blocks_to_system();
  kept = std::malloc(24 * kLargeBlockBytes);
  if (kept == nullptr) std::_Exit(2);
  std::memset(kept, 1, 24 * kLargeBlockBytes);
  std::free(kept);
  const std::size_t before = mapped_blocks();
  kept = std::malloc(16 * kLargeBlockBytes);
  if (kept == nullptr) std::_Exit(2);
  if (mapped_blocks() != before + 1) std::_Exit(3);  // the 16 MiB block came from the heap
  std::free(kept);
  if (mapped_blocks() != before) std::_Exit(4);  // it was not given back
  std::_Exit(0);
}

/// A block below the mapping threshold freed at the top of the heap stays in the heap: the
/// heap is not shrunk (glibc's default trim threshold, 128 KiB, would give it back, and the
/// next allocation of the same size would take it from the system again). Exits 0 when it holds.
[[noreturn]] void check_freed_heap_top_is_kept() {
  return_large_blocks_to_system();
  kept = std::malloc(kLargeBlockBytes / 2);
  if (kept == nullptr) std::_Exit(2);
  std::memset(kept, 1, kLargeBlockBytes / 2);
  const std::size_t heap = mallinfo2().arena;
  std::free(kept);
  if (mallinfo2().arena != heap) std::_Exit(3);  // the heap was trimmed
  std::_Exit(0);
}

TEST(MemoryPolicy, AHalfMegabyteFreedAtTheTopOfTheHeapIsNotGivenBack) {
  if (!kMallocIsGlibcs) GTEST_SKIP() << "malloc is the sanitizer's";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(check_freed_heap_top_is_kept(), ::testing::ExitedWithCode(0), "");
}

TEST(MemoryPolicy, LargeBlocksStayMappedOnTheirOwnAfterALargerOneWasFreed) {
  if (!kMallocIsGlibcs) GTEST_SKIP() << "malloc is the sanitizer's";
  // "threadsafe" runs the check in a new process started from this program, not in a fork.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(check_large_blocks_are_mapped(), ::testing::ExitedWithCode(0), "");
}
#endif

}  // namespace
}  // namespace fosssim::testing
