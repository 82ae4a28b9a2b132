// mallopt and malloc_trim: glibc only.
#include "session/registry/memory_release.h"

#include <malloc.h>

#include <cstdlib>

namespace relmap::session {

void ConfigureAllocator(int arenas, std::size_t mmap_threshold_bytes) {
  if (std::getenv("GLIBC_TUNABLES") != nullptr) return;
  if (std::getenv("MALLOC_ARENA_MAX") == nullptr) mallopt(M_ARENA_MAX, arenas);
  if (std::getenv("MALLOC_MMAP_THRESHOLD_") == nullptr) {
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(mmap_threshold_bytes));
  }
}

void ReturnFreedMemory() { malloc_trim(0); }

}  // namespace relmap::session
