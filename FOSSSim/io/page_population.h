#pragma once
// Fresh memory that is about to be written whole, mapped in one go instead of page by page.

#include <cstddef>

namespace fosssim {

/// Asks the kernel to map, now and in one call, the pages of [data, data + bytes) that a
/// caller is about to write whole (a scene file's text, the XML reader's arrays). Touching
/// fresh memory page by page costs one page fault per 4 KiB, and a page fault is expensive on
/// virtual machines: on the project's machine, 2.6 MB read into a new string took 12-14 ms of
/// CPU page by page and about 1 ms populated at once (docs/limits-and-failures.md, "Start-up").
/// Only whole pages inside the range are populated; nothing happens where the system cannot
/// do it (before Linux 5.14, other systems, the WebAssembly build). The contents are unchanged.
void populate_pages(void* data, std::size_t bytes);

}  // namespace fosssim
