// Memory that sessions free goes back to the system. glibc's allocator keeps freed memory
// for reuse: in one arena per thread that allocated (up to 8 per core: 16 on two cores, for
// 16 worker threads), and it raises its mmap threshold with every large block freed, and its
// trim threshold (the free memory an arena's top keeps) with it, to 64 MB. Measured with
// relmap-load on the mug cloud (8 sessions, 10 cycles): 240 MB of 320 still held after every
// session was deleted (docs/reliability.md, "Memory"). Hence few arenas, a fixed threshold
// and a trim once sessions go.
#pragma once

#include <cstddef>

namespace relmap::session {

// At most `arenas` arenas, and blocks of `mmap_threshold_bytes` or more mapped on their
// own (returned to the system when freed) with the threshold fixed, unless the environment
// says otherwise (MALLOC_ARENA_MAX, MALLOC_MMAP_THRESHOLD_ or GLIBC_TUNABLES: the operator's
// choice wins). Before any thread starts.
void ConfigureAllocator(int arenas, std::size_t mmap_threshold_bytes);

// Returns the free memory of every arena to the system (malloc_trim): after sessions
// are deleted or evicted. Milliseconds for a heap of a few hundred MB.
void ReturnFreedMemory();

}  // namespace relmap::session
