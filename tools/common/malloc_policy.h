// How the programs that pack ask glibc's malloc to behave with large arrays; they call
// ConfigureMalloc first, before any thread starts. Elsewhere it does nothing.
#ifndef HULLPACK_TOOLS_COMMON_MALLOC_POLICY_H_
#define HULLPACK_TOOLS_COMMON_MALLOC_POLICY_H_

#include <cstddef>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace hullpack {

// Arrays from this size on are mapped on their own.
constexpr size_t kMappedArrayBytes = size_t{4} << 20;

// Two settings, both for the resident peak (docs/benchmarks.md, "Where the memory goes"):
// - One arena for the process. glibc gives each thread that allocates an arena of its own and keeps
//   what a thread frees there for that thread; the pipeline's threads allocate and free large
//   arrays in turn (an encode beside a decomposition).
// - Arrays of kMappedArrayBytes or more mapped on their own, so that a freed one goes back to the
//   system at once. By default glibc raises that threshold to the largest array freed so far (up
//   to 32 MB) and keeps what is freed below it resident in the heap: the loader's blocks, and each
//   coded part's tables, then stayed resident beside the next stage's arrays. The cost is a page
//   fault per page of each new array, system time spent beside the work.
inline void ConfigureMalloc() {
#ifdef __GLIBC__
  mallopt(M_ARENA_MAX, 1);
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMappedArrayBytes));
#endif
}

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_MALLOC_POLICY_H_
