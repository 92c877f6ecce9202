#include "common/malloc_policy.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace hullpack {
namespace {

// Resident pages of this process, in bytes.
size_t ResidentBytes() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  unsigned long size = 0, resident = 0;
  const int read = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  return read == 2 ? resident * static_cast<size_t>(sysconf(_SC_PAGESIZE)) : 0;
}

// Allocates `count` arrays of `bytes`, touches them, frees them (a small block allocated after them
// keeps them from the top of the heap), and returns how far the resident size stays above where it
// started.
size_t ResidentAfterFreeing(size_t count, size_t bytes) {
  const size_t before = ResidentBytes();
  std::vector<std::unique_ptr<char[]>> arrays;
  for (size_t i = 0; i < count; ++i) {
    arrays.emplace_back(new char[bytes]);
    std::memset(arrays.back().get(), 1, bytes);
  }
  std::unique_ptr<char[]> pin(new char[64]);
  arrays.clear();
  const size_t after = ResidentBytes();
  return after > before ? after - before : 0;
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HULLPACK_SANITIZED_MALLOC 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define HULLPACK_SANITIZED_MALLOC 1
#endif

TEST(ConfigureMalloc, FreedLargeArraysLeaveTheResidentSet) {
#if !defined(__GLIBC__) || !defined(__linux__)
  GTEST_SKIP() << "the policy applies to glibc's malloc on Linux only";
#elif defined(HULLPACK_SANITIZED_MALLOC)
  GTEST_SKIP() << "the sanitizer's allocator replaces glibc's malloc (and keeps freed memory)";
#else
  ConfigureMalloc();
  // A large array freed first: by default glibc would then keep smaller ones in its heap.
  {
    std::unique_ptr<char[]> large(new char[size_t{16} << 20]);
    std::memset(large.get(), 1, size_t{16} << 20);
  }
  const size_t total = 16 * kMappedArrayBytes;
  EXPECT_LT(ResidentAfterFreeing(16, kMappedArrayBytes), total / 8);
#endif
}

}  // namespace
}  // namespace hullpack
