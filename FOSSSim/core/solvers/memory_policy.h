#pragma once
// How the process's allocator treats the large buffers of big implicit steps.

namespace fosssim {

/// Blocks of at least this many bytes are mapped from the system on their own and given back
/// when freed.
inline constexpr long kLargeBlockBytes = 1L << 20;

/// Free memory at the top of the heap is given back to the system only beyond this many bytes
/// (twice kLargeBlockBytes, the value glibc's dynamic rule would choose).
inline constexpr long kTrimThresholdBytes = 2 * kLargeBlockBytes;

/// Makes every allocation of kLargeBlockBytes or more a mapping of its own, returned to the
/// system when freed (glibc's M_MMAP_THRESHOLD, fixed; elsewhere nothing). By default glibc
/// raises that threshold each time such a block is freed, up to 32 MiB, after which large
/// buffers come from the heap and stay resident once freed: the scratch of a big step matrix's
/// first assembly and analysis (316×316 2D damped cloth: 27 MB) then adds to the peak of every
/// later factorization. It also keeps up to kTrimThresholdBytes of freed heap (glibc's
/// M_TRIM_THRESHOLD), so that buffers allocated and freed at every solve are not returned to
/// the system and faulted in again each time. Programs call it once, first thing in main; results are unchanged.
void return_large_blocks_to_system();

}  // namespace fosssim
